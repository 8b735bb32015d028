// singlestrip — the verifier's cycle check: as many cycles as the rank of H1, each a closed chain
// of edge-adjacent output faces, independent in H1(M;Z2) by its own tree-cotree on the output.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "verify_checks.hpp"

namespace singlestrip::verify_detail {

namespace {

using Bits = std::vector<uint64_t>;

size_t z2_rank(std::vector<Bits>& rows, size_t ncols) {
    size_t rank = 0;
    for (size_t col = 0; col < ncols && rank < rows.size(); ++col) {
        const size_t w = col / 64;
        const uint64_t bit = uint64_t{1} << (col % 64);
        size_t piv = rank;
        while (piv < rows.size() && !(rows[piv][w] & bit)) ++piv;
        if (piv == rows.size()) continue;
        std::swap(rows[piv], rows[rank]);
        for (size_t r = 0; r < rows.size(); ++r)
            if (r != rank && (rows[r][w] & bit))
                for (size_t k = 0; k < rows[r].size(); ++k) rows[r][k] ^= rows[rank][k];
        ++rank;
    }
    return rank;
}

/// Undirected edge ids of the output's half-edges (both halves of an interior edge share one).
std::vector<uint32_t> number_edges(const Adjacency& out, uint32_t& num_edges) {
    const size_t F = out.faces.size();
    std::vector<uint32_t> edge_id(3 * F, kNo);
    num_edges = 0;
    for (uint32_t h = 0; h < 3 * F; ++h) {
        if (!out.face_ok[h / 3]) continue;
        const uint32_t t = out.twin[h];
        if (t == kNo || h < t)
            edge_id[h] = num_edges++;
        else
            edge_id[h] = edge_id[t];
    }
    return edge_id;
}

/// Each cycle's crossings (edge, cycle) into `cross`; false (with failures) if a cycle is not a
/// closed chain of edge-adjacent output faces.
bool collect_crossings(const std::vector<std::vector<uint32_t>>& cycles, const Adjacency& out, const std::vector<uint32_t>& edge_id,
                       Failures& fails, std::vector<std::pair<uint32_t, uint32_t>>& cross) {
    const size_t m = cycles.size();
    const size_t F = out.faces.size();
    bool closed_ok = true;
    for (uint32_t c = 0; c < m; ++c) {
        const auto& cyc = cycles[c];
        if (cyc.size() < 2) {
            fails.add("cycles",
                      "cycle " + std::to_string(c) + " has " + std::to_string(cyc.size()) + " faces; a closed chain needs at least 2");
            closed_ok = false;
            continue;
        }
        bool this_ok = true;
        for (size_t i = 0; i < cyc.size() && this_ok; ++i) {
            const uint32_t f = cyc[i], g = cyc[(i + 1) % cyc.size()];
            if (f >= F || g >= F) {
                fails.add("cycles", "cycle " + std::to_string(c) + " position " + std::to_string(f >= F ? i : (i + 1) % cyc.size()) +
                                        ": face " + std::to_string(f >= F ? f : g) + " out of range (" + std::to_string(F) + " faces)");
                this_ok = false;
                break;
            }
            uint32_t e = kNo;
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t t = out.twin[3 * f + k];
                if (t != kNo && t / 3 == g) e = edge_id[3 * f + k];
            }
            if (e == kNo) {
                fails.add("cycles", "cycle " + std::to_string(c) + ": faces " + std::to_string(f) + " and " + std::to_string(g) +
                                        " (positions " + std::to_string(i) + ", " + std::to_string((i + 1) % cyc.size()) +
                                        ") do not share an edge" + (i + 1 == cyc.size() ? " (the chain is not closed)" : ""));
                this_ok = false;
                break;
            }
            cross.emplace_back(e, c);
        }
        closed_ok = closed_ok && this_ok;
    }
    return closed_ok;
}

/// Crossing parity per edge (a bit per cycle), stored only for edges some cycle crosses an odd
/// number of times.
struct EdgeParity {
    size_t W = 0;
    std::vector<uint32_t> edge_slot;  // edge -> row of edge_bits, kNo = crossed by none
    std::vector<Bits> edge_bits;
    EdgeParity(std::vector<std::pair<uint32_t, uint32_t>> cross, uint32_t num_edges, size_t m)
        : W((m + 63) / 64), edge_slot(num_edges, kNo) {
        std::sort(cross.begin(), cross.end());
        for (size_t i = 0; i < cross.size();) {
            size_t j = i;
            while (j < cross.size() && cross[j] == cross[i]) ++j;
            if ((j - i) % 2 == 1) {
                uint32_t& slot = edge_slot[cross[i].first];
                if (slot == kNo) {
                    slot = static_cast<uint32_t>(edge_bits.size());
                    edge_bits.emplace_back(W, 0);
                }
                edge_bits[slot][cross[i].second / 64] ^= uint64_t{1} << (cross[i].second % 64);
            }
            i = j;
        }
    }
    void xor_edge(Bits& into, uint32_t e) const {
        if (edge_slot[e] != kNo)
            for (size_t k = 0; k < W; ++k) into[k] ^= edge_bits[edge_slot[e]][k];
    }
};

/// Tree-cotree on the output, boundary vertices identified to one super-vertex S = num_points.
struct OutputTreeCotree {
    uint32_t root = kNo;
    std::vector<uint32_t> order;             // quotient vertices in BFS order, root first
    std::vector<uint32_t> tree_parent_edge;  // per quotient vertex: half-edge to its parent
    std::vector<uint32_t> leftovers;         // one half-edge per edge in neither tree
};

uint32_t quotient(const Adjacency& out, uint32_t v) {
    return out.on_boundary[v] ? static_cast<uint32_t>(out.num_points) : v;
}

OutputTreeCotree output_tree_cotree(const Adjacency& out, const std::vector<uint32_t>& edge_id, uint32_t num_edges, bool has_boundary) {
    const size_t F = out.faces.size();
    OutputTreeCotree tc;
    const uint32_t NV = static_cast<uint32_t>(out.num_points);
    const uint32_t S = NV;
    auto q = [&](uint32_t v) { return quotient(out, v); };
    // Interior edges as adjacency lists (CSR) of the quotient graph.
    std::vector<uint32_t> off(NV + 2, 0);
    std::vector<uint32_t> interior;  // one representative half-edge per interior edge
    for (uint32_t h = 0; h < 3 * F; ++h)
        if (out.face_ok[h / 3] && out.twin[h] != kNo && h < out.twin[h]) interior.push_back(h);
    for (uint32_t h : interior) {
        const uint32_t a = q(out.from(h)), b = q(out.to(h));
        if (a == b) continue;
        ++off[a + 1];
        ++off[b + 1];
    }
    for (uint32_t i = 0; i <= NV; ++i) off[i + 1] += off[i];
    std::vector<uint32_t> adj(off[NV + 1]);
    {
        std::vector<uint32_t> fill(off.begin(), off.end() - 1);
        for (uint32_t h : interior) {
            const uint32_t a = q(out.from(h)), b = q(out.to(h));
            if (a == b) continue;
            adj[fill[a]++] = h;
            adj[fill[b]++] = h;
        }
    }
    std::vector<bool> in_tree(num_edges, false);
    std::vector<uint32_t>& tree_parent_edge = tc.tree_parent_edge;
    std::vector<uint32_t>& order = tc.order;
    tree_parent_edge.assign(NV + 1, kNo);
    std::vector<bool> seen(NV + 1, false);
    uint32_t& root = tc.root;
    if (has_boundary)
        root = S;
    else
        for (uint32_t f = 0; f < F && root == kNo; ++f)
            if (out.face_ok[f]) root = out.faces[f][0];
    if (root == kNo) return tc;
    seen[root] = true;
    order.push_back(root);
    for (size_t i = 0; i < order.size(); ++i) {
        const uint32_t x = order[i];
        for (uint32_t k = off[x]; k < off[x + 1]; ++k) {
            const uint32_t h = adj[k];
            const uint32_t a = q(out.from(h)), b = q(out.to(h));
            const uint32_t y = a == x ? b : a;
            if (seen[y]) continue;
            seen[y] = true;
            tree_parent_edge[y] = h;
            in_tree[edge_id[h]] = true;
            order.push_back(y);
        }
    }
    // Dual spanning tree over interior edges not in T.
    std::vector<bool> in_cotree(num_edges, false), face_seen(F, false);
    std::vector<uint32_t> fq;
    for (uint32_t f = 0; f < F && fq.empty(); ++f)
        if (out.face_ok[f]) {
            fq.push_back(f);
            face_seen[f] = true;
        }
    for (size_t i = 0; i < fq.size(); ++i) {
        const uint32_t f = fq[i];
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t h = 3 * f + k, t = out.twin[h];
            if (t == kNo || in_tree[edge_id[h]] || face_seen[t / 3]) continue;
            face_seen[t / 3] = true;
            in_cotree[edge_id[h]] = true;
            fq.push_back(t / 3);
        }
    }
    for (uint32_t h : interior)
        if (!in_tree[edge_id[h]] && !in_cotree[edge_id[h]]) tc.leftovers.push_back(h);
    return tc;
}

