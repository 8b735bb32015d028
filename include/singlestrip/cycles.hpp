// singlestrip — fundamental cycles from the strip's linear order (Gopi, §4, Algorithms 3 and 4).
//
// Which fundamental triangles, per engine.
//   * Growth (StripResult::take_time has one entry per face): the builder tracks the first Betti
//     number of the unstriped region and records the triangles that lower it
//     (StripResult::fundamental_positions) and when each face was taken (take_time).
//   * Matching, or any strip without those records (take_time empty or of the wrong size):
//     replay_fundamental_positions() replays the strip order. The unstriped region before
//     position i is the suffix U_i (faces at positions >= i); the face at position i is
//     fundamental when beta1(U_{i+1}) < beta1(U_i). Faces are added back in reverse order with
//     a union–find for the components (b0) and a local update of chi, a vertex counted once per
//     fan piece of the region: a new face with s edges shared with the region adds
//     1 - (3 - s) to chi, +1 per vertex where it shares no edge, -1 per vertex where it shares
//     both edges unless it closes that vertex's fan (all its other faces already in, vertex not
//     on the mesh boundary); beta1 = b0 - chi (+1 once the whole closed surface is back).
//     O(F alpha(F)). Positions then serve as take times: the region "still unstriped" after T is
//     exactly the faces after it, and the parallel path (5) runs through them.
// Either way the candidates are the rules below; how one is kept differs.
//   * Replayed (when the replay found exactly 2g+h-1 triangles, none at position 0, each with
//     exactly two neighbours after it): each T keeps its shortest candidate that, apart from T,
//     runs through faces after T only (a parallel path always does). No class is computed: such
//     a cycle is, in H1(U_p), the class T adds plus one of U_{p+1}, so one per triangle are
//     independent in H1(U_1), and H1(U_1) -> H1(M) is injective when no face capped a hole.
//     Cost: the candidates' searches and lengths, no term in g x dim.
//   * A replay with an interior first face on a surface with boundary finds one triangle more
//     than the rank. From 2^19 faces the order is then replayed from its first face on the
//     boundary (the prefix before it read backwards; no strip segment crosses that seam) and
//     kept as above when the conditions hold (no classes: their arrays were --cycles' memory).
//   * Otherwise (growth records; the cases above when their conditions fail): classes are
//     computed as below and each T
//     keeps its shortest independent candidate; the greedy choice can leave a triangle without
//     one (about 6% of them on make_genus_surface() at high genus with growth records), and the
//     tree–cotree fallback fills those.
//
// Each fundamental triangle T gets one cycle. With positions taken in the strip order, D = the
// neighbour of T with the largest position and S = the one with the second largest, the
// candidates for T are:
//   (1) steepest ascent (Algorithm 4): T, S, M1, ..., D, each M the neighbour of the previous
//       face with the largest position not beyond D's (D is taken as soon as it is adjacent). A
//       face's strip successor is adjacent, so positions strictly increase: it terminates after
//       at most pos(D) - pos(S) steps and visits no face twice (abandoned if it runs into T, or
//       once longer than 4 x the shortest of (4) and (5) + 64 faces: it would not be kept, and
//       it may otherwise follow the strip for its whole length);
//   (2) steepest descent from D to S, the mirror image;
//   (3) strip segments (§4): T plus the strip between two neighbours on the same side of T;
//   (4) a breadth-first shortest path from S to D avoiding T;
//   (5) the paper's parallel path (§3.1), shortest: a breadth-first path between T's neighbours
//       taken after T through faces taken after T (StripResult::take_time), i.e. through the
//       region that was still unstriped when T was found to be fundamental. Independent of how
//       splices reordered positions; usually the shortest independent candidate (measured in
//       docs/benchmarks.md against tree–cotree generators).
// Shortcuts can change the homology class: a steepest ascent often closes around one vertex of T
// (null-homologous), and since the builder splices deferred islands into the strip, positions
// are not the order in which faces were taken, so even a strip segment can miss the handle.
// Hence, in strip order, each T keeps its SHORTEST candidate that is independent in H1(M; Z2) of
// the cycles kept so far (classes by intersection parity with the tree–cotree basis of
// tree_cotree.hpp); a T with no independent candidate gets the shortest tree–cotree generator
// that is (CycleSource::TreeCotree). Cycles::sources says which rule made each cycle.
//
// Output. A cycle is a closed chain of edge-adjacent faces of the OUTPUT mesh, as indices into the
// strip order (face i = StripResult::order[i], i.e. StripArrays::faces[i]): consecutive entries
// and last -> first share an edge; no face repeats. Adjacency is plain mesh adjacency: constraint
// edges do not matter (the cycles are the surface's), nor do source/target.
//
// Guarantees (any seed, any constraints, any source/target).
//   * Every cycle is closed, simple, made of edge-adjacent output faces.
//   * There are exactly 2g+h-1 cycles (2g on a closed surface) and they are independent in
//     H1(M; Z2): a basis. Each fundamental triangle contributes its shortest independent
//     candidate (shortest in-suffix one when replayed, see above); when the fundamental
//     triangles are fewer than the surface's rank (constraint edges hide a handle from the
//     unstriped region; an interior seed on a surface with boundary) the rest are the shortest
//     independent tree–cotree generators, and fundamental triangles beyond the rank add nothing.
//     `sources` says which rule produced each cycle. Checked by the independent verifier in
//     tests/test_cycles.cpp and tests/test_constraints.cpp.
//
// Complexity, for F faces and dim = 2g+h-1: the replay O(F alpha(F)); per triangle,
// breadth-first searches that cost the faces they visit (arrays allocated once, reset by
// stamps), walks bounded as said in (1), strip segments kept as ranges until chosen or
// examined. With classes (growth records): the classifier O(V + F) once; per candidate examined
// (shortest first, until one is independent) O(n log n + dim) to classify its n faces and
// O(dim^2 / 64) at worst to reduce the class; tree–cotree generators are built only when kept
// (their classes are unit vectors). The searches together visit at most 16 F + 4096 dim faces,
// and give up sooner when, past F of them, their pace per cycle would spend that 8 times over:
// then (corridors one quad wide between long holes, where each search covers most of the mesh)
// every cycle is a tree–cotree generator instead (CycleSource::TreeCotree), still a basis, in
// O(V + F + their length). make_genus_surface(6724, 1):
// matching strip (256K faces) 0.07 s of cycles; growth strip (282K faces) 0.3 s with its
// records, 0.08 s replayed.
#pragma once

