// singlestrip — the independent verifier (see verify.hpp for the list of checks).
//
// Independence: this file has its own adjacency (hash maps keyed by vertex pairs), its own
// strip decoder and its own tree-cotree; it includes nothing from mesh.hpp, strip.hpp or
// encode.hpp. Geometry is in plain doubles with relative tolerances (kRelTol).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/verify.hpp"
#include "verify_attributes.hpp"

namespace singlestrip {
namespace {

constexpr uint32_t kNo = 0xffffffffu;
// Relative tolerance of every geometric test: 1e-9, or 1e-5 while verify() checks float32
// (glTF) positions. A thread-local set by verify() itself keeps the helpers' signatures.
thread_local double kRelTol = 1e-9;
// Float32 mode: positions carry rounding of about one float ulp of the coordinates, so every
// distance test also allows kFloatSlack times the largest coordinate involved.
thread_local double kFloatSlack = 0;

struct ToleranceScope {
    explicit ToleranceScope(bool float32) : saved(kRelTol), saved_slack(kFloatSlack) {
        kRelTol = float32 ? 1e-5 : 1e-9;
        kFloatSlack = float32 ? 4.0 / (1 << 23) : 0.0;
    }
    ~ToleranceScope() {
        kRelTol = saved;
        kFloatSlack = saved_slack;
    }
    ToleranceScope(const ToleranceScope&) = delete;
    ToleranceScope& operator=(const ToleranceScope&) = delete;
    double saved, saved_slack;
};
constexpr size_t kMaxPerCheck = 20;  // failure lines kept per check; the rest are counted

// --- tiny vector algebra: the verifier's own, independent of singlestrip/vec3.hpp by design ---
using V3 = std::array<double, 3>;
V3 sub(const V3& a, const V3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V3 crs(const V3& a, const V3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const V3& a, const V3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm(const V3& a) {
    return std::sqrt(dot(a, a));
}

uint64_t key(uint32_t a, uint32_t b) {
    return (static_cast<uint64_t>(a) << 32) | b;
}
uint64_t ukey(uint32_t a, uint32_t b) {
    return a < b ? key(a, b) : key(b, a);
}

std::string tri_str(const Triangle& t) {
    return "(" + std::to_string(t[0]) + "," + std::to_string(t[1]) + "," + std::to_string(t[2]) + ")";
}

/// Collects failure lines, at most kMaxPerCheck per check name.
class Failures {
public:
    explicit Failures(VerifyReport& r) : r_(r) {}
    void add(const std::string& check, const std::string& msg) {
        size_t& n = count_[check];
        if (++n <= kMaxPerCheck) r_.failures.push_back(check + ": " + msg);
    }
    size_t count(const std::string& check) const {
        auto it = count_.find(check);
        return it == count_.end() ? 0 : it->second;
    }
    void finish() {
        for (const auto& [check, n] : count_)
            if (n > kMaxPerCheck) r_.failures.push_back(check + ": " + std::to_string(n - kMaxPerCheck) + " more failures not shown");
    }

private:
    VerifyReport& r_;
    std::map<std::string, size_t> count_;
};

struct UnionFind {
    std::vector<uint32_t> p;
    explicit UnionFind(size_t n) : p(n) { std::iota(p.begin(), p.end(), 0u); }
    uint32_t find(uint32_t x) {
        while (p[x] != x) x = p[x] = p[p[x]];
        return x;
    }
    void unite(uint32_t a, uint32_t b) { p[find(a)] = find(b); }
};

/// Half-edge adjacency of a triangle list; half-edge h = 3f + i runs from faces[f][i] to
/// faces[f][(i+1)%3]. Outgoing half-edges are bucketed per vertex (counting sort, each bucket
/// sorted by target), so every lookup stays inside one vertex's small bucket: O(V + F) plus
/// O(d log d) per vertex of degree d. Tolerates garbage: problems are recorded, not thrown.
struct Adjacency {
    size_t num_points = 0;
    std::vector<Triangle> faces;
    std::vector<bool> face_ok;                 // indices in range and distinct
    std::vector<uint32_t> twin;                // kNo on the boundary (or when the edge is broken)
    std::vector<uint32_t> out_offset, out_he;  // CSR: outgoing half-edges of each vertex, by target
    bool manifold = true;                      // no repeated directed half-edge, every vertex one fan
    std::vector<std::string> problems;
    long long referenced_vertices = 0;
    long long edges = 0;
    long long euler = 0;
    size_t boundary_loops = 0;
    std::vector<bool> on_boundary;  // per vertex

    uint32_t from(uint32_t h) const { return faces[h / 3][h % 3]; }
    uint32_t to(uint32_t h) const { return faces[h / 3][(h % 3 + 1) % 3]; }
    /// First half-edge running a->b, or kNo.
    uint32_t find(uint32_t a, uint32_t b) const {
        if (a >= num_points) return kNo;
        auto first = out_he.begin() + out_offset[a], last = out_he.begin() + out_offset[a + 1];
        auto it = std::lower_bound(first, last, b, [&](uint32_t h, uint32_t v) { return to(h) < v; });
        return it != last && to(*it) == b ? *it : kNo;
    }
    bool has_edge(uint32_t a, uint32_t b) const { return find(a, b) != kNo || find(b, a) != kNo; }
    /// Records a problem (the first kMaxPerCheck are kept): the triangle list is not a manifold.
    void problem(const std::string& s) {
        manifold = false;
        if (problems.size() < kMaxPerCheck) problems.push_back(s);
    }
};

bool same_vertex_set(const Triangle& a, const Triangle& b) {
    Triangle x = a, y = b;
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    return x == y;
}

// Faces with an index out of range or a repeated vertex are not ok.
void check_faces(Adjacency& a, const std::string& what) {
    const size_t F = a.faces.size();
    const size_t num_points = a.num_points;
    const std::vector<Triangle>& faces = a.faces;
    a.face_ok.assign(F, true);
    for (size_t f = 0; f < F; ++f) {
        const Triangle& t = faces[f];
        bool ok = t[0] < num_points && t[1] < num_points && t[2] < num_points;
        if (!ok) {
            a.problem(what + " face " + std::to_string(f) + " " + tri_str(t) + ": vertex index out of range (" +
                      std::to_string(num_points) + " vertices)");
        } else if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            a.problem(what + " face " + std::to_string(f) + " " + tri_str(t) + ": repeated vertex");
            ok = false;
        }
        a.face_ok[f] = ok;
    }
}

// Outgoing half-edges per vertex, each bucket ordered by (target, id): a stable counting sort
// by target, then one by source (linear; a comparison sort per bucket was verify's largest cost).
void bucket_outgoing(Adjacency& a) {
    const size_t F = a.faces.size();
    const size_t num_points = a.num_points;
    const std::vector<Triangle>& faces = a.faces;
    std::vector<uint32_t> by_to;
    {
        std::vector<uint32_t> count(num_points + 1, 0);
        for (uint32_t f = 0; f < F; ++f)
            if (a.face_ok[f])
                for (uint32_t v : faces[f]) ++count[v + 1];
        for (size_t v = 0; v < num_points; ++v) count[v + 1] += count[v];
        by_to.resize(count[num_points]);
        for (uint32_t f = 0; f < F; ++f)
            if (a.face_ok[f])
                for (uint32_t i = 0; i < 3; ++i) by_to[count[faces[f][(i + 1) % 3]]++] = 3 * f + i;
    }
    a.out_offset.assign(num_points + 1, 0);
    for (uint32_t h : by_to) ++a.out_offset[a.from(h) + 1];
    for (size_t v = 0; v < num_points; ++v) a.out_offset[v + 1] += a.out_offset[v];
    a.out_he.resize(a.out_offset[num_points]);
    {
        std::vector<uint32_t> fill(a.out_offset.begin(), a.out_offset.end() - 1);
        for (uint32_t h : by_to) a.out_he[fill[a.from(h)]++] = h;
    }
}

// Twins between the first half-edges of each (from, to) group; repeated directed half-edges and
// duplicate faces are problems.
void pair_twins(Adjacency& a, const std::string& what) {
    const size_t F = a.faces.size();
    const size_t num_points = a.num_points;
    const std::vector<Triangle>& faces = a.faces;
    a.twin.assign(3 * F, kNo);
    std::vector<bool> canonical(3 * F, false);  // first half-edge of its (from,to) group
    for (size_t v = 0; v < num_points; ++v) {
        auto first = a.out_he.begin() + a.out_offset[v], last = a.out_he.begin() + a.out_offset[v + 1];
        for (auto it = first; it != last; ++it) {
            if (it != first && a.to(*it) == a.to(*(it - 1))) {
                const uint32_t h = *it, g = *(it - 1);
                if (same_vertex_set(faces[h / 3], faces[g / 3]))
                    a.problem(what + " faces " + std::to_string(g / 3) + " and " + std::to_string(h / 3) + " are the same triangle " +
                              tri_str(faces[h / 3]) + " (duplicate face)");
                else
                    a.problem(what + " edge (" + std::to_string(a.from(h)) + "," + std::to_string(a.to(h)) +
                              ") is traversed in the same direction by faces " + std::to_string(g / 3) + " and " + std::to_string(h / 3) +
                              " (flipped face, or more than two faces on an edge)");
            } else {
                canonical[*it] = true;
            }
        }
    }
    // Twins between canonical half-edges (find() returns the canonical one: symmetric).
    for (uint32_t h = 0; h < 3 * F; ++h) {
        if (!canonical[h]) continue;
        const uint32_t t = a.find(a.to(h), a.from(h));
        if (t != kNo) a.twin[h] = t;
    }
    // A duplicate with the opposite orientation: all three edges glued to one face.
    for (uint32_t f = 0; f < F; ++f) {
        const uint32_t t0 = a.twin[3 * f], t1 = a.twin[3 * f + 1], t2 = a.twin[3 * f + 2];
        if (t0 != kNo && t1 != kNo && t2 != kNo && t0 / 3 == t1 / 3 && t1 / 3 == t2 / 3 && f < t0 / 3)
            a.problem(what + " faces " + std::to_string(f) + " and " + std::to_string(t0 / 3) + " are the same triangle " +
                      tri_str(faces[f]) + " with opposite orientations (duplicate face)");
    }
}

// Referenced vertices, edges, boundary vertices and the Euler characteristic. Returns the first
// corner seen at each vertex (kNo for an unreferenced one).
std::vector<uint32_t> count_elements(Adjacency& a) {
    const size_t F = a.faces.size();
    const size_t num_points = a.num_points;
    std::vector<uint32_t> first_corner(num_points, kNo);
    a.on_boundary.assign(num_points, false);
    for (uint32_t f = 0; f < F; ++f) {
        if (!a.face_ok[f]) continue;
        for (uint32_t i = 0; i < 3; ++i) {
            const uint32_t h = 3 * f + i;
            if (first_corner[a.from(h)] == kNo) {
                first_corner[a.from(h)] = h;
                ++a.referenced_vertices;
            }
            if (a.twin[h] == kNo) {
                ++a.edges;
                a.on_boundary[a.from(h)] = true;
                a.on_boundary[a.to(h)] = true;
            } else if (h < a.twin[h]) {
                ++a.edges;
            }
        }
    }
    long long valid_faces = 0;
    for (bool ok : a.face_ok) valid_faces += ok ? 1 : 0;
    a.euler = a.referenced_vertices - a.edges + valid_faces;
    return first_corner;
}

// Vertex manifoldness: corners around a vertex joined across shared edges must form one fan.
void check_fans(Adjacency& a, const std::vector<uint32_t>& first_corner, const std::string& what) {
    const size_t F = a.faces.size();
    UnionFind uf(3 * F);
    for (uint32_t f = 0; f < F; ++f) {
        if (!a.face_ok[f]) continue;
        for (uint32_t i = 0; i < 3; ++i) {
            const uint32_t h = 3 * f + i;  // corner at from(h), outgoing half-edge h
            const uint32_t t = a.twin[h];
            if (t != kNo) {
                // twin runs to(h)->from(h); its face's corner at from(h) is corner of next(t).
                const uint32_t tn = 3 * (t / 3) + (t % 3 + 1) % 3;
                uf.unite(h, tn);
            }
        }
    }
    for (uint32_t f = 0; f < F; ++f) {
        if (!a.face_ok[f]) continue;
        for (uint32_t i = 0; i < 3; ++i) {
            const uint32_t h = 3 * f + i;
            const uint32_t v = a.from(h);
            if (uf.find(h) != uf.find(first_corner[v])) {
                a.problem(what + " vertex " + std::to_string(v) + " is non-manifold (its faces form more than one fan; seen at face " +
                          std::to_string(f) + ")");
                // Merge so that each extra fan is reported once.
                uf.unite(h, first_corner[v]);
            }
        }
    }
}

// Boundary loops: components of the boundary-edge graph.
void count_boundary_loops(Adjacency& a) {
    const size_t F = a.faces.size();
    const size_t num_points = a.num_points;
    UnionFind uf(num_points);
    for (uint32_t h = 0; h < 3 * F; ++h)
        if (a.face_ok[h / 3] && a.twin[h] == kNo) uf.unite(a.from(h), a.to(h));
    for (uint32_t v = 0; v < num_points; ++v)
        if (a.on_boundary[v] && uf.find(v) == v) ++a.boundary_loops;
}

Adjacency build_adjacency(size_t num_points, const std::vector<Triangle>& faces, const std::string& what) {
    Adjacency a;
    a.num_points = num_points;
    a.faces = faces;
    check_faces(a, what);
    bucket_outgoing(a);
    pair_twins(a, what);
    const std::vector<uint32_t> first_corner = count_elements(a);
    check_fans(a, first_corner, what);
    count_boundary_loops(a);
    return a;
}

// --- geometry --------------------------------------------------------------------------------

/// The power of two that brings `big` (a largest absolute coordinate) to [0.5, 1): multiplying
/// by it is exact. Capped at 2^1000 so that it stays finite for subnormal coordinates.
double unit_scale(double big) {
    if (!(big > 0) || !std::isfinite(big)) return 1;
    int e = 0;
    (void)std::frexp(big, &e);
    return std::ldexp(1.0, -std::max(e, -1000));
}

/// An input face in local coordinates: world coordinates times `scale`, a power of two that
/// brings its largest coordinate to [0.5, 1) (exact; squares and cross products of huge or tiny
/// coordinates neither overflow nor underflow). Points tested against it go through local().
struct ParentFrame {
    double scale = 1;
    V3 local(const V3& q) const { return {q[0] * scale, q[1] * scale, q[2] * scale}; }
    V3 a, b, c, n;    // corners and unnormalised normal (b-a)x(c-a)
    double n2 = 0;    // |n|^2
    double size = 0;  // longest edge
    V3 u, v;          // endpoints of a longest edge
    /// Absolute tolerance for twice an area in this face: relative to size^2, plus the rounding
    /// of coordinate differences far from the origin.
    double area_tol = 0;
    /// Nearly degenerate (a sliver, a needle or a point): |n| <= 1e-6 size^2. Barycentric
    /// coordinates divide by |n|^2 and lose about log10(size^2/|n|) digits, and the normal's
    /// direction is noise, so such parents get the robust tests of sliver_contains() instead.
    bool ill = false;
    double slack = 0;  ///< float32 mode: absolute rounding allowance in these units
};

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
    p.slack = kFloatSlack * m;
    p.area_tol = kRelTol * p.size * p.size + 64 * std::numeric_limits<double>::epsilon() * m * p.size + 8 * p.slack * p.size;
    p.ill = !(std::sqrt(p.n2) > 1e-6 * p.size * p.size);
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
    return t >= -kRelTol && t <= 1 + kRelTol && norm(sub(q, foot)) <= height + tol;
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

/// q on the closed segment u-v (within tolerance relative to its length).
bool on_segment(const V3& wu, const V3& wv, const V3& wq, double* t_out = nullptr) {
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

uint32_t common_vertices(const Triangle& a, const Triangle& b, std::array<uint32_t, 3>& out) {
    uint32_t n = 0;
    for (uint32_t x : a)
        if (x == b[0] || x == b[1] || x == b[2]) out[n++] = x;
    return n;
}

bool same_cyclic(const Triangle& a, const Triangle& b) {
    for (int r = 0; r < 3; ++r)
        if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3]) return true;
    return false;
}

// --- parent inference -------------------------------------------------------------------------

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

/// Best input face among candidates for point q: the one with the largest minimum barycentric
/// coordinate among those whose plane passes within tolerance. kNo when none contains q.
uint32_t best_container(const std::vector<Point3>& in_pts, const std::vector<Triangle>& in_faces, const std::vector<uint32_t>& cand,
                        const V3& q) {
    uint32_t best = kNo;
    double best_min = -std::numeric_limits<double>::infinity();
    for (uint32_t f : cand) {
        const ParentFrame p = frame_of(in_pts, in_faces[f]);
        if (p.ill) {
            // No reliable barycentrics: a robust containment test, ranked below every
            // well-conditioned face that contains q.
            if (sliver_contains(p, q) && best == kNo) best = f;
            continue;
        }
        double dist = 0;
        const auto l = bary(p, q, dist);
        if (!(dist <= kRelTol * p.size)) continue;
        const double m = std::min({l[0], l[1], l[2]});
        if (m >= -kRelTol && m > best_min) {
            best_min = m;
            best = f;
        }
    }
    return best;
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

// --- GL strip decoding (own implementation) -------------------------------------------------

// Pieces between restart values are separate strips, each starting at even parity.
std::vector<Triangle> gl_decode(const std::vector<uint32_t>& s, uint32_t restart) {
    std::vector<Triangle> out;
    size_t piece = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == restart) {
            piece = i + 1;
            continue;
        }
        if (i < piece + 2 || s[i - 1] == restart || s[i - 2] == restart) continue;
        const uint32_t a = s[i - 2], b = s[i - 1], c = s[i];
        if (a == b || b == c || a == c) continue;
        out.push_back(((i - 2 - piece) % 2 == 0) ? Triangle{a, b, c} : Triangle{b, a, c});
    }
    return out;
}

/// Edge-connected component of every output face (through manifold twins), numbered in order of
/// first appearance; `count` gets their number.
std::vector<uint32_t> out_components(const Adjacency& out, size_t& count) {
    const size_t F = out.faces.size();
    std::vector<uint32_t> comp(F, kNo);
    count = 0;
    std::vector<uint32_t> stack;
    for (uint32_t s = 0; s < F; ++s) {
        if (comp[s] != kNo) continue;
        comp[s] = static_cast<uint32_t>(count);
        stack.assign(1, s);
        while (!stack.empty()) {
            const uint32_t f = stack.back();
            stack.pop_back();
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t t = out.twin[3 * f + k];
                if (t != kNo && comp[t / 3] == kNo) {
                    comp[t / 3] = static_cast<uint32_t>(count);
                    stack.push_back(t / 3);
                }
            }
        }
        ++count;
    }
    return comp;
}

