// singlestrip — single-strip builder.
//
// Gopi, "Controllable Single-Strip Generation for Triangulated Surfaces": greedy strip growth
// over the unstriped region U, left/right turns, split candidates classified as bridge or
// fundamental triangles, greedy turns (Algorithm 2), constraint edges (§5.1), start/end
// vertices (§5.2). The paper's split rule does not terminate in general (field notes); this file
// replaces it by *deferred islands*: see docs/algorithm.md for the rule and its termination proof.
//
// Invariant (G): while growing a region R from the strip's current face T, the unstriped faces of
// R are edge-connected through passable edges and T touches them (unless none are left).
// Each step takes a neighbour N of T whose removal keeps R connected ("safe"); if none is safe,
// N is a bridge: we still take it, keep one island as R and *defer* the other, to be spliced in
// later by one midpoint split at the face it was cut from (absorb()).
#include "singlestrip/strip.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>

#include "core/gentle_growth.hpp"
#include "singlestrip/errors.hpp"
#include "strip_controls.hpp"

namespace singlestrip {

namespace {

// The builder keeps flat per-face and per-half-edge arrays, so it navigates by plain index.
[[nodiscard]] inline uint32_t he(uint32_t f, uint32_t k) {
    return Mesh::halfedge(FaceId(f), k).idx();
}
[[nodiscard]] inline uint32_t face_of(uint32_t h) {
    return Mesh::face(HalfedgeId(h)).idx();
}
[[nodiscard]] inline uint32_t next_of(uint32_t h) {
    return Mesh::next(HalfedgeId(h)).idx();
}
[[nodiscard]] inline uint32_t prev_of(uint32_t h) {
    return Mesh::prev(HalfedgeId(h)).idx();
}

constexpr uint32_t kNoRegion = kNone;
/// try_detour(): faces scanned near the anchor at most, always allowed, and earned per face taken.
constexpr size_t kScanLimit = 1024, kScanMinimum = 16, kScanCreditPerFace = 8;

class Builder {
public:
    Builder(Mesh mesh, const StripOptions& options) : mesh_(std::move(mesh)), opt_(options) {}

    StripResult run();

private:
    // ---- per-face / per-half-edge state (resized on every split) ----
    Mesh mesh_;
    const StripOptions& opt_;
    // Plain-index navigation (see he()).
    [[nodiscard]] uint32_t twin_of(uint32_t h) const { return mesh_.twin(HalfedgeId(h)).idx(); }
    [[nodiscard]] uint32_t across(uint32_t h) const { return mesh_.neighbor(HalfedgeId(h)).idx(); }
    [[nodiscard]] bool boundary_of(uint32_t h) const { return mesh_.is_boundary(HalfedgeId(h)); }
    [[nodiscard]] uint32_t from_of(uint32_t h) const { return mesh_.from(HalfedgeId(h)).idx(); }
    [[nodiscard]] uint32_t to_of(uint32_t h) const { return mesh_.to(HalfedgeId(h)).idx(); }
    [[nodiscard]] uint32_t shared_of(uint32_t f, uint32_t g) const { return mesh_.shared_halfedge(FaceId(f), FaceId(g)).idx(); }
    [[nodiscard]] uint32_t vertex_he_of(uint32_t v) const { return mesh_.vertex_halfedge(VertexId(v)).idx(); }
    std::vector<uint8_t> blocked_;       ///< per half-edge: constraint edge (never crossed)
    std::vector<uint8_t> striped_;       ///< per face: already in the strip
    std::vector<uint32_t> region_;       ///< per face: region label of an unstriped face
    std::vector<uint32_t> next_, prev_;  ///< per face: doubly linked strip
    std::vector<uint32_t> stamp_;        ///< per face: search marks (stamp_base_ + side)
    uint32_t stamp_base_ = 0;
    std::vector<uint8_t> fundamental_;  ///< per face: taken as a fundamental triangle
    std::vector<uint32_t> time_;        ///< per face: when it was taken (StripResult::take_time)
    uint32_t clock_ = 0;

    // ---- regions ----
    std::vector<uint32_t> region_size_;  ///< unstriped faces per region label
    /// Per region: its first Betti number 2g+b-1 = 1 - chi (chi with vertices counted once per
    /// fan of the region). Bridges split it between the islands, a fundamental triangle lowers
    /// it by one; at 0 the region is a disk and a failed cavity test proves a bridge.
    std::vector<long long> region_beta_;
    std::vector<uint32_t> vstamp_;  ///< per vertex: marks for chi_of()
    /// Per vertex: striped faces around it, and whether a walk around it meets a boundary or
    /// constraint edge (fixed once constraints are applied; a split's midpoint is interior).
    /// Together they answer the cavity test in O(1): fan_connects().
    std::vector<uint32_t> striped_at_;
    std::vector<uint8_t> rim_;
    uint32_t vstamp_base_ = 0;
    struct Deferred {
        uint32_t region;
        uint32_t anchor;  ///< half-edge of a face in the region, facing the striped face it was cut from
        bool done;
    };
    std::vector<Deferred> deferred_;
    std::vector<uint32_t> deferred_of_region_;

    uint32_t head_ = kNone, tail_ = kNone;
    StripStats stats_;
    int last_turn_ = 0;  ///< +1 right, -1 left, 0 none

    // scratch
    std::vector<uint32_t> side_[2];
    std::vector<uint32_t> stack_[2];
    uint32_t searched_ = kNone;  ///< the face whose islands side_ holds
    /// Faces try_detour() may still scan: it earns kScanCreditPerFace per face taken, so the
    /// scans of failed detours (a split follows each) cost O(F) in all.
    size_t scan_credit_ = 0;
    std::vector<uint32_t> scratch_;