/// Class rows of the tree-cotree generators: bit c of row j says whether cycle c crosses the
/// relative cycle of leftover edge j (the edge plus the tree paths to its ends) an odd number of
/// times.
std::vector<Bits> class_rows(const Adjacency& out, const OutputTreeCotree& tc, const std::vector<uint32_t>& edge_id,
                             const EdgeParity& parity) {
    const size_t W = parity.W;
    const uint32_t NV = static_cast<uint32_t>(out.num_points);
    auto q = [&](uint32_t v) { return quotient(out, v); };
    const uint32_t root = tc.root;
    const std::vector<uint32_t>& order = tc.order;
    const std::vector<uint32_t>& tree_parent_edge = tc.tree_parent_edge;
    const std::vector<uint32_t>& leftovers = tc.leftovers;
    // P(x): parity vector of tree path root->x.
    std::vector<Bits> P(NV + 1);
    P[root].assign(W, 0);
    for (size_t i = 1; i < order.size(); ++i) {
        const uint32_t y = order[i], h = tree_parent_edge[y];
        const uint32_t a = q(out.from(h)), b = q(out.to(h));
        const uint32_t x = a == y ? b : a;
        P[y] = P[x];
        parity.xor_edge(P[y], edge_id[h]);
    }
    std::vector<Bits> rows;
    rows.reserve(leftovers.size());
    for (uint32_t h : leftovers) {
        const uint32_t a = q(out.from(h)), b = q(out.to(h));
        Bits r(W, 0);
        if (!P[a].empty() && !P[b].empty())
            for (size_t k = 0; k < W; ++k) r[k] = P[a][k] ^ P[b][k];
        parity.xor_edge(r, edge_id[h]);
        rows.push_back(std::move(r));
    }
    return rows;
}