#include <cstdint>
#include <vector>

#include "singlestrip/strip.hpp"

namespace singlestrip {

// CycleSource and Cycles (the plain result arrays) are in soup.hpp, for the writers in io.

/// Fundamental cycles of the strip (see the top of this header).
/// \pre `result` comes from build_strip(), either engine: `order` is a permutation of the mesh
///      faces in which consecutive faces share an edge; when `take_time` has one entry per face,
///      `fundamental_positions` index into `order` (else they are ignored and found by replay).
/// \throw InternalError if a precondition is broken (a fundamental triangle without two
///        neighbours, or no path from S to D avoiding T).
/// Cycles::sources is filled (one entry per cycle).
Cycles compute_fundamental_cycles(const StripResult& result);

/// Fundamental triangles of any strip order, by replay: positions i (ascending) at which removing
/// face order[i] from the unstriped suffix U_i = {order[j] : j >= i} lowers its first Betti
/// number, each repeated by how much it lowers it (more than once only at position 0).
/// Adjacency is plain mesh adjacency. See "Which fundamental triangles" above.
/// \pre `order` is a permutation of the faces of a valid, edge-connected mesh.
/// \throw InternalError if `order` is not a permutation. O(F alpha(F)).
std::vector<uint32_t> replay_fundamental_positions(const Mesh& mesh, const std::vector<uint32_t>& order);

/// Length of the closed polyline through the face centroids and the midpoints of the edges
/// shared by consecutive faces (last -> first included), faces given as indices into
/// `arrays.faces`. A cycle of fewer than two faces has length 0.
/// \pre consecutive faces share an edge (otherwise the centroid-to-centroid segment is used).
/// O(cycle length).
double cycle_length(const StripArrays& arrays, const std::vector<uint32_t>& cycle);

/// The points of that polyline: c0, m01, c1, m12, ..., c_{n-1}, m_{n-1,0} (the closing segment
/// back to c0 is implicit).
std::vector<Point3> cycle_polyline(const StripArrays& arrays, const std::vector<uint32_t>& cycle);

/// cycle_polyline() of every cycle (for write_cycles_obj(), io.hpp).
/// \throw RequestError if a cycle names a face outside `arrays`. O(total cycle length).
std::vector<std::vector<Point3>> cycle_polylines(const StripArrays& arrays, const Cycles& cycles);

/// Tree–cotree generators (tree_cotree.hpp) of result.mesh indexed in strip order, with their
/// lengths (cycle_length() on strip_arrays(result)), directly comparable to
/// compute_fundamental_cycles(). Cycles::sources stays empty.
Cycles tree_cotree_cycles(const StripResult& result);

}  // namespace singlestrip
