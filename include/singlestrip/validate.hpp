// singlestrip — structural diagnosis of a triangle soup before building a Mesh.
//
// These checks work on the plain soup (no corner table), so they can describe every problem of
// an invalid input precisely; Mesh::from_soup() assumes a soup that passed them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// One structural problem of a soup. `kind` is a stable machine-readable tag:
///   "index_out_of_range", "repeated_vertex", "duplicate_face", "non_manifold_edge",
///   "non_manifold_vertex", "inconsistent_orientation", "non_orientable", "no_faces".
/// Several edge-connected components are not a problem: each gets its own strip (pipeline.hpp).
/// `message` names the element(s) (face / edge / vertex numbers, 0-based) and the problem.
struct SoupProblem {
    std::string kind;
    std::string message;
};

/// Every structural problem of `soup`, in a deterministic order (by kind as listed above, then
/// by element). Per-element lists are capped (the last entry says how many more were found) so a
/// badly broken file gives a readable report. An empty result means the soup is a valid input for
/// stripification: consistently oriented 2-manifold pieces (with or without boundary).
/// Orientation is checked by BFS propagation over manifold edges: an edge traversed in the same
/// direction by both faces is "inconsistent_orientation"; if no flipping of faces can make the
/// surface consistent, "non_orientable" is reported as well.
/// Complexity O(V + F log F) worst case (union-find with path halving; no sort of the whole soup), linear in practice.
std::vector<SoupProblem> diagnose_soup(const TriangleSoup& soup);

struct PrepareOptions {
    /// Consistently re-orient an orientable mesh by flipping faces (each component keeps the
    /// orientation of the majority of its faces; a tie keeps its lowest-numbered face's) instead
    /// of reporting inconsistent orientation.
    bool orient = false;
    /// prepare_soup_components() only: a large soup whose faces have no order (shuffled) comes
    /// back in a Z-order of its face centroids, for the cache (PreparedSoup::face_origin).
    /// Messages, orientation and components are those of the given soup.
    bool locality = false;
    /// With `locality`, when the reordered soup's vertex numbers are scattered too (a file whose
    /// vertices were shuffled): its vertices numbered by first use (PreparedSoup::vertex_origin).
    bool vertex_locality = false;
};

/// Checks (and with opt.orient, re-orients) `soup`; returns it ready for Mesh::from_soup().
/// Flipping face (a,b,c) gives (a,c,b); face order and vertex indices never change.
/// \throw InputError whose message is "<filename_for_messages>: " followed by the first problems
///        (up to 5, "; "-separated, with a count of the rest), then " (fix: ...)" naming the
///        option that repairs each kind (--repair, --orient). A non-orientable surface is always
///        an error. Complexity O(V + F log F) worst case (union-find with path halving; no sort of the whole soup), linear in practice.
TriangleSoup prepare_soup(TriangleSoup soup, const PrepareOptions& opt, const std::string& filename_for_messages);

/// A prepared soup with its edge-connected components (numbered as face_components() does).
struct PreparedSoup {
    TriangleSoup soup;
    std::vector<uint32_t> component;  ///< per face: its component, 0 .. num_components - 1
    uint32_t num_components = 0;
    /// With PrepareOptions::locality, when the faces were reordered: the given soup's face of
    /// each face of `soup`. Empty: same order as given.
    std::vector<uint32_t> face_origin;
    /// With PrepareOptions::vertex_locality, when the vertices were renumbered too (their numbers had
    /// no locality along the faces): the given soup's vertex of each vertex of `soup`. Empty:
    /// numbered as given.
    std::vector<uint32_t> vertex_origin;
    /// The analysis' edge pairing of `soup` (after any flips): per half-edge 3f+k its partner,
    /// kNone on the boundary, for Mesh::from_soup(soup, twin) (no second sort of the half-edges).
    /// With several components, each one's part of it (renumbered) pairs that component.
    std::vector<uint32_t> twin;
};

/// prepare_soup() that also gives the components from the same analysis, so a caller that
/// needs both pays for one. Throws and costs as prepare_soup().
PreparedSoup prepare_soup_components(TriangleSoup soup, const PrepareOptions& opt, const std::string& filename_for_messages);

/// Flips faces so that every component is consistently oriented, keeping the orientation of
/// the majority of each component's faces (a tie: its lowest-numbered face's; flipping (a,b,c)
/// gives (a,c,b)): never more than half of a component's faces are flipped. Faces that are out of
/// range or repeat a vertex are left alone; orientation propagates only across edges with
/// exactly two faces. Returns the number of faces flipped, or -1 (soup unchanged) if some
/// component is not orientable. Complexity O(V + F log F) worst case (union-find with path halving; no sort of the whole soup), linear in
/// practice.
long long orient_soup(TriangleSoup& soup);

/// Throws like prepare_soup() without re-orienting; convenience for callers with a soup.
void validate_soup(const TriangleSoup& soup, const std::string& filename_for_messages);

/// Topological summary of a soup, computed on the soup itself (valid or not).
struct MeshInfo {
    uint64_t vertices = 0;               ///< all vertices in the file
    uint64_t referenced_vertices = 0;    ///< vertices used by at least one face
    uint64_t faces = 0;                  ///< triangles after fan triangulation
    uint64_t polygons = 0;               ///< file polygons (== faces if all were triangles)
    uint64_t edges = 0;                  ///< distinct undirected edges
    uint64_t boundary_edges = 0;         ///< edges with exactly one face
    uint64_t non_manifold_edges = 0;     ///< edges with more than two faces
    uint64_t components = 0;             ///< edge-connected components of faces
    uint64_t boundary_loops = 0;         ///< closed loops of boundary edges (meaningful if manifold)
    long long euler_characteristic = 0;  ///< V(referenced) - E + F
    /// (2*components - chi - boundary_loops)/2 summed as for one surface; only meaningful for a
    /// valid (connected, manifold, orientable) mesh — `genus_valid` says so.
    long long genus = 0;
    bool genus_valid = false;
    bool orientable = false;                ///< every component can be oriented consistently (manifold edges)
    bool oriented = false;                  ///< ... and already is
    std::vector<uint64_t> component_sizes;  ///< faces per component, largest first
    std::vector<SoupProblem> problems;      ///< diagnose_soup(soup)
    uint64_t unwelded_vertices = 0;         ///< unwelded_vertices(soup): --weld would merge them
    [[nodiscard]] bool valid() const noexcept { return problems.empty(); }
};

/// Edge-connected component of every face (0.., numbered by lowest face; faces out of range or
/// with a repeated vertex get 0xFFFFFFFF); `count` receives the number of components.
/// Complexity as diagnose_soup().
std::vector<uint32_t> face_components(const TriangleSoup& soup, uint32_t* count = nullptr);

/// Referenced vertices with exactly the coordinates of a lower-numbered vertex (repair.hpp's
/// weld_map): a file that left its corners apart. O(V log V + F).
uint64_t unwelded_vertices(const TriangleSoup& soup);

/// Computes MeshInfo. Complexity O(V + F log F) worst case (union-find with path halving; no sort of the whole soup), linear in practice.
MeshInfo mesh_info(const TriangleSoup& soup);

}  // namespace singlestrip
