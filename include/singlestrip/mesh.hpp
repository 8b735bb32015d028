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
// Complexity: construction O(V + F) (two counting sorts pair the half-edges); split O(1);
// topology queries O(V + F).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// "No such element": the one sentinel of every id type below and of the flat index arrays
/// (it converts to 0xFFFFFFFF for those).
struct NoneId {
    [[nodiscard]] constexpr operator uint32_t() const noexcept { return 0xffffffffu; }
};
inline constexpr NoneId kNone{};

/// An index that says what it indexes (as pmp-library's handles, geometry-central's elements):
/// built explicitly from an index, read back with idx(), compared and hashed; default or kNone
/// is "none". A trivially copyable uint32_t, so arrays of ids stay flat and cost nothing.
template <class Tag>
class Id {
public:
    constexpr Id() noexcept = default;
    constexpr explicit Id(uint32_t idx) noexcept : idx_(idx) {}
    constexpr Id(NoneId) noexcept {}  // NOLINT(google-explicit-constructor): kNone is every id's none
    [[nodiscard]] constexpr uint32_t idx() const noexcept { return idx_; }
    [[nodiscard]] constexpr bool valid() const noexcept { return idx_ != kNone; }
    friend constexpr bool operator==(const Id&, const Id&) noexcept = default;
    friend constexpr auto operator<=>(const Id&, const Id&) noexcept = default;

private:
    uint32_t idx_ = kNone;
};

using FaceId = Id<struct FaceTag>;          ///< a triangle of a Mesh
using HalfedgeId = Id<struct HalfedgeTag>;  ///< a corner of a Mesh, i.e. the half-edge leaving it
using VertexId = Id<struct VertexTag>;      ///< a vertex (a point) of a Mesh
using RegionId = Id<struct RegionTag>;      ///< a set of faces a strip builder works on

/// The index of an optional id, for interfaces that keep plain indices (the verifier's).
template <class Tag>
constexpr std::optional<uint32_t> index_of(const std::optional<Id<Tag>>& id) noexcept {
    return id ? std::optional<uint32_t>(id->idx()) : std::nullopt;
}

/// Ids 0 .. n-1 of one kind, for range-for loops.
template <class I>
class IdRange {
public:
    class iterator {
    public:
        constexpr explicit iterator(uint32_t i) noexcept : i_(i) {}
        constexpr I operator*() const noexcept { return I(i_); }
        constexpr iterator& operator++() noexcept {
            ++i_;
            return *this;
        }
        friend constexpr bool operator==(iterator, iterator) noexcept = default;

    private:
        uint32_t i_;
    };
    constexpr explicit IdRange(uint32_t n) noexcept : n_(n) {}
    [[nodiscard]] constexpr iterator begin() const noexcept { return iterator(0); }
    [[nodiscard]] constexpr iterator end() const noexcept { return iterator(n_); }

private:
    uint32_t n_;
};

class SoupEdges;  // src/core/soup_edges.hpp

/// What split_edge() created. The split edge (a,b) with midpoint m separated face f=(a,b,c)
/// and its twin face g=(b,a,d); four faces now cover them:
///   f_a = (a,m,c) [reuses f's index], f_b = (m,b,c) [new], g_b = (b,m,d) [reuses g's index],
///   g_a = (m,a,d) [new]. Each child keeps its parent's orientation and input parent.
struct SplitResult {
    VertexId vertex;  ///< the new midpoint vertex m (== old num_vertices())
    FaceId f_a, f_b, g_a, g_b;
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
    /// The same, taking the soup's points instead of copying them; `soup` is left empty (its
    /// memory freed), for callers that no longer need it.
    static Mesh from_soup(TriangleSoup&& soup);
    /// The same with the edge pairing already known (PreparedSoup::twin from
    /// prepare_soup_components(): the analysis that checked the soup paired its half-edges), so
    /// the half-edges are not sorted again. twin[3f+k] is the partner of the half-edge from
    /// triangles[f][k] to triangles[f][(k+1)%3], kNone on the boundary; it is moved into the mesh.
    /// \pre twin holds every interior edge of the soup (a missing pair would be read as boundary).
    /// 	hrow InputError as above, and if twin has the wrong size or pairs two half-edges that do
    ///        not run opposite ways along one edge (checked: O(F)).
    static Mesh from_soup(TriangleSoup&& soup, std::vector<uint32_t>&& twin);
    static Mesh from_soup(const TriangleSoup& soup, std::vector<uint32_t>&& twin);
    /// Half-edges the corner table reserves for a mesh of nf faces (room for the engines' splits
    /// without a reallocation); a caller that fills a twin array for from_soup() reserves as many.
    [[nodiscard]] static size_t reserved_halfedges(size_t nf) noexcept { return 3 * nf + 6 * reserved_spare(nf); }