// --- cycles -----------------------------------------------------------------------------------

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

std::string VerifyReport::to_string() const {
    std::ostringstream os;
    if (ok()) {
        os << "OK: " << output_faces << " output faces (" << input_faces << " input), Euler characteristic " << euler_characteristic << ", "
           << boundary_loops << " boundary loop(s), genus " << genus;
        if (strips > 1) os << ", " << strips << " strips (one per component)";
        if (cycles_checked) os << ", " << cycles_checked << " independent cycles";
        os << "\n";
    } else {
        os << "FAILED: " << failures.size() << " problem line(s)\n";
        for (const auto& f : failures) os << "  " << f << "\n";
    }
    for (const auto& n : notes) os << "  note: " << n << "\n";
    return os.str();
}

std::vector<Triangle> verify_decode_strip(const std::vector<uint32_t>& indices, uint32_t restart_index) {
    return gl_decode(indices, restart_index);
}

namespace {

/// What the checks of the output read: the request, both adjacencies, each output face's
/// parent (kNo when unknown), and where failures and findings go.
struct Checked {
    const VerifyInput& in;
    const Adjacency& inp;
    const Adjacency& out;
    std::vector<uint32_t> parent;
    Failures& fails;
    VerifyReport& report;
    [[nodiscard]] size_t num_faces() const { return in.out_faces.size(); }
    [[nodiscard]] bool all_faces_ok() const {
        return std::all_of(out.face_ok.begin(), out.face_ok.end(), [](bool b) { return b; });
    }
};

// Input vertices unchanged (as a float32 file holds them), every coordinate finite.
void check_vertices(const VerifyInput& in, Failures& fails, VerifyReport& report) {
    const size_t n = in.in_points.size();
    if (in.out_points.size() < n) {
        fails.add("vertices",
                  "output has " + std::to_string(in.out_points.size()) + " vertices, fewer than the input's " + std::to_string(n));
    }
    auto as_stored = [&](const Point3& p) {  // what a float32 file can hold of an input vertex
        return in.float32 ? Point3{static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])} : p;
    };
    if (in.float32)
        report.notes.push_back(
            "float32 positions (glTF): input vertices compared after rounding to float32; geometric tolerances "
            "1e-5 relative (instead of 1e-9) plus 4 float32 ulps of the coordinates; parents inferred");
    for (size_t v = 0; v < std::min(n, in.out_points.size()); ++v)
        if (!(in.out_points[v] == as_stored(in.in_points[v])))
            fails.add("vertices", "vertex " + std::to_string(v) + " moved (input vertices must be unchanged)");
    for (size_t v = 0; v < in.out_points.size(); ++v)
        for (double c : in.out_points[v])
            if (!std::isfinite(c)) {
                fails.add("vertices", "vertex " + std::to_string(v) + " has a non-finite coordinate");
                break;
            }
}