    [[nodiscard]] bool passable(uint32_t h) const { return !boundary_of(h) && !blocked_[h]; }
    [[nodiscard]] bool in_region(uint32_t f, uint32_t r) const { return f != kNone && !striped_[f] && region_[f] == r; }
    /// Face across h if it is an unstriped face of region r, else kNone.
    [[nodiscard]] uint32_t open_neighbor(uint32_t h, uint32_t r) const {
        if (!passable(h)) return kNone;
        const uint32_t g = across(h);
        return in_region(g, r) ? g : kNone;
    }
    [[nodiscard]] uint32_t count_open(uint32_t f, uint32_t r) const {
        uint32_t n = 0;
        for (uint32_t k = 0; k < 3; ++k) n += open_neighbor(he(f, k), r) != kNone;
        return n;
    }

    void grow_arrays();
    long long chi_of(const std::vector<uint32_t>& faces, uint32_t r);
    void note_fundamental(uint32_t f, uint32_t r);
    uint32_t new_region(uint32_t size);
    void insert_after(uint32_t cursor, uint32_t f);
    void take(uint32_t cursor, uint32_t f);
    void count_striped(uint32_t f, int delta);
    bool fan_connects_walk(uint32_t n, uint32_t ha, uint32_t hb, uint32_t r) const;

    /// Safe: removing the face keeps the region connected. Bridge: it does not. Unknown: the
    /// cheap tests failed and the region has cycles, so only a search can tell.
    enum class Kind { Safe, Bridge, Unknown };
    struct Classification {
        Kind kind = Kind::Safe;
        bool fundamental = false;
        uint32_t small_side = kNone;      ///< 0: island of `a`, 1: of `b`; kNone until searched
        uint32_t a = kNone, b = kNone;    ///< N's open neighbours other than T
        uint32_t ha = kNone, hb = kNone;  ///< N's half-edges towards a and b
    };
    Classification classify_local(uint32_t n, uint32_t from, uint32_t r) const;
    bool resolve(Classification& c, uint32_t n, uint32_t r, size_t budget = SIZE_MAX);
    Classification classify(uint32_t n, uint32_t from, uint32_t r) {
        Classification c = classify_local(n, from, r);
        resolve(c, n, r);
        return c;
    }
    bool fan_connects(uint32_t n, uint32_t ha, uint32_t hb, uint32_t r) const;
    /// What a bidirectional search found: the sides met (a and b stay connected without n), the
    /// island of a or of b ran out first (it is in side_[0] or side_[1]), or the budget ran out.
    enum class SearchOutcome : uint8_t { Met, IslandOfA, IslandOfB, OverBudget };
    SearchOutcome bidirectional_search(uint32_t n, uint32_t a, uint32_t b, uint32_t r, size_t budget = SIZE_MAX);

    /// The faces grow() may take next after t: up to three, in the order they are tried.
    struct Candidates {
        uint32_t face[3] = {kNone, kNone, kNone};
        uint32_t he[3] = {kNone, kNone, kNone};  ///< t's half-edge towards face[i]
        int turn[3] = {0, 0, 0};                 ///< +1 right, -1 left, 0 (no in-edge)
        uint32_t order[3] = {0, 1, 2};           ///< indices into face[], most preferred first
        uint32_t n = 0;
        bool dest_adjacent = false;  ///< dest is open but was left out (other faces remain)
    };
    Candidates candidates(uint32_t t, uint32_t region, uint32_t dest) const;
    uint32_t choose_safe(const Candidates& c, uint32_t t, uint32_t region, Classification (&cls)[3]);
    void end_at_dest(uint32_t t, uint32_t region, uint32_t dest);
    void grow(uint32_t cursor, uint32_t region, uint32_t dest);
    uint32_t take_bridge(uint32_t cursor, uint32_t n, uint32_t region, uint32_t dest, const Classification& c);
    uint32_t take_forced(uint32_t cursor, uint32_t f, uint32_t region, uint32_t dest);
    void defer(uint32_t region, uint32_t anchor);
    void absorb(uint32_t record);
    bool absorb_at_tail();
    bool try_detour(uint32_t region, uint32_t anchor);
    uint32_t choose_seed() const;
    [[nodiscard]] bool has_vertex(uint32_t f, uint32_t v) const { return face_has_vertex(mesh_, f, v); }
    [[nodiscard]] uint32_t face_at_vertex(uint32_t v, uint32_t avoid) const {
        return singlestrip::face_at_vertex(mesh_, blocked_, v, avoid);
    }
    uint32_t source_ = kNone, target_ = kNone;

