// singlestrip — the plain arrays between the layers: the triangle soup every reader produces and
// every algorithm takes, and the strip's output arrays every writer takes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace singlestrip {

using Point3 = std::array<double, 3>;
using Triangle = std::array<uint32_t, 3>;

/// Vertices in file order and triangles (indices into `points`), after fan triangulation of
/// polygons. `source_polygon[t]` is the index of the file polygon triangle t came from.
struct TriangleSoup {
    std::vector<Point3> points;
    std::vector<Triangle> triangles;
    std::vector<uint32_t> source_polygon;  ///< same size as triangles (may be empty if 1:1)
};

/// Output arrays in strip order: faces as vertex triples (orientation kept) and the input
/// triangle each lies in (strip_arrays(), strip.hpp).
struct StripArrays {
    std::vector<Point3> points;
    std::vector<Triangle> faces;
    std::vector<uint32_t> parent;
};

}  // namespace singlestrip
