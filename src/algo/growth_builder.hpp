// singlestrip — the growth engine's builder, shared by its source files (private header):
//   strip.cpp           run() and its steps: seed, ends, the seed's pieces, the finished strip;
//   growth_state.cpp    per-face arrays, regions, the strip list, chi, midpoint splits;
//   growth_classify.cpp safe/bridge/fundamental: the cavity test and the bidirectional search;
//   growth_grow.cpp     growing through a region: candidates, turns, bridges taken;
//   growth_splice.cpp   deferred islands spliced back: detours, absorbs.
//
// Gopi, "Controllable Single-Strip Generation for Triangulated Surfaces": greedy strip growth
// over the unstriped region U, left/right turns, split candidates classified as bridge or
// fundamental triangles, greedy turns (Algorithm 2), constraint edges (§5.1), start/end
// vertices (§5.2). The paper's split rule does not terminate in general (field notes); this engine
// replaces it by *deferred islands*: see docs/algorithm.md for the rule and its termination proof.
//
// Invariant (G): while growing a region R from the strip's current face T, the unstriped faces of
// R are edge-connected through passable edges and T touches them (unless none are left).
// Each step takes a neighbour N of T whose removal keeps R connected ("safe"); if none is safe,
// N is a bridge: we still take it, keep one island as R and *defer* the other, to be spliced in
// later by one midpoint split at the face it was cut from (absorb()).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "strip_controls.hpp"

namespace singlestrip::growth {

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

}  // namespace singlestrip::growth