    // ---- the steps of run() ----
    void prepare();
    std::pair<uint32_t, uint32_t> choose_ends();
    [[nodiscard]] long long surface_chi() const;
    void mark_piece(uint32_t f);
    uint32_t relabel_piece(uint32_t f);
    uint32_t split_at_seed(uint32_t seed, uint32_t dest, long long chi_all);
    void absorb_all();
    StripResult finish();
    void check_split_budget() const;
    /// The four children of a split, as plain indices (SplitResult's, see he()).
    struct Children {
        uint32_t f_a, f_b, g_a, g_b;
    };
    Children split_at(uint32_t h);
};

void Builder::grow_arrays() {
    // Gently: splits add a few percent, and doubling 11 arrays would add up to 34 bytes a face.
    auto fit = [](auto& v, uint32_t n, auto value) {
        reserve_gently(v, n);
        v.resize(n, value);
    };
    const uint32_t nf = mesh_.num_faces(), nh = mesh_.num_halfedges(), nv = mesh_.num_vertices();
    fit(striped_, nf, 0);
    fit(region_, nf, kNoRegion);
    fit(next_, nf, kNone);
    fit(prev_, nf, kNone);
    fit(stamp_, nf, 0);
    fit(fundamental_, nf, 0);
    fit(time_, nf, kNone);
    fit(blocked_, nh, 0);
    fit(vstamp_, nv, 0);
    fit(striped_at_, nv, 0);
    fit(rim_, nv, 0);
}

void Builder::count_striped(uint32_t f, int delta) {
    for (uint32_t k = 0; k < 3; ++k) striped_at_[mesh_.corner_vertices()[he(f, k)]] += static_cast<uint32_t>(delta);
}

// chi of a set of open faces of region r: F - (passable edges inside) + (vertices whose whole
// fan lies in the region through passable edges). Derivation in docs/algorithm.md. O(|faces|).
long long Builder::chi_of(const std::vector<uint32_t>& faces, uint32_t r) {
    ++vstamp_base_;
    long long inner_halfedges = 0, interior_vertices = 0;
    for (const uint32_t f : faces) {
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t h = he(f, k);
            inner_halfedges += open_neighbor(h, r) != kNone;
            const uint32_t v = from_of(h);
            if (vstamp_[v] == vstamp_base_) continue;
            vstamp_[v] = vstamp_base_;
            // Interior: rotating around v never leaves the region nor crosses a blocked edge.
            uint32_t g = h;
            bool interior = true;
            do {
                const uint32_t e = prev_of(g);
                if (!passable(e) || !in_region(face_of(g), r)) {
                    interior = false;
                    break;
                }
                g = twin_of(e);
            } while (g != h);
            interior_vertices += interior;
        }
    }
    return static_cast<long long>(faces.size()) - inner_halfedges / 2 + interior_vertices;
}

uint32_t Builder::new_region(uint32_t size) {
    region_size_.push_back(size);
    region_beta_.push_back(0);
    deferred_of_region_.push_back(kNone);
    return static_cast<uint32_t>(region_size_.size() - 1);
}

void Builder::insert_after(uint32_t cursor, uint32_t f) {
    if (cursor == kNone) {
        next_[f] = head_;
        prev_[f] = kNone;
        if (head_ != kNone) prev_[head_] = f;
        head_ = f;
        if (tail_ == kNone) tail_ = f;
        return;
    }
    const uint32_t nx = next_[cursor];
    next_[cursor] = f;
    prev_[f] = cursor;
    next_[f] = nx;
    if (nx != kNone)
        prev_[nx] = f;
    else
        tail_ = f;
}

void Builder::take(uint32_t cursor, uint32_t f) {
    if (striped_[f]) throw InternalError("strip builder: face " + std::to_string(f) + " taken twice");
    striped_[f] = 1;
    count_striped(f, +1);
    time_[f] = clock_++;
    scan_credit_ += kScanCreditPerFace;
    --region_size_[region_[f]];
    insert_after(cursor, f);
}

// Local cavity test (paper Fig. 6): a and b (N's open neighbours across ha and hb) stay connected
// without N if the faces around the vertex V shared by ha and hb lead from a to b, away from N,
// through open faces of r and passable edges. That path is every face and edge around V but N
// and its two edges, so it exists exactly when V is not on the rim (no boundary or constraint
// edge at V) and no face around V is striped: the unstriped faces around V are then connected
// to N, hence in N's region (a region is a connected piece of the unstriped faces). O(1), any
// valence. (A walk around V cost O(valence) per test: quadratic on a cone's apex; a walk capped at
// 4096 steps answered "not connected" wrongly and a closed cone failed with "fundamental
// triangle in a region without cycles".)
bool Builder::fan_connects(uint32_t n, uint32_t ha, uint32_t hb, uint32_t r) const {
    const uint32_t v = from_of(ha) == to_of(hb) ? from_of(ha) : to_of(ha);
    // a shares both its edges at V with N: N closes the fan, the path would go through N.
    const bool connects = across(ha) != across(hb) && !rim_[v] && striped_at_[v] == 0;
    if (opt_.validate_each_split && connects != fan_connects_walk(n, ha, hb, r))
        throw InternalError("strip builder: cavity test disagrees with the walk around vertex " + std::to_string(v));
    return connects;
}

// The same test by walking around V (O(valence)); a cross-check in tests (validate_each_split).
bool Builder::fan_connects_walk(uint32_t n, uint32_t ha, uint32_t hb, uint32_t r) const {
    const uint32_t v = from_of(ha) == to_of(hb) ? from_of(ha) : to_of(ha);
    const uint32_t b = across(hb);
    uint32_t g = twin_of(ha);  // in face a, incident to v
    for (uint32_t guard = 0; guard <= mesh_.num_halfedges(); ++guard) {
        const uint32_t other = from_of(g) == v ? prev_of(g) : next_of(g);
        if (!passable(other)) return false;
        g = twin_of(other);
        const uint32_t f = face_of(g);
        if (f == b) return true;
        if (f == n || !in_region(f, r)) return false;
    }
    return false;
}

// Alternating search from a and from b through open faces of r, never entering n.
// Met if they meet (connected), else the side that ran out first (IslandOfA or IslandOfB); that
// side's faces are then in side_[0] or side_[1]. Cost O(size of the smaller island) when they are separated.
Builder::SearchOutcome Builder::bidirectional_search(uint32_t n, uint32_t a, uint32_t b, uint32_t r, size_t budget) {
    stamp_base_ += 2;
    if (stamp_base_ >= 0xfffffff0u) {
        std::fill(stamp_.begin(), stamp_.end(), 0);
        stamp_base_ = 2;
    }
    const uint32_t mark[2] = {stamp_base_, stamp_base_ + 1};
    size_t popped = 0;
    for (int s = 0; s < 2; ++s) {
        side_[s].clear();
        stack_[s].clear();
    }
    side_[0].push_back(a);
    side_[1].push_back(b);
    stack_[0].push_back(a);
    stack_[1].push_back(b);
    stamp_[a] = mark[0];
    stamp_[b] = mark[1];
    stamp_[n] = mark[0];  // never enter n (both sides treat it as foreign but not as a meeting)
    for (;;) {
        if (popped > budget) {
            stamp_[n] = 0;
            return SearchOutcome::OverBudget;
        }
        for (int s = 0; s < 2; ++s) {
            if (stack_[s].empty()) {
                stamp_[n] = 0;
                return s == 0 ? SearchOutcome::IslandOfA : SearchOutcome::IslandOfB;
            }
            const uint32_t f = stack_[s].back();
            stack_[s].pop_back();
            ++popped;
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t g = open_neighbor(he(f, k), r);
                if (g == kNone || g == n) continue;
                if (stamp_[g] == mark[s]) continue;
                if (stamp_[g] == mark[1 - s]) {
                    stamp_[n] = 0;
                    return SearchOutcome::Met;
                }
                stamp_[g] = mark[s];
                side_[s].push_back(g);
                stack_[s].push_back(g);
            }
        }
    }
}

