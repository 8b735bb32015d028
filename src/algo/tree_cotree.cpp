// singlestrip — tree–cotree homology generators (Eppstein 2003), the reference for §4's cycles.
#include "singlestrip/tree_cotree.hpp"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>

#include "core/face_sides.hpp"
#include "core/id_vector.hpp"
#include "singlestrip/errors.hpp"

namespace singlestrip {

namespace {

/// Tree T (primal, boundary identified) and cotree C (dual) of a mesh; see the header.
struct Decomposition {
    // Quotient vertices are VertexIds: the mesh's, and one more (nv) for the whole boundary.
    IdVector<VertexId, VertexId> q;                 ///< vertex -> quotient vertex (boundary -> nv)
    std::vector<HalfedgeId> edge_he;                ///< interior edge -> representative half-edge
    IdVector<HalfedgeId, uint32_t> edge_of_he;      ///< half-edge -> interior edge (kNone on boundary)
    std::vector<uint8_t> in_tree, in_cotree;        ///< per interior edge
    std::vector<VertexId> tree_order;               ///< quotient vertices in BFS order, root first
    IdVector<VertexId, uint32_t> tree_parent_edge;  ///< per quotient vertex (kNone at the root)
    IdVector<FaceId, FaceId> fparent;               ///< cotree parent face (kNone at face 0)
    IdVector<FaceId, uint32_t> depth;               ///< cotree depth per face
};

/// Quotient vertices: every boundary vertex becomes the extra vertex nv. False if there is no
/// boundary.
bool identify_boundary(const Mesh& mesh, Decomposition& d) {
    const VertexId super(mesh.num_vertices());
    d.q.resize(mesh.num_vertices());
    for (const VertexId v : mesh.vertices()) d.q[v] = v;
    bool has_boundary = false;
    for (const HalfedgeId h : mesh.halfedges()) {
        if (!mesh.is_boundary(h)) continue;
        has_boundary = true;
        d.q[mesh.from(h)] = super;
        d.q[mesh.to(h)] = super;
    }
    return has_boundary;
}

/// Interior edges, one representative half-edge each (h < twin(h)), and the map back.
void number_interior_edges(const Mesh& mesh, Decomposition& d) {
    for (const HalfedgeId h : mesh.halfedges())
        if (!mesh.is_boundary(h) && h < mesh.twin(h)) d.edge_he.push_back(h);
    d.edge_of_he.assign(mesh.num_halfedges(), kNone);
    for (uint32_t e = 0; e < d.edge_he.size(); ++e) {
        d.edge_of_he[d.edge_he[e]] = e;
        d.edge_of_he[mesh.twin(d.edge_he[e])] = e;
    }
}

/// Quotient endpoints of interior edge e.
std::pair<VertexId, VertexId> quotient_ends(const Mesh& mesh, const Decomposition& d, uint32_t e) {
    const HalfedgeId h = d.edge_he[e];
    return {d.q[mesh.from(h)], d.q[mesh.to(h)]};
}

/// T: breadth-first spanning tree of the quotient graph from `root`. Its adjacency is built as
/// CSR; loops (both ends on the boundary) are left out of the tree and so end up dual edges.
void build_tree(const Mesh& mesh, Decomposition& d, VertexId root) {
    const uint32_t nv = mesh.num_vertices();
    const auto ne = static_cast<uint32_t>(d.edge_he.size());
    std::vector<uint32_t> start(nv + 2, 0);
    for (uint32_t e = 0; e < ne; ++e) {
        const auto [a, b] = quotient_ends(mesh, d, e);
        if (a == b) continue;
        ++start[a.idx() + 1];
        ++start[b.idx() + 1];
    }
    for (uint32_t v = 0; v <= nv; ++v) start[v + 1] += start[v];
    std::vector<uint32_t> adj(start[nv + 1]);
    {
        std::vector<uint32_t> fill(start.begin(), start.end() - 1);
        for (uint32_t e = 0; e < ne; ++e) {
            const auto [a, b] = quotient_ends(mesh, d, e);
            if (a == b) continue;
            adj[fill[a.idx()]++] = e;
            adj[fill[b.idx()]++] = e;
        }
    }
    d.in_tree.assign(ne, 0);
    d.tree_parent_edge.assign(nv + 1, kNone);
    IdVector<VertexId, uint8_t> seen(nv + 1, 0);
    std::vector<VertexId>& queue = d.tree_order;
    queue.assign(1, root);
    seen[root] = 1;
    for (size_t head = 0; head < queue.size(); ++head) {
        const VertexId v = queue[head];
        for (uint32_t i = start[v.idx()]; i < start[v.idx() + 1]; ++i) {
            const uint32_t e = adj[i];
            const auto [a, b] = quotient_ends(mesh, d, e);
            const VertexId w = a == v ? b : a;
            if (seen[w]) continue;
            seen[w] = 1;
            d.in_tree[e] = 1;
            d.tree_parent_edge[w] = e;
            queue.push_back(w);
        }
    }
}

/// C: breadth-first spanning tree of the dual graph over the edges not in T, from face 0.
void build_cotree(const Mesh& mesh, Decomposition& d) {
    const uint32_t nf = mesh.num_faces();
    d.fparent.assign(nf, kNone);
    d.depth.assign(nf, 0);
    d.in_cotree.assign(d.edge_he.size(), 0);
    IdVector<FaceId, uint8_t> reached(nf, 0);
    std::vector<FaceId> fqueue{FaceId(0)};
    reached[FaceId(0)] = 1;
    for (size_t head = 0; head < fqueue.size(); ++head) {
        const FaceId f = fqueue[head];
        for (const HalfedgeId h : sides(f)) {
            const FaceId g = mesh.neighbor(h);
            if (!g.valid()) continue;
            const uint32_t e = d.edge_of_he[h];
            if (d.in_tree[e] || reached[g]) continue;
            reached[g] = 1;
            d.in_cotree[e] = 1;
            d.fparent[g] = f;
            d.depth[g] = d.depth[f] + 1;
            fqueue.push_back(g);
        }
    }
    if (fqueue.size() != nf)
        throw InternalError("tree-cotree: the dual graph minus the tree is not connected (" + std::to_string(fqueue.size()) + " of " +
                            std::to_string(nf) + " faces)");
}

Decomposition decompose(const Mesh& mesh) {
    Decomposition d;
    if (mesh.num_faces() == 0) return d;
    if (mesh.num_components() != 1) throw RequestError("tree-cotree: the mesh is not edge-connected");
    const bool has_boundary = identify_boundary(mesh, d);
    number_interior_edges(mesh, d);
    // Rooted at the boundary vertex, else at the lowest referenced vertex.
    VertexId root(mesh.num_vertices());
    if (!has_boundary) {
        root = mesh.from(HalfedgeId(0));
        for (const HalfedgeId h : mesh.halfedges()) root = std::min(root, mesh.from(h));
    }
    build_tree(mesh, d, root);
    build_cotree(mesh, d);
    return d;
}

/// The faces f .. lca .. g of the cotree path between f and g, then back to f across the edge
/// that joins g and f: a closed chain.
std::vector<FaceId> cotree_cycle(IdSpan<FaceId, FaceId> fparent, IdSpan<FaceId, uint32_t> depth, FaceId f, FaceId g) {
    std::vector<FaceId> up, down;  // f .. lca, g .. (child of lca)
    while (depth[f] > depth[g]) {
        up.push_back(f);
        f = fparent[f];
    }
    while (depth[g] > depth[f]) {
        down.push_back(g);
        g = fparent[g];
    }
    while (f != g) {
        up.push_back(f);
        down.push_back(g);
        f = fparent[f];
        g = fparent[g];
    }
    up.push_back(f);
    up.insert(up.end(), down.rbegin(), down.rend());
    return up;
}

/// Number of faces of cotree_cycle(f, g).
size_t cotree_cycle_length(IdSpan<FaceId, FaceId> fparent, IdSpan<FaceId, uint32_t> depth, FaceId f, FaceId g) {
    size_t n = 1;
    for (; depth[f] > depth[g]; ++n) f = fparent[f];
    for (; depth[g] > depth[f]; ++n) g = fparent[g];
    for (; f != g; n += 2) {
        f = fparent[f];
        g = fparent[g];
    }
    return n;
}

}  // namespace

std::vector<std::vector<uint32_t>> tree_cotree_generators(const Mesh& mesh, const std::vector<uint32_t>& order) {
    const uint32_t nf = mesh.num_faces();
    // Face -> position in `order`.
    IdVector<FaceId, uint32_t> pos(nf, kNone);
    if (order.empty()) {
        for (const FaceId f : mesh.faces()) pos[f] = f.idx();
    } else {
        if (order.size() != nf) throw RequestError("tree-cotree: face order does not have one entry per face");
        for (uint32_t i = 0; i < nf; ++i) {
            const FaceId f(order[i]);
            if (f.idx() >= nf || pos[f] != kNone) throw RequestError("tree-cotree: face order is not a permutation of the faces");
            pos[f] = i;
        }
    }
    const Decomposition d = decompose(mesh);
    const uint32_t ne = static_cast<uint32_t>(d.edge_he.size());
    const auto& edge_he = d.edge_he;
    const auto& in_tree = d.in_tree;
    const auto& in_cotree = d.in_cotree;

    // One generator per leftover edge: the edge plus the cotree path between its faces.
    std::vector<std::vector<uint32_t>> gens;
    for (uint32_t e = 0; e < ne; ++e) {
        if (in_tree[e] || in_cotree[e]) continue;
        const HalfedgeId h = edge_he[e];
        const std::vector<FaceId> cycle = cotree_cycle(d.fparent, d.depth, Mesh::face(h), Mesh::face(mesh.twin(h)));
        std::vector<uint32_t> positions;
        positions.reserve(cycle.size());
        for (const FaceId f : cycle) positions.push_back(pos[f]);
        gens.push_back(std::move(positions));
    }
    return gens;
}

}  // namespace singlestrip

