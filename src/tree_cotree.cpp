// singlestrip — tree–cotree homology generators (Eppstein 2003), the reference for §4's cycles.
#include "singlestrip/tree_cotree.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "singlestrip/errors.hpp"

namespace singlestrip {

namespace {

/// Tree T (primal, boundary identified) and cotree C (dual) of a mesh; see the header.
struct Decomposition {
    std::vector<uint32_t> q;                 ///< vertex -> quotient vertex (boundary -> nv)
    std::vector<uint32_t> edge_he;           ///< interior edge -> representative half-edge
    std::vector<uint32_t> edge_of_he;        ///< half-edge -> interior edge (kNone on boundary)
    std::vector<uint8_t> in_tree, in_cotree; ///< per interior edge
    std::vector<uint32_t> tree_order;        ///< quotient vertices in BFS order, root first
    std::vector<uint32_t> tree_parent_edge;  ///< per quotient vertex (kNone at the root)
    std::vector<uint32_t> fparent, depth;    ///< cotree parent face and depth per face
};

Decomposition decompose(const Mesh& mesh) {
    Decomposition d;
    const uint32_t nf = mesh.num_faces();
    const uint32_t nv = mesh.num_vertices();
    if (nf == 0) return d;
    if (mesh.num_components() != 1) throw RequestError("tree-cotree: the mesh is not edge-connected");

    // Quotient vertices: all boundary vertices become the extra vertex `nv`.
    const uint32_t super = nv;
    std::vector<uint32_t>& q = d.q;
    q.resize(nv);
    for (uint32_t v = 0; v < nv; ++v) q[v] = v;
    bool has_boundary = false;
    const uint32_t nh = mesh.num_halfedges();
    for (uint32_t h = 0; h < nh; ++h) {
        if (!mesh.is_boundary(h)) continue;
        has_boundary = true;
        q[mesh.from(h)] = super;
        q[mesh.to(h)] = super;
    }

    // Interior edges, one representative half-edge each (h < twin(h)).
    std::vector<uint32_t>& edge_he = d.edge_he;
    for (uint32_t h = 0; h < nh; ++h)
        if (!mesh.is_boundary(h) && h < mesh.twin(h)) edge_he.push_back(h);
    const uint32_t ne = static_cast<uint32_t>(edge_he.size());
    d.edge_of_he.assign(nh, kNone);
    for (uint32_t e = 0; e < ne; ++e) {
        d.edge_of_he[edge_he[e]] = e;
        d.edge_of_he[mesh.twin(edge_he[e])] = e;
    }

    // Primal adjacency (CSR) of the quotient graph; loops (both ends on the boundary) are left out
    // of the tree and so end up dual edges.
    std::vector<uint32_t> start(nv + 2, 0);
    for (uint32_t e = 0; e < ne; ++e) {
        const uint32_t a = q[mesh.from(edge_he[e])], b = q[mesh.to(edge_he[e])];
        if (a == b) continue;
        ++start[a + 1];
        ++start[b + 1];
    }
    for (uint32_t v = 0; v <= nv; ++v) start[v + 1] += start[v];
    std::vector<uint32_t> adj(start[nv + 1]);
    {
        std::vector<uint32_t> fill(start.begin(), start.end() - 1);
        for (uint32_t e = 0; e < ne; ++e) {
            const uint32_t a = q[mesh.from(edge_he[e])], b = q[mesh.to(edge_he[e])];
            if (a == b) continue;
            adj[fill[a]++] = e;
            adj[fill[b]++] = e;
        }
    }

    // T: breadth-first spanning tree of the quotient graph.
    uint32_t root = super;
    if (!has_boundary) {
        root = mesh.from(0);
        for (uint32_t h = 0; h < nh; ++h) root = std::min(root, mesh.from(h));
    }
    d.in_tree.assign(ne, 0);
    d.tree_parent_edge.assign(nv + 1, kNone);
    std::vector<uint8_t> seen(nv + 1, 0);
    std::vector<uint32_t>& queue = d.tree_order;
    queue.assign(1, root);
    seen[root] = 1;
    for (size_t head = 0; head < queue.size(); ++head) {
        const uint32_t v = queue[head];
        for (uint32_t i = start[v]; i < start[v + 1]; ++i) {
            const uint32_t e = adj[i];
            const uint32_t a = q[mesh.from(edge_he[e])], b = q[mesh.to(edge_he[e])];
            const uint32_t w = a == v ? b : a;
            if (seen[w]) continue;
            seen[w] = 1;
            d.in_tree[e] = 1;
            d.tree_parent_edge[w] = e;
            queue.push_back(w);
        }
    }

    // C: breadth-first spanning tree of the dual graph over edges not in T.
    d.fparent.assign(nf, kNone);
    d.depth.assign(nf, 0);
    d.in_cotree.assign(ne, 0);
    std::vector<uint8_t> reached(nf, 0);
    std::vector<uint32_t> fqueue{0};
    reached[0] = 1;
    for (size_t head = 0; head < fqueue.size(); ++head) {
        const uint32_t f = fqueue[head];
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t h = Mesh::halfedge(f, k);
            const uint32_t g = mesh.neighbor(h);
            if (g == kNone) continue;
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
        throw InternalError("tree-cotree: the dual graph minus the tree is not connected (" +
                            std::to_string(fqueue.size()) + " of " + std::to_string(nf) + " faces)");
    return d;
}

}  // namespace

std::vector<std::vector<uint32_t>> tree_cotree_generators(const Mesh& mesh, const std::vector<uint32_t>& order) {
    const uint32_t nf = mesh.num_faces();
    // Face -> position in `order`.
    std::vector<uint32_t> pos(nf);
    if (order.empty()) {
        for (uint32_t f = 0; f < nf; ++f) pos[f] = f;
    } else {
        if (order.size() != nf) throw RequestError("tree-cotree: face order does not have one entry per face");
        std::fill(pos.begin(), pos.end(), kNone);
        for (uint32_t i = 0; i < nf; ++i) {
            if (order[i] >= nf || pos[order[i]] != kNone)
                throw RequestError("tree-cotree: face order is not a permutation of the faces");
            pos[order[i]] = i;
        }
    }
    const Decomposition d = decompose(mesh);
    const uint32_t ne = static_cast<uint32_t>(d.edge_he.size());
    const auto& fparent = d.fparent;
    const auto& depth = d.depth;
    const auto& edge_he = d.edge_he;
    const auto& in_tree = d.in_tree;
    const auto& in_cotree = d.in_cotree;

    // One generator per leftover edge: the edge plus the cotree path between its faces.
    std::vector<std::vector<uint32_t>> gens;
    for (uint32_t e = 0; e < ne; ++e) {
        if (in_tree[e] || in_cotree[e]) continue;
        uint32_t f = Mesh::face(edge_he[e]);
        uint32_t g = Mesh::face(mesh.twin(edge_he[e]));
        std::vector<uint32_t> up, down;  // f .. lca, g .. (child of lca)
        while (depth[f] > depth[g]) { up.push_back(f); f = fparent[f]; }
        while (depth[g] > depth[f]) { down.push_back(g); g = fparent[g]; }
        while (f != g) {
            up.push_back(f);
            down.push_back(g);
            f = fparent[f];
            g = fparent[g];
        }
        up.push_back(f);
        std::vector<uint32_t> cycle;
        cycle.reserve(up.size() + down.size());
        for (uint32_t x : up) cycle.push_back(pos[x]);
        for (auto it = down.rbegin(); it != down.rend(); ++it) cycle.push_back(pos[*it]);
        gens.push_back(std::move(cycle));
    }
    return gens;
}

Cycles tree_cotree_cycles(const StripResult& result) {
    Cycles out;
    out.cycles = tree_cotree_generators(result.mesh, result.order);
    const StripArrays arrays = strip_arrays(result);
    out.lengths.reserve(out.cycles.size());
    for (const auto& c : out.cycles) out.lengths.push_back(cycle_length(arrays, c));
    return out;
}

}  // namespace singlestrip

namespace singlestrip {

HomologyClassifier::HomologyClassifier(const Mesh& mesh) : mesh_(&mesh) {
    Decomposition d = decompose(mesh);
    q_ = std::move(d.q);
    edge_of_he_ = std::move(d.edge_of_he);
    edge_he_ = std::move(d.edge_he);
    tree_order_ = std::move(d.tree_order);
    tree_parent_edge_ = std::move(d.tree_parent_edge);
    for (uint32_t e = 0; e < edge_he_.size(); ++e)
        if (!d.in_tree[e] && !d.in_cotree[e]) leftover_.push_back(e);
}

std::vector<uint64_t> HomologyClassifier::classify(const std::vector<uint32_t>& faces) const {
    const Mesh& mesh = *mesh_;
    // Crossing parity per interior edge (sparse: only the edges the chain crosses).
    std::vector<uint8_t> crossed(edge_he_.size(), 0);
    for (size_t i = 0; i < faces.size() && faces.size() >= 2; ++i) {
        const uint32_t h = mesh.shared_halfedge(faces[i], faces[(i + 1) % faces.size()]);
        if (h == kNone) throw InternalError("homology class: consecutive faces of a chain are not adjacent");
        crossed[edge_of_he_[h]] ^= 1;
    }
    // Parity along the tree path from every quotient vertex to the root (BFS order: parents first).
    std::vector<uint8_t> par(q_.size() + 1, 0);
    for (uint32_t v : tree_order_) {
        const uint32_t e = tree_parent_edge_[v];
        if (e == kNone) continue;
        const uint32_t a = q_[mesh.from(edge_he_[e])], b = q_[mesh.to(edge_he_[e])];
        par[v] = par[a == v ? b : a] ^ crossed[e];
    }
    std::vector<uint64_t> bits((leftover_.size() + 63) / 64, 0);
    for (size_t j = 0; j < leftover_.size(); ++j) {
        const uint32_t e = leftover_[j];
        const uint8_t p = crossed[e] ^ par[q_[mesh.from(edge_he_[e])]] ^ par[q_[mesh.to(edge_he_[e])]];
        if (p) bits[j / 64] |= uint64_t{1} << (j % 64);
    }
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