// Cheap part of the classification: open neighbours, then the local cavity test. In a region
// without cycles (beta 0, a disk) a failed cavity test proves a bridge without any search.
Builder::Classification Builder::classify_local(uint32_t n, uint32_t from, uint32_t r) const {
    Classification c;
    for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t h = he(n, k);
        const uint32_t g = open_neighbor(h, r);
        if (g == kNone || g == from) continue;
        if (c.a == kNone) {
            c.a = g;
            c.ha = h;
        } else {
            c.b = g;
            c.hb = h;
        }
    }
    if (c.b == kNone) return c;  // at most one open neighbour: removing n keeps R connected
    if (fan_connects(n, c.ha, c.hb, r)) return c;
    c.kind = region_beta_[r] <= 0 ? Kind::Bridge : Kind::Unknown;
    return c;
}

// Expensive part: the bidirectional search decides Unknown, and finds the smaller island of a
// bridge (left in side_[c.small_side]); call it right before taking a bridge. With a budget
// (faces visited) it may return false: still Unknown.
bool Builder::resolve(Classification& c, uint32_t n, uint32_t r, size_t budget) {
    if (c.kind == Kind::Safe || (c.kind == Kind::Bridge && c.small_side != kNone && searched_ == n)) return true;
    const SearchOutcome s = bidirectional_search(n, c.a, c.b, r, budget);
    searched_ = n;
    if (s == SearchOutcome::OverBudget) return false;
    if (s == SearchOutcome::Met) {
        // A split candidate that is not a bridge (§3.1). Impossible in a disk.
        if (region_beta_[r] <= 0)
            throw InternalError("strip builder: fundamental triangle in a region without cycles (topology tracking broken)");
        c.kind = Kind::Safe;
        c.fundamental = true;
        return true;
    }
    c.kind = Kind::Bridge;
    c.small_side = s == SearchOutcome::IslandOfA ? 0 : 1;
    return true;
}

void Builder::note_fundamental(uint32_t f, uint32_t r) {
    fundamental_[f] = 1;
    ++stats_.fundamental_triangles;
    --region_beta_[r];
}

void Builder::defer(uint32_t region, uint32_t anchor) {
    deferred_of_region_[region] = static_cast<uint32_t>(deferred_.size());
    deferred_.push_back({region, anchor, false});
    ++stats_.deferred_regions;
}

// Splits the edge of h at its midpoint, keeping the per-face and per-half-edge state in step.
Builder::Children Builder::split_at(uint32_t h) {
    // Constraint flags of the two half-edges that split_edge moves into new faces.
    const uint32_t moved_f = next_of(h), moved_g = next_of(twin_of(h));
    const uint8_t blocked_f = blocked_[moved_f], blocked_g = blocked_[moved_g];
    // The children of a striped face are striped (the host's in absorb()).
    const uint8_t striped_f = striped_[face_of(h)], striped_g = striped_[face_of(twin_of(h))];
    if (striped_f) count_striped(face_of(h), -1);
    if (striped_g) count_striped(face_of(twin_of(h)), -1);
    const SplitResult r = mesh_.split_edge(HalfedgeId(h));
    const Children s{r.f_a.idx(), r.f_b.idx(), r.g_a.idx(), r.g_b.idx()};
    ++stats_.splits;
    check_split_budget();
    grow_arrays();
    striped_[s.f_b] = striped_f;
    striped_[s.g_a] = striped_g;
    for (const uint32_t f : {s.f_a, s.f_b, s.g_a, s.g_b})
        if (striped_[f]) count_striped(f, +1);
    blocked_[moved_f] = 0;
    blocked_[moved_g] = 0;
    blocked_[he(s.f_b, 1)] = blocked_f;
    blocked_[he(s.g_a, 1)] = blocked_g;
    if (opt_.validate_each_split) mesh_.validate();
    return s;
}

void Builder::check_split_budget() const {
    // docs/algorithm.md: splits < input faces (+1 for the target pre-split). Exceeding it means a
    // broken invariant, never a long loop.
    if (stats_.splits > mesh_.num_input_faces() + 1)
        throw InternalError("strip builder: split budget exceeded (" + std::to_string(stats_.splits) + " splits)");
}

// The open neighbours of t in `region`, dest left out while anything else is left, in the order
// they are tried.
Builder::Candidates Builder::candidates(uint32_t t, uint32_t region, uint32_t dest) const {
    Candidates c;
    for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t h = he(t, k);
        const uint32_t g = open_neighbor(h, region);
        if (g == kNone) continue;
        if (g == dest && region_size_[region] > 1) {
            c.dest_adjacent = true;
            continue;
        }
        c.face[c.n] = g;
        c.he[c.n++] = h;
    }
    // Turn of each candidate relative to the in-edge of t.
    const uint32_t pv = prev_[t];
    const uint32_t hin = pv == kNone ? kNone : shared_of(t, pv);
    for (uint32_t i = 0; i < c.n; ++i) c.turn[i] = hin == kNone ? 0 : (c.he[i] == next_of(hin) ? +1 : -1);
    // Order: greedy = fewer open neighbours first (Warnsdorff), ties alternate the turn;
    // paper = keep the same turn direction as before.
    uint32_t deg[3] = {0, 0, 0};
    for (uint32_t i = 0; i < c.n; ++i) deg[i] = count_open(c.face[i], region);
    auto better = [&](uint32_t i, uint32_t j) {
        if (opt_.greedy) {
            if (deg[i] != deg[j]) return deg[i] < deg[j];
            return c.turn[i] != last_turn_ && c.turn[j] == last_turn_;
        }
        return c.turn[i] == (last_turn_ == 0 ? +1 : last_turn_) && c.turn[j] != c.turn[i];
    };
    // Up to three candidates (the seed has no in-edge): insertion sort.
    for (uint32_t i = 1; i < c.n; ++i)
        for (uint32_t j = i; j > 0 && better(c.order[j], c.order[j - 1]); --j) std::swap(c.order[j], c.order[j - 1]);
    return c;
}

