// singlestrip — triangle soup: the plain arrays every reader produces and every algorithm takes.
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

}  // namespace singlestrip
