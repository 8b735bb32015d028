// singlestrip — each output face's input parent for the verifier: the given parent array,
// range-checked, or inferred from the geometry (the input face containing the face's centroid).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "verify_checks.hpp"

namespace singlestrip::verify_detail {

namespace {

/// A face's three corners, then its centroid.
using Corners = std::array<V3, 4>;

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

/// Best input face among candidates for a face (its corners, then its centroid q), in four
/// tiers: a well-conditioned face that contains q within kRelTol and in which the face keeps its
/// orientation (the largest minimum barycentric coordinate wins), else a nearly degenerate one
/// that contains q (the one nearest to all corners), else a well-conditioned one within the
/// rounding allowance of ParentFrame::bary_tol (thin faces far from the origin), else one in
/// which the face is flipped beyond rounding. The orientation ranks a needle lying along an edge between a
/// well-conditioned face and the sliver across (float32: both hold it within tolerance) into
/// the sliver, where it is. kNo when none contains q.
uint32_t best_container(const std::vector<Point3>& in_pts, const std::vector<Triangle>& in_faces, const std::vector<uint32_t>& cand,
                        const Corners& corners) {
    const V3& q = corners[3];
    uint32_t best = kNo, sliver = kNo, loose = kNo, flipped = kNo;
    double best_min = -std::numeric_limits<double>::infinity(), loose_min = best_min;
    double sliver_far = std::numeric_limits<double>::infinity();
    int sliver_held = -1;
    for (uint32_t f : cand) {
        const ParentFrame p = frame_of(in_pts, in_faces[f]);
        if (p.ill) {  // no reliable barycentrics: a robust containment test
            if (!sliver_contains(p, q)) continue;
            // Neighbouring needles (a polygon's ears in float32) may all hold the centroid:
            // the one that holds the most corners, then the nearest to all of them.
            int held = 0;
            double far = 0;
            for (const V3& k : corners) {
                held += sliver_contains(p, k) ? 1 : 0;
                far = std::max(far, distance_to(p, k) / p.scale);
            }
            if (held > sliver_held || (held == sliver_held && far < sliver_far)) sliver = f, sliver_held = held, sliver_far = far;
            continue;
        }
        double dist = 0;
        const auto l = bary(p, q, dist);
        if (!(dist <= p.plane_tol())) continue;
        const double m = std::min({l[0], l[1], l[2]});
        const V3 a = p.local(corners[0]), b = p.local(corners[1]), c = p.local(corners[2]);
        const double area2 = dot(crs(sub(b, a), sub(c, a)), p.n) / std::sqrt(p.n2);  // twice the signed area in p's plane
        if (!(area2 >= -p.orient_tol(a, b, c))) {
            if (m >= -p.bary_tol() && flipped == kNo) flipped = f;
        } else if (dist <= kRelTol * p.size && m >= -kRelTol && m > best_min) {
            best_min = m;
            best = f;
        } else if (m >= -p.bary_tol() && m > loose_min) {
            loose_min = m;
            loose = f;
        }
    }
    return best != kNo ? best : sliver != kNo ? sliver : loose != kNo ? loose : flipped;
}

/// Parents without a parent array (glTF): combinatorics first, geometry where it cannot decide.
/// Float32 needles make geometry ambiguous (a polygon's ear thinner than a float32 step lies
/// within the tolerance of its neighbours), so a face with three input vertices is its own parent
/// when it is an input face, and a face with two lies in the one input face holding the directed
/// edge between them (a child keeps its parent's orientation; the face across holds the edge
/// reversed). Faces with one input vertex: the best container in its star. Faces with none:
/// breadth-first from the others, an output neighbour's parent first.
std::vector<uint32_t> infer_parents(const VerifyInput& in, const Adjacency& out, Failures& fails) {
    const size_t n = in.in_points.size();
    const size_t F = in.out_faces.size();
    std::vector<uint32_t> parent(F, kNo);
    std::vector<uint32_t> queue;
    std::vector<uint32_t> cand;
    auto corners = [&](uint32_t f) {
        const Triangle& t = in.out_faces[f];
        Corners c{};
        for (size_t i = 0; i < 3; ++i)
            for (size_t k = 0; k < 3; ++k) {
                c[i][k] = in.out_points[t[i]][k];
                c[3][k] += c[i][k] / 3.0;
            }
        return c;
    };
    std::optional<InputStars> stars;
    auto add_star = [&](uint32_t v) {
        if (!stars) stars = build_stars(n, in.in_faces);  // only for what the split structure leaves
        for (uint32_t i = stars->offset[v]; i < stars->offset[v + 1]; ++i) cand.push_back(stars->faces[i]);
    };
    auto add_input_stars = [&](uint32_t f) {
        for (uint32_t v : in.out_faces[f])
            if (v < n) add_star(v);
    };
    auto inputs = [&](uint32_t f) {
        return static_cast<int>(std::count_if(in.out_faces[f].begin(), in.out_faces[f].end(), [&](uint32_t v) { return v < n; }));
    };
    auto assign = [&](uint32_t f, uint32_t p) {
        if (p == kNo) return;
        parent[f] = p;
        queue.push_back(f);
    };
    auto container = [&](uint32_t f) { return best_container(in.in_points, in.in_faces, cand, corners(f)); };
    const std::vector<uint32_t> from_splits = parents_from_splits(in);
    for (uint32_t f = 0; f < F; ++f) {
        if (!out.face_ok[f]) continue;
        if (from_splits[f] != kNo) {
            assign(f, from_splits[f]);
        } else if (inputs(f) > 0) {  // the split structure not found: geometry in the stars
            cand.clear();
            add_input_stars(f);
            assign(f, container(f));
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
            cand.assign(1, parent[f]);
            uint32_t p = container(g);
            if (p == kNo) {
                cand.clear();
                for (uint32_t v : in.in_faces[parent[f]]) add_star(v);
                p = container(g);
            }
            assign(g, p);
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
    return infer_parents(in, out, fails);
}

}  // namespace singlestrip::verify_detail