// The first candidate (in c.order) that is safe to take, or kNone; cls[i] classifies the i-th.
uint32_t Builder::choose_safe(const Candidates& c, uint32_t t, uint32_t region, Classification (&cls)[3]) {
    // Cheap tests first for every candidate considered; searches only if none passes.
    // Without greedy turns only the preferred neighbour is considered (paper, Algorithm 1).
    const uint32_t considered = opt_.greedy ? c.n : 1;
    uint32_t chosen = kNone;
    // In preference order: safe by the cheap tests, or by a search of bounded cost (O(1)
    // per step, so a long search is never spent on a face we might not take). The cheap
    // tests of a candidate run only when the ones before it are not safe (a cavity test
    // around a high-valence vertex is not O(1) either).
    constexpr size_t kFirstBudget = 256;
    for (uint32_t i = 0; i < considered && chosen == kNone; ++i) {
        cls[i] = classify_local(c.face[c.order[i]], t, region);
        if (cls[i].kind == Kind::Unknown) resolve(cls[i], c.face[c.order[i]], region, kFirstBudget);
        if (cls[i].kind == Kind::Safe) chosen = i;
    }
    // Two undecided candidates: search both with a growing budget, so a quick answer for
    // one is not preceded by a long search of the other (a bridge search not taken is
    // wasted work that no amortisation pays for).
    for (size_t budget = 4 * kFirstBudget; chosen == kNone; budget *= 4) {
        bool undecided = false;
        for (uint32_t i = 0; i < considered && chosen == kNone; ++i) {
            if (cls[i].kind != Kind::Unknown) continue;
            if (!resolve(cls[i], c.face[c.order[i]], region, budget))
                undecided = true;
            else if (cls[i].kind == Kind::Safe)
                chosen = i;
        }
        if (!undecided) break;
    }
    return chosen;
}

// Only dest is reachable from t: the region ends here and what is left is deferred; it touches
// dest (inside a splice dest's out-edge leads back to the strip, so through one edge; as the
// strip's last face, possibly through two, then maybe as two islands).
void Builder::end_at_dest(uint32_t t, uint32_t region, uint32_t dest) {
    const Classification c = classify(dest, t, region);
    if (c.kind == Kind::Bridge) {
        const uint32_t large_he = c.small_side == 0 ? c.hb : c.ha;
        const uint32_t large = take_bridge(t, dest, region, kNone, c);
        defer(large, twin_of(large_he));
        return;
    }
    if (c.fundamental) note_fundamental(dest, region);
    take(t, dest);
    defer(region, twin_of(c.ha));
}

// Grows the strip after `cursor` through region `region`; if dest != kNone the region must end
// with dest (it is spliced before an existing strip face).
void Builder::grow(uint32_t cursor, uint32_t region, uint32_t dest) {
    uint32_t t = cursor;
    while (region_size_[region] > 0) {
        const Candidates c = candidates(t, region, dest);
        if (c.n == 0) {
            if (c.dest_adjacent) {
                end_at_dest(t, region, dest);
                return;
            }
            throw InternalError("strip builder: strip stuck with " + std::to_string(region_size_[region]) +
                                " faces left in its region (invariant G broken)");
        }
        Classification cls[3];
        if (const uint32_t chosen = choose_safe(c, t, region, cls); chosen != kNone) {
            const uint32_t n = c.face[c.order[chosen]];
            if (cls[chosen].fundamental) note_fundamental(n, region);
            last_turn_ = c.turn[c.order[chosen]];
            take(t, n);
            t = n;
            continue;
        }
        // Every candidate considered is a bridge: take the first anyway, continue into one island
        // and defer the other (relabelled, so R stays connected: invariant G).
        const uint32_t n = c.face[c.order[0]];
        last_turn_ = c.turn[c.order[0]];
        resolve(cls[0], n, region);
        region = take_bridge(t, n, region, dest, cls[0]);
        t = n;
    }
}

// Takes n (a bridge of `region`, classified in c) after cursor: the island holding dest, or the
// larger one, stays the region to grow; the other is relabelled if needed and deferred,
// anchored at n. Returns the region to continue in.
uint32_t Builder::take_bridge(uint32_t cursor, uint32_t n, uint32_t region, uint32_t dest, const Classification& c) {
    const uint32_t small = c.small_side;
    const uint32_t small_he = small == 0 ? c.ha : c.hb;
    const uint32_t large_he = small == 0 ? c.hb : c.ha;
    take(cursor, n);  // first, so that n counts in neither island below
    const uint32_t small_size = static_cast<uint32_t>(side_[small].size());
    const long long beta_small = 1 - chi_of(side_[small], region);
    const uint32_t r_small = new_region(small_size);
    region_size_[region] -= small_size;
    region_beta_[r_small] = beta_small;
    region_beta_[region] -= beta_small;
    if (region_beta_[region] < 0 || beta_small < 0)
        throw InternalError("strip builder: negative cycle count after a bridge (topology tracking broken)");
    bool dest_in_small = false;
    for (uint32_t f : side_[small]) {
        region_[f] = r_small;
        dest_in_small |= f == dest;
    }
    if (dest_in_small) {
        defer(region, twin_of(large_he));
        return r_small;
    }
    defer(r_small, twin_of(small_he));
    return region;
}

