// singlestrip — the verifier's checks of the strip's controls: constraint edges (§5.1) kept
// whole and never crossed, the source in the first face and the target in the last (§5.2).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "verify_checks.hpp"

namespace singlestrip::verify_detail {

// Constraint edges are input edges, never split, and never crossed between consecutive faces.
void check_constraints(const Checked& chk) {
    const VerifyInput& in = chk.in;
    const Adjacency& inp = chk.inp;
    const Adjacency& out = chk.out;
    const std::vector<uint32_t>& parent = chk.parent;
    Failures& fails = chk.fails;
    const size_t n = in.in_points.size();
    const size_t F = chk.num_faces();
    if (!in.constraints.empty()) {
        std::unordered_set<uint64_t> cset;
        for (size_t i = 0; i < in.constraints.size(); ++i) {
            const auto [a, b] = in.constraints[i];
            const std::string who = "constraint " + std::to_string(i) + " (" + std::to_string(a) + "," + std::to_string(b) + ")";
            if (a >= n || b >= n || a == b) {
                fails.add("constraints", who + ": not a pair of distinct input vertices");
                continue;
            }
            if (!inp.has_edge(a, b)) {
                fails.add("constraints", who + ": not an edge of the input");
                continue;
            }
            cset.insert(ukey(a, b));
            if (!out.has_edge(a, b)) fails.add("constraints", who + ": constraint edge was split (it is not an edge of the output)");
        }
        auto constraint_edges_of = [&](uint32_t P, std::vector<std::pair<uint32_t, uint32_t>>& es) {
            const Triangle& t = in.in_faces[P];
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t u = t[k], v = t[(k + 1) % 3];
                if (cset.count(ukey(u, v))) es.emplace_back(u, v);
            }
        };
        std::vector<std::pair<uint32_t, uint32_t>> es;
        // No output vertex strictly inside a constraint edge. A constraint that is still an
        // output edge was not split: another vertex on its line is the input's degenerate
        // geometry (an input edge through an input vertex, or a midpoint of an edge along it).
        auto whole = [&](uint32_t u, uint32_t v) { return out.has_edge(u, v); };
        for (uint32_t f = 0; f < F; ++f) {
            if (!out.face_ok[f] || parent[f] == kNo) continue;
            es.clear();
            constraint_edges_of(parent[f], es);
            for (const auto& [u, v] : es)
                for (uint32_t p : in.out_faces[f]) {
                    if (p == u || p == v || whole(u, v)) continue;
                    double t = 0;
                    if (on_segment(in.in_points[u], in.in_points[v], in.out_points[p], &t) && t > kRelTol && t < 1 - kRelTol)
                        fails.add("constraints", "vertex " + std::to_string(p) + " (face " + std::to_string(f) +
                                                     ") lies inside constraint edge (" + std::to_string(u) + "," + std::to_string(v) +
                                                     "): the constraint was split");
                }
        }
        // Consecutive faces never share (a piece of) a constraint edge.
        for (uint32_t f = 0; f + 1 < F; ++f) {
            if (!out.face_ok[f] || !out.face_ok[f + 1] || parent[f] == kNo || parent[f + 1] == kNo) continue;
            std::array<uint32_t, 3> common{};
            if (common_vertices(in.out_faces[f], in.out_faces[f + 1], common) != 2) continue;
            es.clear();
            constraint_edges_of(parent[f], es);
            if (parent[f + 1] != parent[f]) constraint_edges_of(parent[f + 1], es);
            for (const auto& [u, v] : es) {
                const V3 U = in.in_points[u], Vv = in.in_points[v];
                const bool piece = whole(u, v) ? ukey(common[0], common[1]) == ukey(u, v)
                                               : on_segment(U, Vv, in.out_points[common[0]]) && on_segment(U, Vv, in.out_points[common[1]]);
                if (piece) {
                    fails.add("constraints", "faces " + std::to_string(f) + " and " + std::to_string(f + 1) + " share edge (" +
                                                 std::to_string(common[0]) + "," + std::to_string(common[1]) + ") on constraint edge (" +
                                                 std::to_string(u) + "," + std::to_string(v) + "): the strip crosses a constraint");
                    break;
                }
            }
        }
    }
}

// The first face holds the source, the last face of the first strip the target.
void check_source_target(const Checked& chk, uint32_t first_strip_end) {
    const VerifyInput& in = chk.in;
    Failures& fails = chk.fails;
    const size_t n = in.in_points.size();
    auto has_vertex = [&](uint32_t f, uint32_t v) {
        const Triangle& t = in.out_faces[f];
        return t[0] == v || t[1] == v || t[2] == v;
    };
    if (in.source) {
        if (*in.source >= n)
            fails.add("source", "source vertex " + std::to_string(*in.source) + " is not an input vertex");
        else if (!has_vertex(0, *in.source))
            fails.add("source",
                      "first face 0 " + tri_str(in.out_faces[0]) + " does not contain source vertex " + std::to_string(*in.source));
    }
    if (in.target) {  // the end of the first strip (the whole output when there is one)
        const uint32_t last = first_strip_end;
        if (*in.target >= n)
            fails.add("target", "target vertex " + std::to_string(*in.target) + " is not an input vertex");
        else if (!has_vertex(last, *in.target))
            fails.add("target", "last face " + std::to_string(last) + " " + tri_str(in.out_faces[last]) +
                                    " of the first strip does not contain target vertex " + std::to_string(*in.target));
    }
}

}  // namespace singlestrip::verify_detail