namespace singlestrip {

namespace {

/// Preorder number and subtree size of every tree vertex: the subtree below a vertex is the
/// preorder interval [pre, pre + size). Parents come before children in d.tree_order (BFS), so
/// each child takes the next free slot of its parent. Vertices outside the tree keep kNone.
void preorder_intervals(const Mesh& mesh, const Decomposition& d, IdVector<VertexId, uint32_t>& pre, IdVector<VertexId, uint32_t>& size) {
    const size_t nq = d.tree_parent_edge.size();
    pre.assign(nq, kNone);
    size.assign(nq, 1);
    if (d.tree_order.empty()) return;
    auto parent_of = [&](VertexId v) {
        const auto [a, b] = quotient_ends(mesh, d, d.tree_parent_edge[v]);
        return a == v ? b : a;
    };
    for (auto it = d.tree_order.rbegin(); it != d.tree_order.rend(); ++it)
        if (d.tree_parent_edge[*it] != kNone) size[parent_of(*it)] += size[*it];
    IdVector<VertexId, uint32_t> next_free(nq, 0);
    for (const VertexId v : d.tree_order) {
        pre[v] = d.tree_parent_edge[v] == kNone ? 0 : next_free[parent_of(v)];
        if (d.tree_parent_edge[v] != kNone) next_free[parent_of(v)] += size[v];
        next_free[v] = pre[v] + 1;
    }
}

}  // namespace

HomologyClassifier::HomologyClassifier(const Mesh& mesh) : mesh_(&mesh) {
    Decomposition d = decompose(mesh);
    const uint32_t ne = static_cast<uint32_t>(d.edge_he.size());
    bit_of_edge_.assign(ne, kNone);
    for (uint32_t e = 0; e < ne; ++e)
        if (!d.in_tree[e] && !d.in_cotree[e]) {
            bit_of_edge_[e] = static_cast<uint32_t>(leftover_.size());
            leftover_.push_back(e);
        }
    IdVector<VertexId, uint32_t> pre, size;
    preorder_intervals(mesh, d, pre, size);
    // Both endpoints of every leftover edge, sorted by the preorder number of their vertex.
    std::vector<std::pair<uint32_t, uint32_t>> ends;  // (preorder, class bit)
    ends.reserve(2 * leftover_.size());
    for (uint32_t j = 0; j < leftover_.size(); ++j) {
        const auto [a, b] = quotient_ends(mesh, d, leftover_[j]);
        ends.push_back({pre[a], j});
        ends.push_back({pre[b], j});
    }
    std::sort(ends.begin(), ends.end());
    std::vector<uint32_t> end_pre(ends.size());
    end_bit_.resize(ends.size());
    for (size_t i = 0; i < ends.size(); ++i) std::tie(end_pre[i], end_bit_[i]) = ends[i];
    // Per tree edge: the endpoints in the subtree below it (its child's preorder interval).
    under_first_.assign(ne, 0);
    under_last_.assign(ne, 0);
    for (const VertexId c : d.tree_order) {
        const uint32_t e = d.tree_parent_edge[c];
        if (e == kNone) continue;
        under_first_[e] = static_cast<uint32_t>(std::lower_bound(end_pre.begin(), end_pre.end(), pre[c]) - end_pre.begin());
        under_last_[e] = static_cast<uint32_t>(std::lower_bound(end_pre.begin(), end_pre.end(), pre[c] + size[c]) - end_pre.begin());
    }
    edge_of_he_ = std::move(d.edge_of_he).release();
    for (const uint32_t e : leftover_) leftover_he_.push_back(d.edge_he[e]);
    fparent_ = std::move(d.fparent).release();
    depth_ = std::move(d.depth).release();
}

std::vector<FaceId> HomologyClassifier::generator(size_t j) const {
    const HalfedgeId h = leftover_he_.at(j);
    return cotree_cycle(IdSpan<FaceId, FaceId>(fparent_), IdSpan<FaceId, uint32_t>(depth_), Mesh::face(h), Mesh::face(mesh_->twin(h)));
}

size_t HomologyClassifier::generator_length(size_t j) const {
    const HalfedgeId h = leftover_he_.at(j);
    return cotree_cycle_length(IdSpan<FaceId, FaceId>(fparent_), IdSpan<FaceId, uint32_t>(depth_), Mesh::face(h),
                               Mesh::face(mesh_->twin(h)));
}

// Bit j = crossings of leftover edge j + crossings of the tree paths from its two endpoints to
// the root. A crossed tree edge lies on the root path of exactly the vertices below it, so it
// flips the endpoints in one preorder interval; parity is odd between the 1st and 2nd, 3rd and
// 4th, ... interval ends in sorted order.
std::vector<uint64_t> HomologyClassifier::classify(const std::vector<FaceId>& faces) const {
    const Mesh& mesh = *mesh_;
    const IdSpan<HalfedgeId, uint32_t> edge_of_he(edge_of_he_);
    std::vector<uint64_t> bits((leftover_.size() + 63) / 64, 0);
    if (faces.size() < 2) return bits;
    std::vector<uint32_t> crossed(faces.size());
    for (size_t i = 0; i < faces.size(); ++i) {
        const HalfedgeId h = mesh.shared_halfedge(faces[i], faces[(i + 1) % faces.size()]);
        if (!h.valid()) throw InternalError("homology class: consecutive faces of a chain are not adjacent");
        crossed[i] = edge_of_he[h];
    }
    std::sort(crossed.begin(), crossed.end());
    auto flip = [&](uint32_t bit) { bits[bit / 64] ^= uint64_t{1} << (bit % 64); };
    std::vector<uint32_t> marks;
    for (size_t i = 0, j = 0; i < crossed.size(); i = j) {
        while (j < crossed.size() && crossed[j] == crossed[i]) ++j;
        if ((j - i) % 2 == 0) continue;  // crossed back and forth: no intersection
        const uint32_t e = crossed[i];
        if (bit_of_edge_[e] != kNone) flip(bit_of_edge_[e]);
        if (under_first_[e] != under_last_[e]) {
            marks.push_back(under_first_[e]);
            marks.push_back(under_last_[e]);
        }
    }
    std::sort(marks.begin(), marks.end());
    for (size_t k = 0; k + 1 < marks.size(); k += 2)
        for (uint32_t i = marks[k]; i < marks[k + 1]; ++i) flip(end_bit_[i]);
    return bits;
}

size_t z2_rank(std::vector<std::vector<uint64_t>> rows) {
    if (rows.empty()) return 0;
    const size_t words = rows[0].size();
    size_t rank = 0;
    for (size_t col = 0; col < 64 * words && rank < rows.size(); ++col) {
        const size_t w = col / 64;
        const uint64_t bit = uint64_t{1} << (col % 64);
        size_t piv = rank;
        while (piv < rows.size() && !(rows[piv][w] & bit)) ++piv;
        if (piv == rows.size()) continue;
        std::swap(rows[piv], rows[rank]);
        for (size_t r = rank + 1; r < rows.size(); ++r)
            if (rows[r][w] & bit)
                for (size_t k = w; k < words; ++k) rows[r][k] ^= rows[rank][k];
        ++rank;
    }
    return rank;
}

}  // namespace singlestrip