// Takes f after cursor when f is forced (no choice): if f is a bridge of its region, the island
// without dest is deferred. Returns the region to continue in.
uint32_t Builder::take_forced(uint32_t cursor, uint32_t f, uint32_t region, uint32_t dest) {
    const Classification c = classify(f, cursor, region);
    if (c.kind == Kind::Bridge) return take_bridge(cursor, f, region, dest, c);
    if (c.fundamental) note_fundamental(f, region);
    take(cursor, f);
    return region;
}

// Splices a deferred region into the strip at the face it was cut from (its host): the host and
// the region's anchor face are split at the midpoint of their shared edge; the host's two
// children keep the host's in- and out-edges, the anchor's two children become the first and
// last face of the region's own strip, which is grown between them.
void Builder::absorb(uint32_t record) {
    Deferred& d = deferred_[record];
    d.done = true;
    const uint32_t region = d.region;
    const uint32_t ha = d.anchor;  // in the anchor face
    const uint32_t hh = twin_of(ha);
    if (hh == kNone) throw InternalError("strip builder: deferred region lost its host");
    const uint32_t host = face_of(hh);
    const uint32_t anchor = face_of(ha);
    if (!striped_[host] || !in_region(anchor, region))
        throw InternalError("strip builder: deferred region " + std::to_string(region) + " has a bad anchor");
    if (try_detour(region, anchor)) return;
    if (host == tail_ && target_ == kNone) {  // free: the strip simply continues into the region
        const uint32_t r = take_forced(host, anchor, region, kNone);
        grow(anchor, r, kNone);
        return;
    }
    const uint32_t p = prev_[host], n = next_[host];
    const Children s = split_at(hh);
    region_[s.f_b] = kNoRegion;
    fundamental_[s.f_b] = fundamental_[host];
    time_[s.f_b] = time_[host];
    region_[s.g_a] = region;
    ++region_size_[region];
    // c0 keeps the host's in-edge, c1 its out-edge; a0 is the anchor child beside c0.
    bool fa_first;
    if (p != kNone)
        fa_first = shared_of(s.f_a, p) != kNone;
    else if (n != kNone)
        fa_first = shared_of(s.f_a, n) == kNone;
    else
        fa_first = source_ == kNone || has_vertex(s.f_a, source_);
    const uint32_t c0 = fa_first ? s.f_a : s.f_b, c1 = fa_first ? s.f_b : s.f_a;
    const uint32_t a0 = fa_first ? s.g_a : s.g_b, a1 = fa_first ? s.g_b : s.g_a;
    // Host slot (index f_a) becomes c0 -> c1.
    if (fa_first)
        insert_after(s.f_a, s.f_b);
    else
        insert_after(p, s.f_b);  // p == kNone inserts at the head
    // Normally the region goes between the children: c0 -> a0 ... a1 -> c1. At the ends of the
    // strip the region may instead go first (a1 ... a0 -> c0 -> c1) or last (c0 -> c1 -> a1 ... a0)
    // so that the first face keeps the source vertex and the last face the target (§5.2).
    uint32_t cursor = c0, first = a0, last = a1;
    if (p == kNone && source_ != kNone && !has_vertex(c0, source_)) {
        cursor = kNone;
        first = a1;
        last = a0;
    } else if (n == kNone && target_ != kNone && !has_vertex(c1, target_)) {
        cursor = c1;
        first = a1;
        last = a0;
    }
    const uint32_t r = take_forced(cursor, first, region, last);
    grow(first, r, last);
}

// Zero-cost splice: if two consecutive strip faces x -> y touch the region at faces r1 (beside x)
// and r2 (beside y), with r1 != r2 unless the region is that single face, the region's own
// strip r1 ... r2 goes between them and no split is needed. O(min(region size, kScanLimit)).
bool Builder::try_detour(uint32_t region, uint32_t anchor) {
    // Only the part of the region near its anchor is examined (a large region deferred again and
    // again inside nested splices would otherwise be scanned each time: quadratic), and no more
    // than the credit earned by the faces taken so far (many absorbs of large regions without a
    // detour, as between parallel holes, would otherwise cost kScanLimit each).
    const size_t limit = std::max(kScanMinimum, std::min(kScanLimit, scan_credit_));
    scratch_.clear();
    scratch_.push_back(anchor);
    stamp_base_ += 2;
    stamp_[anchor] = stamp_base_;
    for (size_t i = 0; i < scratch_.size() && scratch_.size() < limit; ++i) {
        const uint32_t f = scratch_[i];
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t g = open_neighbor(he(f, k), region);
            if (g != kNone && stamp_[g] != stamp_base_) {
                stamp_[g] = stamp_base_;
                scratch_.push_back(g);
            }
        }
    }
    scan_credit_ -= std::min(scan_credit_, scratch_.size());
    const bool single = region_size_[region] == 1;
    for (const uint32_t r1 : scratch_) {
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t h = he(r1, k);
            if (!passable(h)) continue;
            const uint32_t x = across(h);
            if (!striped_[x]) continue;
            const uint32_t y = next_[x];
            if (y == kNone) continue;
            for (uint32_t j = 0; j < 3; ++j) {
                const uint32_t hy = he(y, j);
                if (!passable(hy)) continue;
                const uint32_t r2 = across(hy);
                if (!in_region(r2, region) || (r2 == r1) != single) continue;
                ++stats_.detours;
                const uint32_t r = take_forced(x, r1, region, single ? kNone : r2);
                grow(r1, r, single ? kNone : r2);
                return true;
            }
        }
    }
    return false;
}

bool Builder::absorb_at_tail() {
    for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t h = he(tail_, k);
        if (!passable(h)) continue;
        const uint32_t g = across(h);
        if (striped_[g]) continue;
        const uint32_t rec = deferred_of_region_[region_[g]];
        if (rec == kNone || deferred_[rec].done) continue;
        deferred_[rec].anchor = twin_of(h);
        absorb(rec);
        return true;
    }
    return false;
}