// The output's Euler characteristic and boundary loops are the input's.
void check_topology(const Adjacency& inp, const Adjacency& out, Failures& fails, VerifyReport& report) {
    for (const auto& p : out.problems) fails.add("manifold", p);
    report.output_vertices = static_cast<size_t>(out.referenced_vertices);
    report.euler_characteristic = out.euler;
    report.boundary_loops = out.boundary_loops;
    if (out.euler != inp.euler)
        fails.add("topology",
                  "Euler characteristic " + std::to_string(out.euler) + " differs from the input's " + std::to_string(inp.euler));
    if (out.boundary_loops != inp.boundary_loops)
        fails.add("topology",
                  std::to_string(out.boundary_loops) + " boundary loop(s), the input has " + std::to_string(inp.boundary_loops));
}

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
    size_t degenerate_parents_checked = 0;
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
            if (!(dist <= kRelTol * P.size + P.slack)) in_plane = false;
            // A barycentric l_i below 0 is a distance -l_i * |n| / |edge_i| outside edge i.
            const double l_slack = P.slack > 0 ? P.slack * P.size / std::sqrt(P.n2) : 0.0;
            if (!(std::min({l[0], l[1], l[2]}) >= -kRelTol - l_slack)) inside = false;
        }
        if (!in_plane)
            fails.add("geometry", who + ": not in its parent's plane");
        else if (!inside)
            fails.add("geometry", who + ": not inside its parent");
        const V3 nf = crs(sub(b, a), sub(c, a));
        const double nP = std::sqrt(P.n2);
        const double projected = nP > 0 ? dot(nf, P.n) / nP : 0.0;  // twice the signed area in the parent's plane
        if (!(norm(nf) > 1e-15 * nP))
            fails.add("geometry", who + ": degenerate (zero area)");
        else if (!(projected > 0))
            fails.add("orientation", who + ": orientation opposite to its parent's (flipped)");
        child_area[parent[f]] += 0.5 * projected;
    }
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
                                          std::to_string(child_area[p] / (P.scale * P.scale)) + ", parent's area is " +
                                          std::to_string(area / (P.scale * P.scale)));
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

