// singlestrip — repair of a triangle soup into consistently oriented 2-manifold pieces
// (`--repair`, PipelineOptions::repair, Python `repair=True`). Rules and reasons: docs/repair.md.
//
// Steps, in this order (each deterministic, so `verify --repair` can replay them):
//   1. weld: vertices with exactly equal coordinates (as doubles, -0 == +0, no tolerance) are one
//      vertex; faces are re-pointed to the lowest-numbered vertex of each set. Points are never
//      removed or renumbered: welded-away vertices stay in the array, unreferenced.
//   2. drop faces with an index out of range or a repeated vertex (after welding: "degenerate"),
//      and faces with the same vertex SET as an earlier face ("duplicate"; the first is kept,
//      whatever the orientation of the later ones: a face and its reverse cover the same
//      triangle, and keeping both would glue three faces to each edge of it).
//   3. cut non-manifold edges (more than two faces) and non-manifold vertices (several fans of
//      faces) apart: faces are glued only across edges with exactly two faces, and every vertex
//      gets one copy per fan of glued faces around it. The first fan (the one holding the
//      lowest corner 3f+k) keeps the vertex; the others get new vertices appended after the input
//      points, at the same position. The drawn surface is unchanged.
//   4. orient: per edge-connected component, a breadth-first search from its lowest face fixes
//      the relative orientation. A non-orientable component is cut along the edges where that
//      search disagrees with itself (they form curves; their vertices get copies as in 3.), which
//      leaves one orientable piece. Then each component keeps the orientation of the majority of
//      its faces, and a closed component (no boundary edge) is turned outward (positive signed
//      volume) even when that flips the majority.
//
// Numbering contract. Output vertex i < n (n = input points) IS input vertex i; vertex n + j is a
// copy of vertex `RepairReport::copied_from[j]`. Output face t comes from input face
// `RepairedSoup::face_origin[t]`; kept faces stay in input order, possibly re-wound.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// What repair_soup() changed. Vertex ids are input ids (after welding: the kept vertex), face
/// ids are input face ids.
struct RepairReport {
    std::vector<std::pair<uint32_t, uint32_t>> welded;              ///< (vertex, merged into); referenced ones only
    std::vector<uint32_t> invalid_faces;                            ///< dropped: an index out of range
    std::vector<uint32_t> degenerate_faces;                         ///< dropped: a repeated vertex (after welding)
    std::vector<uint32_t> duplicate_faces;                          ///< dropped: same vertices as an earlier face
    std::vector<std::pair<uint32_t, uint32_t>> non_manifold_edges;  ///< edges with more than two faces, cut apart
    std::vector<uint32_t> split_vertices;                           ///< vertices given copies (non-manifold or cut)
    std::vector<uint32_t> copied_from;                              ///< new vertex n + j copies vertex copied_from[j]
    std::vector<std::pair<uint32_t, uint32_t>> orientation_cuts;    ///< edges cut to make a component orientable
    uint32_t non_orientable_components = 0;
    std::vector<uint32_t> flipped_faces;  ///< faces whose winding was reversed
    uint32_t turned_outward = 0;          ///< closed components reversed to get positive volume
    uint32_t components = 0;              ///< edge-connected components after repair

    /// True when the soup was changed in any way.
    [[nodiscard]] bool changed() const noexcept;
    /// One line of counts, e.g. "welded 12 vertices, dropped 2 duplicate faces, ..." or "nothing to repair".
    [[nodiscard]] std::string summary() const;
};

struct RepairedSoup {
    TriangleSoup soup;                  ///< repaired: input points + copies, kept faces in input order
    std::vector<uint32_t> face_origin;  ///< input face of each face of `soup`
    RepairReport report;
};

/// Weld map of step 1: rep[v] = the lowest-numbered vertex with exactly v's coordinates.
/// O(V log V).
std::vector<uint32_t> weld_map(const std::vector<Point3>& points);

/// weld_map() of a soup with attributes: vertices weld only when their attributes are equal
/// too (a texture or normal seam stays apart). O(V log V) plus O(k^2) for k attribute variants
/// at one position.
std::vector<uint32_t> weld_map(const TriangleSoup& soup);

/// Step 1 alone (`--weld`): re-points faces to the weld representatives. Returns how many
/// referenced vertices were merged away. O(V log V + F).
uint64_t weld_soup(TriangleSoup& soup);

struct RepairOptions {
    /// Step 1. Off for glTF primitives, whose vertices are already split at attribute seams.
    bool weld = true;
};

/// Runs steps 1-4 on `soup` (step 1 only with options.weld). \pre none (any indices, any structure; NaN coordinates never weld).
/// \post the result passes prepare_soup() (validate.hpp) except for "no_faces" when every face
///       was dropped. \throw InternalError if a step does not reach its post-condition (a bug).
/// Complexity O(V log V + F log F).
RepairedSoup repair_soup(const TriangleSoup& soup, const RepairOptions& options = {});

/// Signed volume of the closed faces `faces` of `points` (sum of tetrahedra to the first vertex
/// of the first face). O(faces).
double signed_volume(const std::vector<Point3>& points, const std::vector<Triangle>& faces);

}  // namespace singlestrip