void check_cycles(const VerifyInput& in, const Adjacency& out, long long expected, Failures& fails, VerifyReport& report) {
    const auto& cycles = *in.cycles;
    const size_t m = cycles.size();
    report.cycles_checked = m;
    if (static_cast<long long>(m) != expected)
        fails.add("cycles",
                  "found " + std::to_string(m) + " cycles, expected 2g+h-1 = " + std::to_string(expected) + " (2g for a closed surface)");
    uint32_t num_edges = 0;
    const std::vector<uint32_t> edge_id = number_edges(out, num_edges);
    std::vector<std::pair<uint32_t, uint32_t>> cross;
    if (!collect_crossings(cycles, out, edge_id, fails, cross)) {
        report.notes.push_back("cycles: independence not checked (a cycle is not a closed chain)");
        return;
    }
    if (m == 0) return;
    if (static_cast<long long>(m) > expected) {
        report.notes.push_back("cycles: independence not checked (more cycles than the dimension of H1)");
        return;
    }
    const EdgeParity parity(std::move(cross), num_edges, m);
    const OutputTreeCotree tc = output_tree_cotree(out, edge_id, num_edges, report.boundary_loops > 0);
    if (tc.root == kNo) return;
    const std::vector<uint32_t>& leftovers = tc.leftovers;
    if (static_cast<long long>(leftovers.size()) != expected) {
        fails.add("cycles", "tree-cotree on the output gives " + std::to_string(leftovers.size()) + " generators, expected " +
                                std::to_string(expected) + " (output is not a connected surface of the input's topology)");
        return;
    }
    std::vector<Bits> rows = class_rows(out, tc, edge_id, parity);
    const size_t W = parity.W;
    // Null-homologous cycles: zero column.
    Bits any(W, 0);
    for (const Bits& r : rows)
        for (size_t k = 0; k < W; ++k) any[k] |= r[k];
    for (uint32_t c = 0; c < m; ++c)
        if (!(any[c / 64] >> (c % 64) & 1))
            fails.add("cycles",
                      "cycle " + std::to_string(c) + " is null-homologous in H1(M;Z2) (it bounds a region, e.g. a loop around one vertex)");
    const size_t rank = z2_rank(rows, m);
    report.cycle_rank = rank;
    if (rank < m)
        fails.add("cycles", "the " + std::to_string(m) + " cycles are not linearly independent in H1(M;Z2): rank " + std::to_string(rank));
}
}  // namespace

// The cycles: as many as the surface's rank and a basis (check_cycles) when the output is one
// manifold component.
void check_cycles_request(const Checked& chk, size_t num_components) {
    const VerifyInput& in = chk.in;
    const Adjacency& inp = chk.inp;
    const Adjacency& out = chk.out;
    Failures& fails = chk.fails;
    VerifyReport& report = chk.report;
    const bool all_faces_ok = chk.all_faces_ok();
    if (in.cycles) {
        const long long h = static_cast<long long>(inp.boundary_loops);
        const long long expected = h > 0 ? 1 - inp.euler : 2 - inp.euler;
        if (num_components > 1) {
            report.cycles_checked = in.cycles->size();
            report.notes.push_back("cycles: not checked (the output has " + std::to_string(num_components) +
                                   " components; the cycle check covers one)");
        } else if (!out.manifold || !all_faces_ok) {
            report.cycles_checked = in.cycles->size();
            if (static_cast<long long>(in.cycles->size()) != expected)
                fails.add("cycles", "found " + std::to_string(in.cycles->size()) + " cycles, expected " + std::to_string(expected));
            report.notes.push_back("cycles: independence not checked (output is not a manifold)");
        } else {
            check_cycles(in, out, expected, fails, report);
        }
    }
}

}  // namespace singlestrip::verify_detail