// One strip per edge-connected component of the output, each a contiguous run of faces in which
// consecutive faces share an edge; a new strip starts exactly where the component changes.
// Returns the last face of each strip; `num_components` receives the output's components.
std::vector<uint32_t> check_strips(const Checked& chk, size_t& num_components) {
    const VerifyInput& in = chk.in;
    const Adjacency& out = chk.out;
    Failures& fails = chk.fails;
    VerifyReport& report = chk.report;
    const size_t F = chk.num_faces();
    // in which consecutive faces share an edge; a new strip starts exactly where the component changes.
    const std::vector<uint32_t> comp = out_components(out, num_components);
    std::vector<uint32_t> strip_end;  // last face of each strip
    {
        std::vector<bool> seen(num_components, false);
        seen[comp[0]] = true;
        for (uint32_t f = 0; f + 1 < F; ++f) {
            if (comp[f + 1] != comp[f]) {
                strip_end.push_back(f);
                if (seen[comp[f + 1]])
                    fails.add("strip", "face " + std::to_string(f + 1) +
                                           " returns to an edge-connected component already stripped "
                                           "(each component must be one contiguous strip)");
                seen[comp[f + 1]] = true;
                continue;
            }
            if (!out.face_ok[f] || !out.face_ok[f + 1]) continue;
            std::array<uint32_t, 3> common{};
            const uint32_t k = common_vertices(in.out_faces[f], in.out_faces[f + 1], common);
            if (k != 2)
                fails.add("strip", "faces " + std::to_string(f) + " and " + std::to_string(f + 1) + " share " + std::to_string(k) +
                                       " vertices, not an edge");
        }
        strip_end.push_back(static_cast<uint32_t>(F - 1));
        report.strips = strip_end.size();
        report.genus = (2 * static_cast<long long>(num_components) - out.euler - static_cast<long long>(out.boundary_loops)) / 2;
    }
    return strip_end;
}