    // --- sizes ---
    [[nodiscard]] uint32_t num_vertices() const noexcept { return static_cast<uint32_t>(points_.size()); }
    [[nodiscard]] uint32_t num_faces() const noexcept { return static_cast<uint32_t>(face_parent_.size()); }
    [[nodiscard]] uint32_t num_halfedges() const noexcept { return static_cast<uint32_t>(twin_.size()); }
    [[nodiscard]] uint32_t num_input_faces() const noexcept { return num_input_faces_; }
    [[nodiscard]] uint32_t num_input_vertices() const noexcept { return num_input_vertices_; }

    [[nodiscard]] IdRange<FaceId> faces() const noexcept { return IdRange<FaceId>(num_faces()); }
    [[nodiscard]] IdRange<HalfedgeId> halfedges() const noexcept { return IdRange<HalfedgeId>(num_halfedges()); }
    [[nodiscard]] IdRange<VertexId> vertices() const noexcept { return IdRange<VertexId>(num_vertices()); }

    // --- navigation (all O(1)) ---
    [[nodiscard]] static FaceId face(HalfedgeId h) noexcept { return FaceId(h.idx() / 3); }
    [[nodiscard]] static HalfedgeId next(HalfedgeId h) noexcept { return HalfedgeId(h.idx() % 3 == 2 ? h.idx() - 2 : h.idx() + 1); }
    [[nodiscard]] static HalfedgeId prev(HalfedgeId h) noexcept { return HalfedgeId(h.idx() % 3 == 0 ? h.idx() + 2 : h.idx() - 1); }
    /// Half-edge k (0, 1, 2) of face f, counter-clockwise.
    [[nodiscard]] static HalfedgeId halfedge(FaceId f, uint32_t k) noexcept { return HalfedgeId(3 * f.idx() + k); }
    /// k of half-edge h in its face: halfedge(face(h), k) == h.
    [[nodiscard]] static uint32_t index_in_face(HalfedgeId h) noexcept { return h.idx() % 3; }
    [[nodiscard]] VertexId from(HalfedgeId h) const noexcept { return VertexId(corner_vertex_[h.idx()]); }
    [[nodiscard]] VertexId to(HalfedgeId h) const noexcept { return from(next(h)); }
    /// Vertex opposite half-edge h in its face.
    [[nodiscard]] VertexId opposite(HalfedgeId h) const noexcept { return from(prev(h)); }
    [[nodiscard]] HalfedgeId twin(HalfedgeId h) const noexcept { return HalfedgeId(twin_[h.idx()]); }
    [[nodiscard]] bool is_boundary(HalfedgeId h) const noexcept { return twin_[h.idx()] == kNone; }
    /// Face across half-edge h, or kNone.
    [[nodiscard]] FaceId neighbor(HalfedgeId h) const noexcept { return is_boundary(h) ? FaceId() : face(twin(h)); }
    [[nodiscard]] HalfedgeId vertex_halfedge(VertexId v) const noexcept { return HalfedgeId(vertex_halfedge_[v.idx()]); }
    [[nodiscard]] const Point3& position(VertexId v) const noexcept { return points_[v.idx()]; }
    /// The input face (of the mesh from_soup() built) that face f lies in.
    [[nodiscard]] FaceId parent(FaceId f) const noexcept { return FaceId(face_parent_[f.idx()]); }
    /// The half-edge of face f shared with face g, or kNone if they are not adjacent.
    [[nodiscard]] HalfedgeId shared_halfedge(FaceId f, FaceId g) const noexcept;

