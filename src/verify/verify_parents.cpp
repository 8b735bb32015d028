// singlestrip — each output face's input parent for the verifier: the given parent array,
// range-checked, or inferred from the geometry (the input face containing the face's centroid).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "verify_checks.hpp"

namespace singlestrip::verify_detail {

namespace {

struct InputStars {
    std::vector<uint32_t> offset, faces;  // CSR: faces around each input vertex
};

InputStars build_stars(size_t n, const std::vector<Triangle>& in_faces) {
    InputStars s;
    s.offset.assign(n + 1, 0);
    for (const Triangle& t : in_faces)
        for (uint32_t v : t) ++s.offset[v + 1];
    for (size_t i = 0; i < n; ++i) s.offset[i + 1] += s.offset[i];
    s.faces.resize(s.offset[n]);
    std::vector<uint32_t> fill(s.offset.begin(), s.offset.end() - 1);
    for (uint32_t f = 0; f < in_faces.size(); ++f)
        for (uint32_t v : in_faces[f]) s.faces[fill[v]++] = f;
    return s;
}

/// Best input face among candidates for point q, in three tiers: a well-conditioned face that
/// contains q within kRelTol (the largest minimum barycentric coordinate wins), else a nearly
/// degenerate one that contains it, else a well-conditioned one within the rounding allowance of
/// ParentFrame::bary_tol (thin faces far from the origin). kNo when none contains q.
uint32_t best_container(const std::vector<Point3>& in_pts, const std::vector<Triangle>& in_faces, const std::vector<uint32_t>& cand,
                        const V3& q) {
    uint32_t best = kNo, sliver = kNo, loose = kNo;
    double best_min = -std::numeric_limits<double>::infinity(), loose_min = best_min;
    for (uint32_t f : cand) {
        const ParentFrame p = frame_of(in_pts, in_faces[f]);
        if (p.ill) {  // no reliable barycentrics: a robust containment test
            if (sliver == kNo && sliver_contains(p, q)) sliver = f;
            continue;
        }
        double dist = 0;
        const auto l = bary(p, q, dist);
        if (!(dist <= p.plane_tol())) continue;
        const double m = std::min({l[0], l[1], l[2]});
        if (dist <= kRelTol * p.size && m >= -kRelTol && m > best_min) {
            best_min = m;
            best = f;
        } else if (m >= -p.bary_tol() && m > loose_min) {
            loose_min = m;
            loose = f;
        }
    }
    return best != kNo ? best : sliver != kNo ? sliver : loose;
}

std::vector<uint32_t> infer_parents(const VerifyInput& in, const Adjacency& out, const InputStars& stars, Failures& fails) {
    const size_t n = in.in_points.size();
    const size_t F = in.out_faces.size();
    std::vector<uint32_t> parent(F, kNo);
    std::vector<uint32_t> queue;
    std::vector<uint32_t> cand;
    auto centroid = [&](uint32_t f) {
        const Triangle& t = in.out_faces[f];
        V3 c{0, 0, 0};
        for (uint32_t v : t)
            for (int k = 0; k < 3; ++k) c[static_cast<size_t>(k)] += in.out_points[v][static_cast<size_t>(k)] / 3.0;
        return c;
    };
    auto add_star = [&](uint32_t v) {
        for (uint32_t i = stars.offset[v]; i < stars.offset[v + 1]; ++i) cand.push_back(stars.faces[i]);
    };
    for (uint32_t f = 0; f < F; ++f) {
        if (!out.face_ok[f]) continue;
        cand.clear();
        const Triangle& t = in.out_faces[f];
        std::array<uint32_t, 3> orig{};
        int no = 0;
        for (uint32_t v : t)
            if (v < n) orig[static_cast<size_t>(no++)] = v;
        if (no == 0) continue;
        if (no >= 2) {
            // Faces containing both of two original vertices: intersect the stars.
            for (uint32_t i = stars.offset[orig[0]]; i < stars.offset[orig[0] + 1]; ++i) {
                const Triangle& it = in.in_faces[stars.faces[i]];
                for (int j = 1; j < no; ++j) {
                    const uint32_t w = orig[static_cast<size_t>(j)];
                    if (it[0] == w || it[1] == w || it[2] == w) {
                        cand.push_back(stars.faces[i]);
                        break;
                    }
                }
            }
            if (no == 3)  // the pair (orig[1], orig[2]) too
                for (uint32_t i = stars.offset[orig[1]]; i < stars.offset[orig[1] + 1]; ++i) {
                    const Triangle& it = in.in_faces[stars.faces[i]];
                    if (it[0] == orig[2] || it[1] == orig[2] || it[2] == orig[2]) cand.push_back(stars.faces[i]);
                }
        }
        uint32_t p = best_container(in.in_points, in.in_faces, cand, centroid(f));
        if (p == kNo) {
            cand.clear();
            for (int j = 0; j < no; ++j) add_star(orig[static_cast<size_t>(j)]);
            p = best_container(in.in_points, in.in_faces, cand, centroid(f));
        }
        if (p != kNo) {
            parent[f] = p;
            queue.push_back(f);
        }
    }
    // Breadth-first over edge-adjacent output faces for faces made only of inserted vertices.
    for (size_t qi = 0; qi < queue.size(); ++qi) {
        const uint32_t f = queue[qi];
        for (uint32_t i = 0; i < 3; ++i) {
            const uint32_t tw = out.twin[3 * f + i];
            if (tw == kNo) continue;
            const uint32_t g = tw / 3;
            if (parent[g] != kNo || !out.face_ok[g]) continue;
            const Triangle& P = in.in_faces[parent[f]];
            cand.assign(1, parent[f]);
            uint32_t p = best_container(in.in_points, in.in_faces, cand, centroid(g));
            if (p == kNo) {
                cand.clear();
                for (uint32_t v : P) add_star(v);
                p = best_container(in.in_points, in.in_faces, cand, centroid(g));
            }
            if (p != kNo) {
                parent[g] = p;
                queue.push_back(g);
            }
        }
    }
    for (uint32_t f = 0; f < F; ++f)
        if (out.face_ok[f] && parent[f] == kNo)
            fails.add("parent", "face " + std::to_string(f) + " " + tri_str(in.out_faces[f]) +
                                    ": no input face contains its centroid (cannot infer its parent)");
    return parent;
}
}  // namespace

// Each output face's input parent: the given array, checked, or inferred from the geometry.
std::vector<uint32_t> resolve_parents(const VerifyInput& in, const Adjacency& out, Failures& fails) {
    const size_t n = in.in_points.size();
    const size_t F = in.out_faces.size();
    if (!in.out_parent.empty()) {
        std::vector<uint32_t> parent = in.out_parent;
        if (parent.size() != F) {
            fails.add("parent", "parent array has " + std::to_string(parent.size()) + " entries for " + std::to_string(F) + " faces");
            parent.resize(F, kNo);
        }
        for (size_t f = 0; f < F; ++f)
            if (parent[f] != kNo && parent[f] >= in.in_faces.size()) {
                fails.add("parent", "face " + std::to_string(f) + ": parent " + std::to_string(parent[f]) + " out of range (" +
                                        std::to_string(in.in_faces.size()) + " input faces)");
                parent[f] = kNo;
            }
        return parent;
    }
    const InputStars stars = build_stars(n, in.in_faces);
    return infer_parents(in, out, stars, fails);
}

}  // namespace singlestrip::verify_detail
