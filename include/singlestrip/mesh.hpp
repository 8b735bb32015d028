// singlestrip — mesh core: a corner table (flat arrays, implicit half-edges) with the
// midpoint split of two adjacent triangles.
//
// Layout. Face f owns corners 3f, 3f+1, 3f+2 in counter-clockwise order (its orientation).
// Half-edge h == corner h: it runs from corner_vertex(h) to corner_vertex(next(h)) and belongs
// to face h/3. twin(h) is the half-edge of the neighbouring face on the same edge, running the
// other way, or kNone on the mesh boundary. No per-edge or per-face records exist: faces,
// next/prev and edge ids are all derived from the corner index.
//
// Invariants (checked by validate(); tests call it after every mutation):
//   I1 corner_vertex_.size() == twin_.size() == 3 * face_parent_.size()
//   I2 every corner_vertex_ entry < points_.size(); a face's three vertices are distinct
//   I3 twin_[h] == kNone or (twin_[twin_[h]] == h, twin_[h] in another face, and the twin runs
//      from to(h) to from(h)): consistently oriented, at most two faces per edge
//   I4 vertex_halfedge_[v] is kNone for an unreferenced vertex, else an outgoing half-edge of v
//   I5 every referenced vertex is manifold: its faces form one fan (closed, or open with two
//      boundary half-edges)
//   I6 face_parent_[f] < num_input_faces_
//
// Complexity: construction O(V + F) plus sorting each vertex's few edges; split O(1);
// topology queries O(V + F).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

inline constexpr uint32_t kNone = 0xffffffffu;

/// What split_edge() created. The split edge (a,b) with midpoint m separated face f=(a,b,c)
/// and its twin face g=(b,a,d); four faces now cover them:
///   f_a = (a,m,c) [reuses f's index], f_b = (m,b,c) [new], g_b = (b,m,d) [reuses g's index],
///   g_a = (m,a,d) [new]. Each child keeps its parent's orientation and input parent.
struct SplitResult {
    uint32_t vertex;  ///< the new midpoint vertex m (== old num_vertices())
    uint32_t f_a, f_b, g_a, g_b;
};

class Mesh {
public:
    Mesh() = default;

    /// Builds the corner table of a triangle soup. Vertices keep their indices (unreferenced
    /// ones are kept and ignored); face f is soup triangle f and its own input parent.
    /// \pre every index < points.size(); use validate_soup() (validate.hpp) first on user input
    ///      to get precise diagnostics.
    /// \throw InputError if a face repeats a vertex, an edge has more than two faces, two faces
    ///        traverse an edge in the same direction, or a vertex is non-manifold.
    /// Complexity O(V + F) (half-edges bucketed by vertex).
    static Mesh from_soup(const TriangleSoup& soup);

    // --- sizes ---
    [[nodiscard]] uint32_t num_vertices() const noexcept { return static_cast<uint32_t>(points_.size()); }
    [[nodiscard]] uint32_t num_faces() const noexcept { return static_cast<uint32_t>(face_parent_.size()); }
    [[nodiscard]] uint32_t num_halfedges() const noexcept { return static_cast<uint32_t>(twin_.size()); }
    [[nodiscard]] uint32_t num_input_faces() const noexcept { return num_input_faces_; }
    [[nodiscard]] uint32_t num_input_vertices() const noexcept { return num_input_vertices_; }

    // --- navigation (all O(1)) ---
    [[nodiscard]] static uint32_t face(uint32_t h) noexcept { return h / 3; }
    [[nodiscard]] static uint32_t next(uint32_t h) noexcept { return h % 3 == 2 ? h - 2 : h + 1; }
    [[nodiscard]] static uint32_t prev(uint32_t h) noexcept { return h % 3 == 0 ? h + 2 : h - 1; }
    [[nodiscard]] static uint32_t halfedge(uint32_t f, uint32_t k) noexcept { return 3 * f + k; }
    [[nodiscard]] uint32_t from(uint32_t h) const noexcept { return corner_vertex_[h]; }
    [[nodiscard]] uint32_t to(uint32_t h) const noexcept { return corner_vertex_[next(h)]; }
    /// Vertex opposite half-edge h in its face.
    [[nodiscard]] uint32_t opposite(uint32_t h) const noexcept { return corner_vertex_[prev(h)]; }
    [[nodiscard]] uint32_t twin(uint32_t h) const noexcept { return twin_[h]; }
    [[nodiscard]] bool is_boundary(uint32_t h) const noexcept { return twin_[h] == kNone; }
    /// Face across half-edge h, or kNone.
    [[nodiscard]] uint32_t neighbor(uint32_t h) const noexcept {
        return twin_[h] == kNone ? kNone : twin_[h] / 3;
    }
    [[nodiscard]] uint32_t vertex_halfedge(uint32_t v) const noexcept { return vertex_halfedge_[v]; }
    [[nodiscard]] const Point3& position(uint32_t v) const noexcept { return points_[v]; }
    [[nodiscard]] uint32_t parent(uint32_t f) const noexcept { return face_parent_[f]; }
    /// The half-edge of face f shared with face g, or kNone if they are not adjacent.
    [[nodiscard]] uint32_t shared_halfedge(uint32_t f, uint32_t g) const noexcept;

    [[nodiscard]] const std::vector<uint32_t>& corner_vertices() const noexcept { return corner_vertex_; }
    [[nodiscard]] const std::vector<Point3>& points() const noexcept { return points_; }
    [[nodiscard]] const std::vector<uint32_t>& face_parents() const noexcept { return face_parent_; }

    // --- mutation ---
    /// Splits the interior edge of half-edge h at its midpoint: the two faces on it become four
    /// (see SplitResult). All invariants hold afterwards. O(1) amortised.
    /// \pre h < num_halfedges() and !is_boundary(h)
    /// \throw InternalError if the precondition is violated.
    SplitResult split_edge(uint32_t h);

    // --- topology (O(V + F)) ---
    [[nodiscard]] uint32_t num_referenced_vertices() const;
    [[nodiscard]] uint32_t num_edges() const;
    [[nodiscard]] uint32_t num_boundary_edges() const;
    [[nodiscard]] uint32_t num_boundary_loops() const;
    /// Number of edge-connected components of faces.
    [[nodiscard]] uint32_t num_components() const;
    /// Component id of every face (0..num_components()-1).
    [[nodiscard]] std::vector<uint32_t> component_of_faces() const;
    /// V - E + F over referenced vertices.
    [[nodiscard]] long long euler_characteristic() const;
    /// Genus of a connected orientable surface: (2 - chi - boundary_loops) / 2.
    /// \pre num_components() == 1
    [[nodiscard]] long long genus() const;

    /// Checks invariants I1–I6. \throw InternalError naming the first violated invariant.
    void validate() const;

private:
    std::vector<Point3> points_;            ///< vertex positions; input vertices first, then midpoints
    std::vector<uint32_t> corner_vertex_;   ///< I1, I2: vertex of each corner, 3 per face, CCW
    std::vector<uint32_t> twin_;            ///< I3: opposite half-edge or kNone
    std::vector<uint32_t> vertex_halfedge_; ///< I4: one outgoing half-edge per vertex, or kNone
    std::vector<uint32_t> face_parent_;     ///< I6: input triangle each face lies in
    uint32_t num_input_faces_ = 0;
    uint32_t num_input_vertices_ = 0;
};

}  // namespace singlestrip
