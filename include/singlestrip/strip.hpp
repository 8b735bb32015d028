// singlestrip — one triangle strip for an oriented 2-manifold, with midpoint splits where one
// strip is otherwise impossible. Two engines: the matching engine (default; Gopi & Eppstein,
// "Single-Strip Triangulation of Manifolds with Arbitrary Topology", 2004, with boundaries as in
// Diaz-Gutierrez, Eppstein & Gopi 2006) and the growth builder (Gopi, "Controllable Single-Strip
// Generation for Triangulated Surfaces", §3 and §5).
//
// Contract. Given an edge-connected, consistently oriented manifold triangle mesh (any genus, any
// number of boundary loops), build_strip() returns a mesh that covers exactly the same surface
// (input vertices unchanged, midpoints appended) whose faces form ONE sequence in which
// consecutive faces share an edge, honouring constraint edges, seed face, source and target with
// either engine. Why it always ends in one strip: docs/algorithm.md.
//
// Complexity: growth O(F log F) plus O(F) per fundamental triangle search (at most 2g + b - 1 of
// them); matching O(F) plus local repairs (Edmonds' matching in bounded balls around faces the
// greedy matching leaves short). Splits are bounded by the number of input faces (the matching
// engine falls back to the growth builder on the input rather than exceed it).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "singlestrip/mesh.hpp"

namespace singlestrip {

/// Which strip builder runs (docs/algorithm.md).
enum class StripEngine : uint8_t {
    /// Default. Dual-graph matching (Gopi & Eppstein 2004; Diaz-Gutierrez, Eppstein & Gopi 2006):
    /// loops of a 2-factor with alternating turns, joined by one midpoint split each.
    Matching,
    /// The paper's §3 growth builder with deferred islands: the reference method.
    Growth,
};

/// "matching" or "growth".
const char* engine_name(StripEngine engine) noexcept;
/// Parses "matching" / "growth"; std::nullopt for anything else.
std::optional<StripEngine> parse_engine(std::string_view name) noexcept;

struct StripOptions {
    /// The strip builder. Both give one verified strip on every valid input.
    StripEngine engine = StripEngine::Matching;
    /// Input face to start from. Default: a face on the mesh boundary when there is one (§4).
    std::optional<FaceId> seed_face;
    /// Greedy turns (paper Algorithm 2) and the neighbour-count ordering; off = the paper's
    /// plain same-direction turn rule.
    bool greedy = true;
    /// Edges the strip never crosses, as pairs of input vertex indices (§5.1); their lines only
    /// name them in messages.
    std::vector<ConstraintEdge> constraint_edges;
    /// First strip face is incident to `source`, last to `target` (§5.2); input vertex indices.
    std::optional<VertexId> source;
    std::optional<VertexId> target;
    /// Matching engine: after the matching is settled, rematch each face that swaps by the path
    /// that adds the fewest swaps (faces left short sit out), kept where it removes some (about 1% fewer GL indices on real
    /// meshes for two to three times the strip stage's time; docs/algorithm.md step 6). The growth
    /// builder ignores it.
    bool polish = false;
    /// Call Mesh::validate() after every split (tests only: O(F) per split).
    bool validate_each_split = false;
};

struct StripStats {
    uint32_t input_triangles = 0;
    uint32_t output_triangles = 0;
    uint32_t splits = 0;
    uint32_t swaps = 0;                  ///< consecutive turns in the same direction
    uint32_t fundamental_triangles = 0;  ///< growth builder only (the matching engine: 0; cycles replay the order)
    uint32_t deferred_regions = 0;       ///< islands cut off by bridges and spliced in later
    uint32_t detours = 0;                ///< islands spliced between two strip faces without a split
    long long genus = 0;
    uint32_t boundary_loops = 0;
    StripEngine engine = StripEngine::Matching;  ///< the engine that built the strip
    uint32_t loops = 0;                          ///< matching engine: loops and paths before joining
    uint32_t ring_flips = 0;                     ///< matching engine: vertex rings flipped to join loops for free
    uint32_t absorbed = 0;                       ///< matching engine: loops taken into the path for free (end rotations)
    uint32_t parity_splits = 0;                  ///< matching engine: rounds of splits beside faces left short
    uint32_t unmatched = 0;                      ///< matching engine: faces left short by the matching (path ends)
    uint32_t polished = 0;                       ///< matching engine, StripOptions::polish: faces rematched with fewer swaps
    /// Matching engine: the growth builder made the strip, because the engine's loops and paths
    /// could not be joined into one, or because after parity splits its strip was the better one.
    bool growth_fallback = false;
};

struct StripResult {
    Mesh mesh;                    ///< the split mesh (faces in construction order)
    std::vector<uint32_t> order;  ///< faces of `mesh` in strip order (a permutation of all faces)
    /// Positions in `order` of the fundamental triangles met (§3.1, seeds of §4's cycles).
    /// Growth builder only; empty from the matching engine (compute_fundamental_cycles() then finds
    /// them by replaying `order`, src/algo/fundamental_replay.cpp).
    std::vector<uint32_t> fundamental_positions;
    /// Per face of `mesh`: when it was taken (0 = the seed; the two children of a split strip
    /// face share its time). Faces taken after a fundamental triangle T contain T's parallel path
    /// (§3.1), which src/algo/cycles.cpp searches for a short cycle.
    std::vector<uint32_t> take_time;
    StripStats stats;
};

/// Builds one strip. \pre mesh is valid. \throw RequestError for a mesh of several
/// edge-connected components (stripify() strips each), an out-of-range seed face, source or
/// target, a constraint pair that is not a mesh edge, or constraints that disconnect the
/// surface (message gives the pieces); InternalError on a broken invariant (bug).
/// Runs options.engine. Complexity: growth O(F log F) plus O(F) per fundamental triangle search;
/// matching O(F) expected (docs/algorithm.md).
StripResult build_strip(Mesh mesh, const StripOptions& options = {});

/// build_strip() without its O(F) count of components, for a caller that knows the mesh is one
/// edge-connected component (stripify(): its checks counted them). \pre mesh.num_components()
/// == 1, not checked: a mesh of several ends in an InternalError. Otherwise build_strip()'s contract.
StripResult build_strip_connected(Mesh mesh, const StripOptions& options = {});

/// The engines themselves (build_strip_connected() dispatches); its contract.
StripResult build_strip_growth(Mesh mesh, const StripOptions& options);
StripResult build_strip_matching(Mesh mesh, const StripOptions& options);

/// The output arrays (StripArrays, soup.hpp) of a strip: faces in strip order. O(V + F).
StripArrays strip_arrays(const StripResult& result);
/// The same arrays without a copy of the points: the mesh gives them up, and the rest of the
/// result (mesh, order) is freed; only result.stats stays. O(F).
StripArrays strip_arrays(StripResult&& result);

}  // namespace singlestrip
