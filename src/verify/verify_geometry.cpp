// singlestrip — the verifier's geometry: exact power-of-two scaling, parent frames, containment
// and segment tests, then the checks that every face lies inside its parent with its orientation
// (areas summing up) and that output boundary edges tile the input's (no T-junction).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "verify_checks.hpp"

namespace singlestrip::verify_detail {

namespace {

/// The power of two that brings `big` (a largest absolute coordinate) to [0.5, 1): multiplying
/// by it is exact. Capped at 2^1000 so that it stays finite for subnormal coordinates.
double unit_scale(double big) {
    if (!(big > 0) || !std::isfinite(big)) return 1;
    int e = 0;
    (void)std::frexp(big, &e);
    return std::ldexp(1.0, -std::max(e, -1000));
}

/// Position of q along segment u->v: t in [0,1] when inside; `dist` = distance from the line.
double seg_param(const V3& u, const V3& v, const V3& q, double& dist) {
    const V3 d = sub(v, u);
    const double dd = dot(d, d);
    if (!(dd > 0)) {
        dist = norm(sub(q, u));
        return 0;
    }
    const double t = dot(sub(q, u), d) / dd;
    const V3 foot = {u[0] + t * d[0], u[1] + t * d[1], u[2] + t * d[2]};
    dist = norm(sub(q, foot));
    return t;
}

/// Seven significant digits: the areas of needles far from the origin are far below 1e-6.
std::string short_num(double x) {
    std::ostringstream os;
    os << std::setprecision(7) << x;
    return os.str();
}

}  // namespace

ParentFrame frame_of(const std::vector<Point3>& pts, const Triangle& t) {
    ParentFrame p;
    double big = 0;
    for (uint32_t v : t)
        for (double x : pts[v]) big = std::max(big, std::abs(x));
    p.scale = unit_scale(big);
    p.a = p.local(pts[t[0]]);
    p.b = p.local(pts[t[1]]);
    p.c = p.local(pts[t[2]]);
    p.n = crs(sub(p.b, p.a), sub(p.c, p.a));
    p.n2 = dot(p.n, p.n);
    const double lab = norm(sub(p.b, p.a)), lbc = norm(sub(p.c, p.b)), lca = norm(sub(p.a, p.c));
    p.size = std::max({lab, lbc, lca});
    if (p.size == lab)
        p.u = p.a, p.v = p.b;
    else if (p.size == lbc)
        p.u = p.b, p.v = p.c;
    else
        p.u = p.c, p.v = p.a;
    double m = 0;
    for (const V3* q : {&p.a, &p.b, &p.c})
        for (double x : *q) m = std::max(m, std::abs(x));
    // float32 output: 4 ulps of the coordinates, and 4 steps of float32's subnormals near 0.
    p.slack = kFloatSlack * m + (kFloatSlack > 0 ? 4 * std::numeric_limits<float>::denorm_min() * p.scale : 0.0);
    p.round = 16 * std::numeric_limits<double>::epsilon() * m;
    p.area_tol = kRelTol * p.size * p.size + 64 * std::numeric_limits<double>::epsilon() * m * p.size + 8 * p.slack * p.size;
    // Also nearly degenerate at the coordinates' precision: a height (|n| / size) within 16
    // roundings of the largest coordinate (float32 output: a needle on a circle of 20,000
    // points is thinner than a float32 step there; its split children may round to either side).
    p.ill = !(std::sqrt(p.n2) > std::max(1e-6 * p.size, 16 * (p.slack + p.round)) * p.size);
    return p;
}
/// Containment test for a nearly degenerate parent that needs no division by its area: q lies
/// in the parent's bounding box and within the parent's height (|n| / size) of the line through
/// its longest edge, between that edge's ends (all with tolerance 1e-9 relative to the size,
/// plus rounding far from the origin).
bool sliver_contains(const ParentFrame& p, const V3& world_q) {
    const V3 q = p.local(world_q);
    const double tol = kRelTol * p.size + (p.size > 0 ? p.area_tol / p.size : 0.0) + 1e-300;
    for (size_t k = 0; k < 3; ++k) {
        const double lo = std::min({p.a[k], p.b[k], p.c[k]}), hi = std::max({p.a[k], p.b[k], p.c[k]});
        if (!(q[k] >= lo - tol && q[k] <= hi + tol)) return false;
    }
    const V3 d = sub(p.v, p.u);
    const double dd = dot(d, d);
    if (!(dd > 0)) return norm(sub(q, p.u)) <= tol;  // the parent is a point
    const double t = dot(sub(q, p.u), d) / dd;
    const V3 foot = {p.u[0] + t * d[0], p.u[1] + t * d[1], p.u[2] + t * d[2]};
    const double height = std::sqrt(p.n2) / p.size;
    const double t_tol = kRelTol + tol / std::sqrt(dd);  // the same distance along the edge
    return t >= -t_tol && t <= 1 + t_tol && norm(sub(q, foot)) <= height + tol;
}

double distance_to(const ParentFrame& p, const V3& world_q) {
    const V3 q = p.local(world_q);
    double d = std::numeric_limits<double>::infinity();
    for (const auto& [u, v] : {std::pair{p.a, p.b}, std::pair{p.b, p.c}, std::pair{p.c, p.a}}) {
        double line = 0;
        const double t = std::clamp(seg_param(u, v, q, line), 0.0, 1.0);
        d = std::min(d, norm(sub(q, {u[0] + t * (v[0] - u[0]), u[1] + t * (v[1] - u[1]), u[2] + t * (v[2] - u[2])})));
    }
    if (!(p.n2 > 0)) return d;
    const double la = dot(crs(sub(p.b, q), sub(p.c, q)), p.n), lb = dot(crs(sub(p.c, q), sub(p.a, q)), p.n);
    if (la >= 0 && lb >= 0 && la + lb <= p.n2) return std::min(d, std::abs(dot(sub(q, p.a), p.n)) / std::sqrt(p.n2));
    return d;
}

/// Barycentric coordinates of the projection of q onto the parent's plane, and the distance
/// of q from that plane.
std::array<double, 3> bary(const ParentFrame& p, const V3& world_q, double& plane_dist) {
    const V3 q = p.local(world_q);
    const double nn = std::sqrt(p.n2);
    plane_dist = nn > 0 ? std::abs(dot(sub(q, p.a), p.n)) / nn : std::numeric_limits<double>::infinity();
    if (!(p.n2 > 0)) return {-1, -1, -1};
    const double la = dot(crs(sub(p.b, q), sub(p.c, q)), p.n) / p.n2;
    const double lb = dot(crs(sub(p.c, q), sub(p.a, q)), p.n) / p.n2;
    return {la, lb, 1.0 - la - lb};
}
/// q on the closed segment u-v (within tolerance relative to its length).
bool on_segment(const V3& wu, const V3& wv, const V3& wq, double* t_out) {
    // In units where the segment's largest coordinate is in [0.5, 1): no overflow for huge
    // coordinates (an exact power-of-two scaling).
    double big = 0;
    for (const V3* p : {&wu, &wv})
        for (double x : *p) big = std::max(big, std::abs(x));
    const double scale = unit_scale(big);
    const V3 u = {wu[0] * scale, wu[1] * scale, wu[2] * scale}, v = {wv[0] * scale, wv[1] * scale, wv[2] * scale},
             q = {wq[0] * scale, wq[1] * scale, wq[2] * scale};
    double dist = 0;
    const double t = seg_param(u, v, q, dist);
    const double len = norm(sub(v, u));
    if (t_out) *t_out = t;
    const double slack =
        kFloatSlack * std::max({std::abs(u[0]), std::abs(u[1]), std::abs(u[2]), std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
    const double t_slack = len > 0 ? slack / len : 0.0;
    return dist <= kRelTol * len + slack && t >= -kRelTol - t_slack && t <= 1 + kRelTol + t_slack;
}

// Every face lies inside its parent, in its plane, with its orientation; children's areas add
// up to their parent's.
void check_geometry(Checked& chk) {
    const VerifyInput& in = chk.in;
    const Adjacency& out = chk.out;
    const std::vector<uint32_t>& parent = chk.parent;
    Failures& fails = chk.fails;
    VerifyReport& report = chk.report;
    const size_t F = chk.num_faces();
    const bool all_faces_ok = chk.all_faces_ok();
    std::vector<double> child_area(in.in_faces.size(), 0.0);
    size_t degenerate_parents_checked = 0, needles = 0;
    std::vector<uint32_t> child_count(in.in_faces.size(), 0);
    for (uint32_t f = 0; f < F; ++f) {
        if (!out.face_ok[f] || parent[f] == kNo) continue;
        ++report.faces_checked;
        const Triangle& t = in.out_faces[f];
        const ParentFrame P = frame_of(in.in_points, in.in_faces[parent[f]]);
        const std::string who = "face " + std::to_string(f) + " (parent " + std::to_string(parent[f]) + ")";
        ++child_count[parent[f]];
        const V3 wa = in.out_points[t[0]], wb = in.out_points[t[1]], wc = in.out_points[t[2]];
        const V3 a = P.local(wa), b = P.local(wb), c = P.local(wc);  // for areas, in the parent's units
        if (P.ill) {
            // A zero-area or nearly degenerate input face (real meshes and exporters make
            // them; they are valid input): its plane and barycentrics are noise. Its children
            // must stay within it (sliver_contains) and none may be larger than it; the area
            // sum below is then checked with unsigned areas. Orientation cannot be checked.
            ++degenerate_parents_checked;
            bool within = true;
            for (const V3& q : {wa, wb, wc}) within = within && sliver_contains(P, q);
            const double nd = norm(crs(sub(b, a), sub(c, a)));
            if (!within)
                fails.add("geometry", who + ": not within its (nearly) degenerate parent");
            else if (!(nd <= std::sqrt(P.n2) + P.area_tol))
                fails.add("geometry", who + ": larger than its (nearly) degenerate parent");
            child_area[parent[f]] += 0.5 * nd;
            continue;
        }
        bool in_plane = true, inside = true;
        for (const V3& p : {wa, wb, wc}) {
            double dist = 0;
            const auto l = bary(P, p, dist);
            if (!(dist <= P.plane_tol())) in_plane = false;
            if (!(std::min({l[0], l[1], l[2]}) >= -P.bary_tol())) inside = false;
        }
        if (!in_plane)
            fails.add("geometry", who + ": not in its parent's plane");
        else if (!inside)
            fails.add("geometry", who + ": not inside its parent");
        const V3 nf = crs(sub(b, a), sub(c, a));
        const double nP = std::sqrt(P.n2);
        const double projected = nP > 0 ? dot(nf, P.n) / nP : 0.0;                     // twice the signed area in the parent's plane
        const bool rounded_flat = P.slack > 0 && projected >= -P.orient_tol(a, b, c);  // float32 needle
        if (!(projected > 0) && rounded_flat)
            ++needles;
        else if (!(norm(nf) > 1e-15 * nP))
            fails.add("geometry", who + ": degenerate (zero area)");
        else if (!(projected > 0))
            fails.add("orientation", who + ": orientation opposite to its parent's (flipped)");
        child_area[parent[f]] += 0.5 * projected;
    }
    if (needles)
        report.notes.push_back(std::to_string(needles) +
                               " face(s) flat or flipped within float32 rounding (needles along a parent's edge): orientation not checked");
    if (degenerate_parents_checked)
        report.notes.push_back(
            std::to_string(degenerate_parents_checked) +
            " face(s) lie in zero-area or nearly degenerate input faces: checked to stay within them, orientation not checked");
    if (all_faces_ok && std::all_of(parent.begin(), parent.end(), [](uint32_t p) { return p != kNo; })) {
        for (uint32_t p = 0; p < in.in_faces.size(); ++p) {
            const ParentFrame P = frame_of(in.in_points, in.in_faces[p]);
            const double area = 0.5 * std::sqrt(P.n2);
            if (child_count[p] == 0) {
                fails.add("coverage", "input face " + std::to_string(p) + " has no child in the output");
                continue;
            }
            if (!(std::abs(child_area[p] - area) <= kRelTol * area + 0.5 * P.area_tol))
                fails.add("coverage", "input face " + std::to_string(p) + ": children's areas sum to " +
                                          short_num(child_area[p] / (P.scale * P.scale)) + ", parent's area is " +
                                          short_num(area / (P.scale * P.scale)));
        }
    } else {
        report.notes.push_back("area sums not checked (some faces invalid or without parent)");
    }
}

// T-junctions: output boundary edges must tile the input boundary edges exactly. Runs even when
// the output is not vertex-manifold: a T-junction leaves a crack that makes its corner vertices
// non-manifold, and this check names the cause.
void check_boundary_tiling(const Checked& chk) {
    const VerifyInput& in = chk.in;
    const Adjacency& inp = chk.inp;
    const Adjacency& out = chk.out;
    const std::vector<uint32_t>& parent = chk.parent;
    Failures& fails = chk.fails;
    const size_t F = chk.num_faces();
    // Runs even when the output is not vertex-manifold: a T-junction leaves a crack that makes
    // its corner vertices non-manifold, and this check names the cause.
    {
        struct Piece {
            uint32_t input_he;
            double t;
            uint32_t a, b, face;
        };
        std::vector<Piece> pieces;
        for (uint32_t h = 0; h < 3 * F; ++h) {
            const uint32_t f = h / 3;
            if (!out.face_ok[f] || parent[f] == kNo || out.twin[h] != kNo) continue;
            const uint32_t a = out.from(h), b = out.to(h);
            const uint32_t P = parent[f];
            uint32_t found = kNo;
            double ta = 0;
            // Candidates ranked: the input edge itself (same vertex ids), then an edge sharing
            // an end vertex with it, then any edge it lies on. Needed for zero-length input
            // edges, on which every point has the same position (and the parameter t is 0).
            int found_rank = 3;
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t ih = 3 * P + k;
                if (inp.twin[ih] != kNo) continue;
                const uint32_t iu = inp.from(ih), iv = inp.to(ih);
                const V3 u = in.in_points[iu], v = in.in_points[iv];
                double sa = 0, sb = 0;
                if (!on_segment(u, v, in.out_points[a], &sa) || !on_segment(u, v, in.out_points[b], &sb)) continue;
                const bool zero_length = u == v;
                if (!(sa < sb) && !zero_length && !(a == iu && b == iv)) continue;
                const int rank = a == iu && b == iv ? 0 : (a == iu || b == iv) ? 1 : 2;
                if (rank < found_rank) {
                    found_rank = rank;
                    found = ih;
                    ta = zero_length ? (a == iu ? 0.0 : b == iv ? 1.0 : 0.5) : sa;
                }
            }
            if (found == kNo) {
                fails.add("conformity", "edge (" + std::to_string(a) + "," + std::to_string(b) + ") of face " + std::to_string(f) +
                                            " has only one face but is not on the input's boundary (T-junction or hole)");
                continue;
            }
            pieces.push_back({found, ta, a, b, f});
        }
        std::sort(pieces.begin(), pieces.end(),
                  [](const Piece& x, const Piece& y) { return x.input_he != y.input_he ? x.input_he < y.input_he : x.t < y.t; });
        std::vector<bool> covered(3 * in.in_faces.size(), false);
        for (size_t i = 0; i < pieces.size();) {
            size_t j = i;
            const uint32_t ih = pieces[i].input_he;
            while (j < pieces.size() && pieces[j].input_he == ih) ++j;
            covered[ih] = true;
            bool ok = pieces[i].a == inp.from(ih) && pieces[j - 1].b == inp.to(ih);
            for (size_t k = i; k + 1 < j; ++k) ok = ok && pieces[k].b == pieces[k + 1].a;
            if (!ok) {
                // Positions along the edge do not order the pieces when they coincide (a
                // zero-length edge, or rounding): the pieces must still chain by vertex ids
                // from one end of the edge to the other, each used once.
                std::sort(pieces.begin() + static_cast<std::ptrdiff_t>(i), pieces.begin() + static_cast<std::ptrdiff_t>(j),
                          [](const Piece& x, const Piece& y) { return x.a < y.a; });
                std::vector<bool> used(j - i, false);
                uint32_t cur = inp.from(ih);
                size_t steps = 0;
                for (; steps < j - i; ++steps) {
                    auto it =
                        std::lower_bound(pieces.begin() + static_cast<std::ptrdiff_t>(i), pieces.begin() + static_cast<std::ptrdiff_t>(j),
                                         cur, [](const Piece& x, uint32_t v) { return x.a < v; });
                    while (it != pieces.begin() + static_cast<std::ptrdiff_t>(j) && it->a == cur &&
                           used[static_cast<size_t>(it - pieces.begin()) - i])
                        ++it;
                    if (it == pieces.begin() + static_cast<std::ptrdiff_t>(j) || it->a != cur) break;
                    used[static_cast<size_t>(it - pieces.begin()) - i] = true;
                    cur = it->b;
                }
                ok = steps == j - i && cur == inp.to(ih);
            }
            if (!ok)
                fails.add("conformity", "input boundary edge (" + std::to_string(inp.from(ih)) + "," + std::to_string(inp.to(ih)) +
                                            ") is not tiled exactly by output boundary edges (T-junction, gap or overlap; near face " +
                                            std::to_string(pieces[i].face) + ")");
            i = j;
        }
        for (uint32_t ih = 0; ih < 3 * in.in_faces.size(); ++ih)
            if (inp.twin[ih] == kNo && !covered[ih])
                fails.add("conformity", "input boundary edge (" + std::to_string(inp.from(ih)) + "," + std::to_string(inp.to(ih)) +
                                            ") is not covered by output boundary edges");
    }
}

}  // namespace singlestrip::verify_detail