uint32_t Builder::choose_seed() const {
    const uint32_t nf = mesh_.num_faces();
    if (opt_.seed_face) return opt_.seed_face->idx();
    // Prefer a face with two blocked sides (it has one open neighbour: always safe), then one
    // with one blocked side whose opposite vertex is interior, then any face with a blocked side.
    uint32_t best = 0;
    int best_score = -1;
    for (uint32_t f = 0; f < nf; ++f) {
        int closed = 0;
        for (uint32_t k = 0; k < 3; ++k) closed += !passable(he(f, k));
        const int score = closed >= 3 ? 0 : closed;
        if (score > best_score) {
            best_score = score;
            best = f;
            if (score == 2) break;
        }
    }
    return best;
}

// Per-face state, constraints, the rim flags of the cavity test, the input's statistics, and
// region 0 holding every face.
void Builder::prepare() {
    grow_arrays();
    blocked_ = constraint_halfedges(mesh_, opt_);
    for (uint32_t h = 0; h < mesh_.num_halfedges(); ++h)
        if (!passable(h)) rim_[from_of(h)] = rim_[to_of(h)] = 1;
    stats_.input_triangles = mesh_.num_faces();
    stats_.boundary_loops = mesh_.num_boundary_loops();
    stats_.genus = mesh_.genus();
    source_ = opt_.source ? opt_.source->idx() : kNone;
    target_ = opt_.target ? opt_.target->idx() : kNone;
    const uint32_t r0 = new_region(mesh_.num_faces());
    std::fill(region_.begin(), region_.end(), r0);
}

// The first face (seed) and the face the strip must end with (dest, kNone without a target).
std::pair<uint32_t, uint32_t> Builder::choose_ends() {
    const uint32_t nf = mesh_.num_faces();
    const uint32_t r0 = 0;
    uint32_t seed = opt_.seed_face ? opt_.seed_face->idx() : opt_.source ? face_at_vertex(opt_.source->idx(), kNone) : choose_seed();
    if (!opt_.target) return {seed, kNone};
    uint32_t dest = face_at_vertex(opt_.target->idx(), seed);
    if (dest == seed && nf > 1) {
        // The target's only face is the first face: split it across the edge opposite the
        // target so that both children touch the target; start in one, end in the other.
        uint32_t h = he(seed, 0);
        while (from_of(h) == target_ || to_of(h) == target_) ++h;
        if (!passable(h))
            throw RequestError("cannot end at target vertex " + std::to_string(target_) +
                               ": its only face is the first face of the strip and cannot be split");
        const Children sr = split_at(h);
        const bool a_first = source_ == kNone || has_vertex(sr.f_a, source_);
        seed = a_first ? sr.f_a : sr.f_b;
        dest = a_first ? sr.f_b : sr.f_a;
        for (uint32_t f : {sr.f_b, sr.g_a}) region_[f] = r0;
        region_size_[r0] += 2;
    }
    if (nf == 1) dest = kNone;
    return {seed, dest};
}

// chi of the whole surface (through passable edges) before anything is taken: chi_of() of every
// face, where an interior vertex is one off the rim (a flat pass, no walk around the vertices).
long long Builder::surface_chi() const {
    long long passable_halfedges = 0, interior_vertices = 0;
    for (uint32_t h = 0; h < mesh_.num_halfedges(); ++h) passable_halfedges += passable(h);
    for (uint32_t v = 0; v < mesh_.num_vertices(); ++v) interior_vertices += vertex_he_of(v) != kNone && !rim_[v];
    return static_cast<long long>(mesh_.num_faces()) - passable_halfedges / 2 + interior_vertices;
}

// Marks (stamp_base_) the faces of region 0 reachable from f without crossing striped faces.
void Builder::mark_piece(uint32_t f) {
    stamp_base_ += 2;
    stamp_[f] = stamp_base_;
    scratch_.assign(1, f);
    while (!scratch_.empty()) {
        const uint32_t x = scratch_.back();
        scratch_.pop_back();
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t g = open_neighbor(he(x, k), 0);
            if (g != kNone && stamp_[g] != stamp_base_) {
                stamp_[g] = stamp_base_;
                scratch_.push_back(g);
            }
        }
    }
}

// Moves the piece of region 0 holding f (not connected to the first piece) to a new region.
uint32_t Builder::relabel_piece(uint32_t f) {
    const uint32_t r = new_region(0);
    region_[f] = r;
    scratch_.assign(1, f);
    while (!scratch_.empty()) {
        const uint32_t x = scratch_.back();
        scratch_.pop_back();
        ++region_size_[r];
        --region_size_[0];
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t g = open_neighbor(he(x, k), 0);
            if (g != kNone) {
                region_[g] = r;
                scratch_.push_back(g);
            }
        }
    }
    return r;
}