    /// Flat arrays for output and for algorithms that keep their own per-element arrays: plain
    /// indices, corner 3f+k of face f.
    [[nodiscard]] const std::vector<uint32_t>& corner_vertices() const noexcept { return corner_vertex_; }
    [[nodiscard]] const std::vector<Point3>& points() const noexcept { return points_; }
    [[nodiscard]] const std::vector<uint32_t>& face_parents() const noexcept { return face_parent_; }

    // --- mutation ---
    /// Splits the interior edge of half-edge h at its midpoint: the two faces on it become four
    /// (see SplitResult). All invariants hold afterwards. O(1) amortised.
    /// \pre h.idx() < num_halfedges() and !is_boundary(h)
    /// \throw InternalError if the precondition is violated.
    SplitResult split_edge(HalfedgeId h);

    /// Room for `splits` more split_edge() calls without moving the arrays. A builder that will
    /// split calls it before allocating its own arrays: growing the mesh later copies each array
    /// while the builder's exist (the growth builder's memory peak). O(F) once.
    void reserve_splits(uint32_t splits);

    /// Renumbers the input vertices: vertex v becomes to[v] (midpoints keep their numbers). For a
    /// caller that built the mesh from a renumbered soup and hands it back in the given numbers.
    /// All invariants hold afterwards. O(V + F).
    /// \pre `to` is a permutation of 0 .. num_input_vertices() - 1
    /// \throw InternalError if `to` has the wrong size or is no permutation.
    void renumber_input_vertices(const std::vector<uint32_t>& to);

    /// Moves the vertex positions out and leaves an empty mesh: for a caller done with the mesh
    /// that needs its points (the output arrays), without a second copy at the peak.
    [[nodiscard]] std::vector<Point3> release_points() &&;

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
    /// Genus of a connected orientable surface: (2 - chi - boundary_loops) / 2 (the library's
    /// one formula, src/core/topology.hpp, which mesh_info() uses too).
    /// \pre num_components() == 1
    [[nodiscard]] long long genus() const;

    /// Checks invariants I1–I6. \throw InternalError naming the first violated invariant.
    void validate() const;

private:
    // Steps of from_soup().
    static Mesh build(const std::vector<Triangle>& triangles, std::vector<Point3> points, std::vector<Triangle>* release = nullptr,
                      std::vector<uint32_t>* paired = nullptr);
    /// Splits reserved for up front (reserve_splits(): F/16 at most).
    [[nodiscard]] static size_t reserved_spare(size_t nf) noexcept { return nf / 16 + 64; }
    void adopt_twins(std::vector<uint32_t>&& twin, const std::vector<Triangle>& triangles);
    void reserve_for_split();
    void pair_halfedges(const SoupEdges& edges);
    void pair_halfedge_range(const SoupEdges& edges, uint32_t v_begin, uint32_t v_end);
    void assign_vertex_halfedges();
    void check_vertex_fans() const;
    void check_fan_range(const std::vector<uint32_t>& corners_at, uint32_t v_begin, uint32_t v_end) const;

    std::vector<Point3> points_;             ///< vertex positions; input vertices first, then midpoints
    std::vector<uint32_t> corner_vertex_;    ///< I1, I2: vertex of each corner, 3 per face, CCW
    std::vector<uint32_t> twin_;             ///< I3: opposite half-edge or kNone
    std::vector<uint32_t> vertex_halfedge_;  ///< I4: one outgoing half-edge per vertex, or kNone
    std::vector<uint32_t> face_parent_;      ///< I6: input triangle each face lies in
    uint32_t num_input_faces_ = 0;
    uint32_t num_input_vertices_ = 0;
};

}  // namespace singlestrip

template <class Tag>
struct std::hash<singlestrip::Id<Tag>> {
    std::size_t operator()(singlestrip::Id<Tag> id) const noexcept { return std::hash<uint32_t>{}(id.idx()); }
};

#if defined(__GLIBCXX__)
// A growing std::vector moves trivial elements with one memmove and others one by one, in a loop
// that keeps GCC from unrolling the loop around a push_back (3 sides of a face). An Id is not
// trivial (it starts as none) but moves as its uint32_t does: let it take the memmove.
template <class Tag>
struct std::__is_bitwise_relocatable<singlestrip::Id<Tag>, void> : std::true_type {};
#endif
