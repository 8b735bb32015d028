// singlestrip — fundamental cycles from the strip's linear order (Gopi, §4, Algorithms 3 and 4).
//
// Each fundamental triangle T met during stripification (StripResult::fundamental_positions)
// seeds one cycle. With positions taken in the strip order: D = the neighbour of T with the
// largest position, S = the one with the second largest; the cycle is T, S, M1, ..., D where
// each M is the neighbour of the previous face with the largest position that does not exceed
// D's (steepest ascent, Algorithm 4: D itself is taken as soon as it is adjacent). Since a face's
// strip successor is always adjacent, positions strictly increase: the ascent terminates after at
// most pos(D) - pos(S) steps and visits no face twice. If S comes before T in the strip (possible
// once a deferred island is spliced in) the ascent could run into T; it skips T, and if it gets
// stuck (no neighbour with a larger position), the whole path from S to D is replaced by a
// breadth-first shortest path of faces that avoids T.
//
// Output. A cycle is a closed chain of edge-adjacent faces of the OUTPUT mesh, as indices into the
// strip order (face i = StripResult::order[i], i.e. StripArrays::faces[i]): consecutive entries
// and last -> first share an edge; no face repeats. Adjacency is plain mesh adjacency: constraint
// edges do not matter (the cycles are the surface's), nor do source/target.
//
// Guarantees.
//   * Always: every cycle is closed, simple, made of edge-adjacent output faces, and there is one
//     cycle per fundamental triangle.
//   * Seed on the boundary (the builder's default when there is a boundary) or closed surface:
//     on every mesh tested (tests/test_cycles.cpp, checked independently by verify()) there are
//     exactly 2g+h-1 cycles (2g closed) and they are independent in H1(M; Z2). This is the
//     paper's claim; it is tested, not proven here.
//   * Seed NOT on the boundary of a surface with boundary: the first face's edges act as an extra
//     boundary loop of the unstriped region (paper §3.1 (b)), so a fundamental triangle may close
//     a cycle around the seed that is null-homologous, or one cycle may be missing. Count and
//     independence are then NOT guaranteed; closure and adjacency still are. Use
//     tree_cotree.hpp for a guaranteed basis.
//
// Complexity: O(sum of cycle lengths) for the ascent (O(F) per cycle), O(F) for the fallback.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "singlestrip/strip.hpp"

namespace singlestrip {

/// Where a cycle came from (see the top of this header).
enum class CycleSource : uint8_t { SteepestAscent, SteepestDescent, StripSegment, ShortestPath, TreeCotree };

struct Cycles {
    /// Face indices into the OUTPUT (strip order), one closed chain per cycle.
    std::vector<std::vector<uint32_t>> cycles;
    /// Geometric length of each cycle (see cycle_length()), same order as `cycles`.
    std::vector<double> lengths;
    /// How each cycle was obtained (empty for cycles not made by compute_fundamental_cycles()).
    std::vector<CycleSource> sources;
};

/// Fundamental cycles of the strip (see the top of this header).
/// \pre `result` comes from build_strip(): `order` is a permutation of the mesh faces in which
///      consecutive faces share an edge; `fundamental_positions` index into `order`.
/// \throw InternalError if a precondition is broken (a fundamental triangle without two
///        neighbours, or no path from S to D avoiding T).
Cycles compute_fundamental_cycles(const StripResult& result);

/// Length of the closed polyline through the face centroids and the midpoints of the edges
/// shared by consecutive faces (last -> first included), faces given as indices into
/// `arrays.faces`. A cycle of fewer than two faces has length 0.
/// \pre consecutive faces share an edge (otherwise the centroid-to-centroid segment is used).
/// O(cycle length).
double cycle_length(const StripArrays& arrays, const std::vector<uint32_t>& cycle);

/// The points of that polyline: c0, m01, c1, m12, ..., c_{n-1}, m_{n-1,0} (the closing segment
/// back to c0 is implicit).
std::vector<Point3> cycle_polyline(const StripArrays& arrays, const std::vector<uint32_t>& cycle);

/// Writes {"cycles": [[face, ...], ...], "lengths": [...]} atomically (temporary + rename).
/// \throw OutputError if the file cannot be written.
void write_cycles_json(const std::string& path, const Cycles& cycles);

/// Writes each cycle as a closed OBJ polyline (`v` lines, then one `l` line per cycle whose last
/// index repeats its first) through face centroids and shared-edge midpoints, atomically.
/// \throw OutputError if the file cannot be written.
void write_cycles_obj(const std::string& path, const StripArrays& arrays, const Cycles& cycles);

}  // namespace singlestrip