// The seed (already taken) may cut U apart, into up to three pieces: labels each piece, sets
// their Betti numbers, notes the seed as fundamental if it lowered the total (a face joining
// two boundary loops, paper Fig. 4), defers every piece but the one to grow (the destination's,
// or the first), anchored at the seed. Returns the region to grow. chi_all: surface_chi().
uint32_t Builder::split_at_seed(uint32_t seed, uint32_t dest, long long chi_all) {
    const long long beta_all = 1 - chi_all;
    uint32_t nbr[3], arm[3], cnt = 0;
    for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t g = open_neighbor(he(seed, k), 0);
        if (g != kNone) {
            nbr[cnt] = g;
            arm[cnt++] = he(seed, k);
        }
    }
    if (cnt <= 1) {
        // One piece: chi_of() of every face but the seed, from chi_all without another pass. The
        // seed takes one face and its cnt passable edges away, and its vertices off the rim are
        // no longer interior (their fans hold a striped face). Beta cannot drop: not fundamental.
        if (cnt == 0) return 0;
        long long interior = 0;
        for (uint32_t k = 0; k < 3; ++k) interior += !rim_[from_of(he(seed, k))];
        region_beta_[0] = beta_all + 1 - cnt + interior;
        if (opt_.validate_each_split) {  // tests: the same by chi_of() and a walk around every vertex
            std::vector<uint32_t> rest;
            for (uint32_t f = 0; f < mesh_.num_faces(); ++f)
                if (!striped_[f]) rest.push_back(f);
            if (region_beta_[0] != 1 - chi_of(rest, 0)) throw InternalError("strip builder: Betti number after the seed is wrong");
        }
        return 0;
    }
    uint32_t piece_region[3] = {0, kNone, kNone};
    for (uint32_t i = 1; i < cnt; ++i) {
        if (i == 1) mark_piece(nbr[0]);  // the first neighbour's piece keeps region 0
        if (stamp_[nbr[i]] == stamp_base_)
            piece_region[i] = 0;
        else if (region_[nbr[i]] != 0)  // relabelled with an earlier neighbour
            piece_region[i] = region_[nbr[i]];
        else
            piece_region[i] = relabel_piece(nbr[i]);
    }
    std::vector<std::vector<uint32_t>> members(region_size_.size());
    for (uint32_t f = 0; f < mesh_.num_faces(); ++f)  // faces of a target pre-split too
        if (!striped_[f]) members[region_[f]].push_back(f);
    long long beta_pieces = 0;
    for (uint32_t r = 0; r < members.size(); ++r) {
        if (members[r].empty()) continue;
        region_beta_[r] = 1 - chi_of(members[r], r);
        beta_pieces += region_beta_[r];
    }
    if (beta_all > beta_pieces) {
        fundamental_[seed] = 1;
        stats_.fundamental_triangles += static_cast<uint32_t>(beta_all - beta_pieces);
    }
    const uint32_t grow_region = dest != kNone ? region_[dest] : 0;
    std::vector<uint32_t> done_regions{grow_region};
    for (uint32_t i = 0; i < cnt; ++i) {
        const uint32_t r = piece_region[i];
        if (std::find(done_regions.begin(), done_regions.end(), r) != done_regions.end()) continue;
        done_regions.push_back(r);
        defer(r, twin_of(arm[i]));
    }
    return grow_region;
}

// Splices the deferred regions: first any that touch the tail (free), then the rest, newest
// first (absorbing one may defer more).
void Builder::absorb_all() {
    for (;;) {
        if (target_ == kNone && absorb_at_tail()) continue;
        uint32_t rec = kNone;
        while (!deferred_.empty()) {
            if (!deferred_.back().done) {
                rec = static_cast<uint32_t>(deferred_.size() - 1);
                break;
            }
            deferred_.pop_back();
        }
        if (rec == kNone) break;
        absorb(rec);
    }
}

// The strip's faces in order, the positions of fundamental triangles, and the swap count.
StripResult Builder::finish() {
    StripResult result;
    result.order.reserve(mesh_.num_faces());
    for (uint32_t f = head_; f != kNone; f = next_[f]) {
        if (result.order.size() > mesh_.num_faces()) throw InternalError("strip builder: strip list has a cycle");
        if (fundamental_[f]) result.fundamental_positions.push_back(static_cast<uint32_t>(result.order.size()));
        result.order.push_back(f);
    }
    if (result.order.size() != mesh_.num_faces())
        throw InternalError("strip builder: strip covers " + std::to_string(result.order.size()) + " of " +
                            std::to_string(mesh_.num_faces()) + " faces");
    stats_.swaps += count_swaps(mesh_, result.order);
    stats_.output_triangles = mesh_.num_faces();
    result.stats = stats_;
    result.take_time = std::move(time_);
    result.mesh = std::move(mesh_);
    return result;
}

StripResult Builder::run() {
    check_strip_request(mesh_, opt_);
    prepare();
    const auto [seed, dest] = choose_ends();
    const long long chi_all = surface_chi();
    if (opt_.validate_each_split) {  // tests: the same by chi_of()
        std::vector<uint32_t> all(mesh_.num_faces());
        std::iota(all.begin(), all.end(), 0u);
        if (chi_all != chi_of(all, 0)) throw InternalError("strip builder: chi of the surface is wrong");
    }
    take(kNone, seed);
    const uint32_t region = split_at_seed(seed, dest, chi_all);
    grow(seed, region, dest);
    absorb_all();
    return finish();
}

}  // namespace

StripResult build_strip_growth(Mesh mesh, const StripOptions& options) {
    Builder builder(std::move(mesh), options);
    StripResult r = builder.run();
    r.stats.engine = StripEngine::Growth;
    return r;
}

StripResult build_strip(Mesh mesh, const StripOptions& options) {
    // One strip covers one edge-connected piece; the engines' invariants assume it.
    if (const uint32_t parts = mesh.num_components(); parts > 1)
        throw RequestError("the mesh has " + std::to_string(parts) +
                           " edge-connected components; build_strip() strips one (stripify() strips each)");
    return options.engine == StripEngine::Growth ? build_strip_growth(std::move(mesh), options)
                                                 : build_strip_matching(std::move(mesh), options);
}

const char* engine_name(StripEngine engine) noexcept {
    return engine == StripEngine::Growth ? "growth" : "matching";
}

std::optional<StripEngine> parse_engine(std::string_view name) noexcept {
    if (name == "matching") return StripEngine::Matching;
    if (name == "growth") return StripEngine::Growth;
    return std::nullopt;
}

StripArrays strip_arrays(const StripResult& result) {
    StripArrays out;
    out.points = result.mesh.points();
    out.faces.reserve(result.order.size());
    out.parent.reserve(result.order.size());
    const auto& cv = result.mesh.corner_vertices();
    for (uint32_t f : result.order) {
        out.faces.push_back({cv[3 * f], cv[3 * f + 1], cv[3 * f + 2]});
        out.parent.push_back(result.mesh.parent(FaceId(f)).idx());
    }
    return out;
}

}  // namespace singlestrip
