// singlestrip — internal to the verifier: what the check families of verify() share. Files:
//   verify.cpp             verify() in order, the report, vertices and topology;
//   verify_adjacency.cpp   the verifier's own half-edge adjacency (manifoldness, Euler, loops);
//   verify_geometry.cpp    geometry primitives, faces inside their parents, boundary tiling;
//   verify_parents.cpp     each output face's parent: given and checked, or inferred;
//   verify_carriers.cpp    inferred parents from the split structure (no tolerance);
//   verify_strips.cpp      the GL decoder, one strip per component, the index sequence;
//   verify_constraints.cpp constraint edges, source and target;
//   verify_cycles.cpp      the fundamental cycles: count, closed chains, independence in H1.
// Independence: nothing here comes from mesh.hpp, strip.hpp or encode.hpp; geometry is in plain
// doubles with relative tolerances (kRelTol).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "singlestrip/verify.hpp"

namespace singlestrip::verify_detail {

constexpr uint32_t kNo = 0xffffffffu;
// Relative tolerance of every geometric test: 1e-9, or 1e-5 while verify() checks float32
// (glTF) positions. A thread-local set by verify() itself keeps the helpers' signatures.
extern thread_local double kRelTol;
// Float32 mode: positions carry rounding of about one float ulp of the coordinates, so every
// distance test also allows kFloatSlack times the largest coordinate involved.
extern thread_local double kFloatSlack;
constexpr size_t kMaxPerCheck = 20;  // failure lines kept per check; the rest are counted
// --- tiny vector algebra: the verifier's own, independent of singlestrip/vec3.hpp by design ---
using V3 = std::array<double, 3>;
inline V3 sub(const V3& a, const V3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline V3 crs(const V3& a, const V3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dot(const V3& a, const V3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline double norm(const V3& a) {
    return std::sqrt(dot(a, a));
}

inline uint64_t key(uint32_t a, uint32_t b) {
    return (static_cast<uint64_t>(a) << 32) | b;
}
inline uint64_t ukey(uint32_t a, uint32_t b) {
    return a < b ? key(a, b) : key(b, a);
}

inline std::string tri_str(const Triangle& t) {
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

/// The adjacency of `faces` over `num_points` vertices; `what` ("input", "output") prefixes its
/// problems.
Adjacency build_adjacency(size_t num_points, const std::vector<Triangle>& faces, const std::string& what);

// --- geometry (verify_geometry.cpp) ----------------------------------------------------------

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
    /// Nearly degenerate (a sliver, a needle or a point): |n| <= 1e-6 size^2, or a height within
    /// 16 (slack + round) at the coordinates' precision. Barycentric
    /// coordinates divide by |n|^2 and lose about log10(size^2/|n|) digits, and the normal's
    /// direction is noise, so such parents get the robust tests of sliver_contains() instead.
    bool ill = false;
    double slack = 0;  ///< float32 mode: absolute rounding allowance in these units
    /// Rounding of a point computed from these corners (a midpoint) far from the origin: 16 ulps
    /// of the largest coordinate. A thin face far from the origin turns it into barycentric
    /// errors above kRelTol (a polygon's ear on a circle of 20,000 points: 2e-9).
    double round = 0;
    /// How far a point may lie from the plane, and how far below 0 its barycentric coordinates
    /// may go, and still count as in this face: kRelTol of the size, plus the float32 slack and
    /// the rounding above. A barycentric l_i below 0 is a distance -l_i |n| / |edge_i| outside
    /// edge i, and the normal's direction errs by about round * size / |n|.
    [[nodiscard]] double plane_tol() const { return kRelTol * size + slack + round * (1 + size * stretch()); }
    [[nodiscard]] double bary_tol() const { return kRelTol + (slack + round) * stretch(); }
    [[nodiscard]] double stretch() const { return n2 > 0 ? size / std::sqrt(n2) : 0.0; }
    /// How far below 0 twice the signed area of a face p, q, r (local units) may go from
    /// rounding its corners (float32: a needle along an edge may come out flipped or flat).
    [[nodiscard]] double orient_tol(const V3& p, const V3& q, const V3& r) const {
        return 4 * (slack + round) * std::max({norm(sub(q, p)), norm(sub(r, q)), norm(sub(p, r))});
    }
};
ParentFrame frame_of(const std::vector<Point3>& pts, const Triangle& t);

/// Containment test for a nearly degenerate parent that needs no division by its area: q lies
/// in the parent's bounding box and within the parent's height (|n| / size) of the line through
/// its longest edge, between that edge's ends (all with tolerance 1e-9 relative to the size,
/// plus rounding far from the origin).
bool sliver_contains(const ParentFrame& p, const V3& world_q);

/// Distance from q to the closed face, in its local units (exact enough for a sliver: no
/// division by its area to find the nearest point outside it).
double distance_to(const ParentFrame& p, const V3& world_q);

/// Barycentric coordinates of the projection of q onto the parent's plane, and the distance
/// of q from that plane.
std::array<double, 3> bary(const ParentFrame& p, const V3& world_q, double& plane_dist);

/// q on the closed segment u-v (within tolerance relative to its length).
bool on_segment(const V3& wu, const V3& wv, const V3& wq, double* t_out = nullptr);

/// The vertices a and b share, into `out`; returns how many.
uint32_t common_vertices(const Triangle& a, const Triangle& b, std::array<uint32_t, 3>& out);

// --- strips (verify_strips.cpp) ----------------------------------------------------------------

/// GL_TRIANGLE_STRIP decoding of `s`: pieces between `restart` values are separate strips.
std::vector<Triangle> gl_decode(const std::vector<uint32_t>& s, uint32_t restart);

// --- the checks of the output, in the order verify() runs them ---------------------------------

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
/// Each output face's parent from the split structure (each inserted vertex the midpoint of two
/// earlier ones), kNo where it cannot tell (verify_carriers.cpp).
std::vector<uint32_t> parents_from_splits(const VerifyInput& in);
/// Each output face's input parent (verify_parents.cpp).
std::vector<uint32_t> resolve_parents(const VerifyInput& in, const Adjacency& out, Failures& fails);
void check_geometry(Checked& chk);                                               // verify_geometry.cpp
void check_boundary_tiling(const Checked& chk);                                  // verify_geometry.cpp
std::vector<uint32_t> check_strips(const Checked& chk, size_t& num_components);  // verify_strips.cpp
void check_indices(const Checked& chk);                                          // verify_strips.cpp
void check_constraints(const Checked& chk);                                      // verify_constraints.cpp
void check_source_target(const Checked& chk, uint32_t first_strip_end);          // verify_constraints.cpp
void check_cycles_request(const Checked& chk, size_t num_components);            // verify_cycles.cpp

}  // namespace singlestrip::verify_detail