// The index sequence decodes to exactly the output's faces, in order, with their winding.
void check_indices(const Checked& chk) {
    const VerifyInput& in = chk.in;
    Failures& fails = chk.fails;
    const size_t F = chk.num_faces();
    if (in.indices) {
        const auto& s = *in.indices;
        bool range_ok = true;
        for (size_t i = 0; i < s.size(); ++i)
            if (s[i] >= in.out_points.size() && s[i] != in.restart_index) {
                fails.add("indices", "index " + std::to_string(i) + " = " + std::to_string(s[i]) + " out of range (" +
                                         std::to_string(in.out_points.size()) + " vertices)");
                range_ok = false;
            }
        if (range_ok) {
            const auto dec = gl_decode(s, in.restart_index);
            if (dec.size() != F)
                fails.add("indices",
                          "index sequence decodes to " + std::to_string(dec.size()) + " triangles, the output has " + std::to_string(F));
            for (size_t f = 0; f < std::min(dec.size(), F); ++f)
                if (!same_cyclic(dec[f], in.out_faces[f])) {
                    const bool flipped = same_cyclic({dec[f][1], dec[f][0], dec[f][2]}, in.out_faces[f]);
                    fails.add("indices", "decoded triangle " + std::to_string(f) + " " + tri_str(dec[f]) +
                                             (flipped ? " has the opposite winding of face " : " differs from face ") + std::to_string(f) +
                                             " " + tri_str(in.out_faces[f]));
                }
        }
    }
}

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
        // No output vertex strictly inside a constraint edge.
        for (uint32_t f = 0; f < F; ++f) {
            if (!out.face_ok[f] || parent[f] == kNo) continue;
            es.clear();
            constraint_edges_of(parent[f], es);
            for (const auto& [u, v] : es)
                for (uint32_t p : in.out_faces[f]) {
                    if (p == u || p == v) continue;
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
                if (on_segment(U, Vv, in.out_points[common[0]]) && on_segment(U, Vv, in.out_points[common[1]])) {
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

}  // namespace

VerifyReport verify(const VerifyInput& in) {
    const ToleranceScope tolerance(in.float32);
    VerifyReport report;
    Failures fails(report);
    report.input_faces = in.in_faces.size();
    report.output_faces = in.out_faces.size();

    // The input is the reference everything is compared with.
    const Adjacency inp = build_adjacency(in.in_points.size(), in.in_faces, "input");
    if (!inp.manifold || in.in_faces.empty()) {
        for (const auto& p : inp.problems) fails.add("input", p);
        if (in.in_faces.empty()) fails.add("input", "no faces");
        report.notes.push_back("input is not a valid manifold mesh; output not checked");
        fails.finish();
        return report;
    }
    check_vertices(in, fails, report);
    if (in.out_faces.empty()) {
        fails.add("faces", "output has no faces");
        fails.finish();
        return report;
    }
    const Adjacency out = build_adjacency(in.out_points.size(), in.out_faces, "output");
    check_topology(inp, out, fails, report);
    Checked chk{in, inp, out, resolve_parents(in, out, fails), fails, report};
    check_geometry(chk);
    std::vector<std::string> attribute_failures;
    verify_detail::check_attributes(in, chk.parent, attribute_failures, report.notes);
    for (const std::string& f : attribute_failures) fails.add("attributes", f);
    check_boundary_tiling(chk);
    size_t num_components = 0;
    const std::vector<uint32_t> strip_end = check_strips(chk, num_components);
    check_indices(chk);
    check_constraints(chk);
    check_source_target(chk, strip_end.front());
    check_cycles_request(chk, num_components);
    fails.finish();
    return report;
}

}  // namespace singlestrip
