// singlestrip — the plain arrays between the layers: the triangle soup every reader produces and
// every algorithm takes, and the strip's output arrays and cycles every writer takes.
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

/// Where a cycle came from (see the top of this header).
enum class CycleSource : uint8_t { SteepestAscent, SteepestDescent, StripSegment, ShortestPath, TreeCotree, ParallelPath };

struct Cycles {
    /// Face indices into the OUTPUT (strip order), one closed chain per cycle.
    std::vector<std::vector<uint32_t>> cycles;
    /// Geometric length of each cycle (see cycle_length()), same order as `cycles`.
    std::vector<double> lengths;
    /// How each cycle was obtained (empty for cycles not made by compute_fundamental_cycles()).
    std::vector<CycleSource> sources;
};

}  // namespace singlestrip
