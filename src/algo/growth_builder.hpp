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

#include "core/face_sides.hpp"
#include "core/id_vector.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "strip_controls.hpp"

namespace singlestrip::growth {

/// A deferred island's record (Builder::deferred_).
using DeferredId = Id<struct DeferredTag>;
/// The region prepare() makes of every face; the seed's first piece keeps it.
constexpr RegionId kRegion0{0};
/// try_detour(): faces scanned near the anchor at most, always allowed, and earned per face taken.
constexpr size_t kScanLimit = 1024, kScanMinimum = 16, kScanCreditPerFace = 8;

/// Thrown by a bounded Builder once its deferred islands pass the bound (build_strip_growth_bounded()).
struct OverBound {};

class Builder {
public:
    Builder(Mesh mesh, const StripOptions& options, uint32_t max_deferred = UINT32_MAX)
        : mesh_(std::move(mesh)), opt_(options), max_deferred_(max_deferred) {}

    StripResult run();

private:
    // ---- per-face / per-half-edge state (resized on every split) ----
    Mesh mesh_;
    const StripOptions& opt_;
    uint32_t max_deferred_;                 ///< deferred islands after which run() throws OverBound
    EdgeFlags blocked_;                     ///< per half-edge: constraint edge (never crossed)
    IdVector<FaceId, uint8_t> striped_;     ///< per face: already in the strip
    IdVector<FaceId, RegionId> region_;     ///< per face: region label of an unstriped face
    IdVector<FaceId, FaceId> next_, prev_;  ///< per face: doubly linked strip
    IdVector<FaceId, uint32_t> stamp_;      ///< per face: search marks (stamp_base_ + side)
    uint32_t stamp_base_ = 0;
    IdVector<FaceId, uint8_t> fundamental_;  ///< per face: taken as a fundamental triangle
    IdVector<FaceId, uint32_t> time_;        ///< per face: when it was taken (StripResult::take_time)
    uint32_t clock_ = 0;

    // ---- regions ----
    IdVector<RegionId, uint32_t> region_size_;  ///< unstriped faces per region label
    /// Per region: its first Betti number 2g+b-1 = 1 - chi (chi with vertices counted once per
    /// fan of the region). Bridges split it between the islands, a fundamental triangle lowers
    /// it by one; at 0 the region is a disk and a failed cavity test proves a bridge.
    IdVector<RegionId, long long> region_beta_;
    IdVector<VertexId, uint32_t> vstamp_;  ///< per vertex: marks for chi_of()
    /// Per vertex: striped faces around it, and whether a walk around it meets a boundary or
    /// constraint edge (fixed once constraints are applied; a split's midpoint is interior).
    /// Together they answer the cavity test in O(1): fan_connects().
    IdVector<VertexId, uint32_t> striped_at_;
    IdVector<VertexId, uint8_t> rim_;
    uint32_t vstamp_base_ = 0;
    struct Deferred {
        RegionId region;
        HalfedgeId anchor;  ///< half-edge of a face in the region, facing the striped face it was cut from
        bool done;
    };
    IdVector<DeferredId, Deferred> deferred_;
    IdVector<RegionId, DeferredId> deferred_of_region_;

    FaceId head_, tail_;
    StripStats stats_;
    int last_turn_ = 0;  ///< +1 right, -1 left, 0 none

    // scratch
    std::vector<FaceId> side_[2];
    std::vector<FaceId> stack_[2];
    FaceId searched_;  ///< the face whose islands side_ holds
    /// Faces try_detour() may still scan: it earns kScanCreditPerFace per face taken, so the
    /// scans of failed detours (a split follows each) cost O(F) in all.
    size_t scan_credit_ = 0;
    std::vector<FaceId> scratch_;

    [[nodiscard]] bool passable(HalfedgeId h) const { return !mesh_.is_boundary(h) && !blocked_[h]; }
    [[nodiscard]] bool in_region(FaceId f, RegionId r) const { return f != kNone && !striped_[f] && region_[f] == r; }
    /// Face across h if it is an unstriped face of region r, else kNone.
    [[nodiscard]] FaceId open_neighbor(HalfedgeId h, RegionId r) const {
        if (!passable(h)) return kNone;
        const FaceId g = mesh_.neighbor(h);
        return in_region(g, r) ? g : FaceId();
    }
    [[nodiscard]] uint32_t count_open(FaceId f, RegionId r) const {
        uint32_t n = 0;
        for (const HalfedgeId h : sides(f)) n += open_neighbor(h, r) != kNone;
        return n;
    }

    /// Sizes the per-element arrays to the mesh; room for spare_faces more faces (and their
    /// half-edges and midpoints) is reserved on top.
    void grow_arrays(uint32_t spare_faces = 0);
    long long chi_of(const std::vector<FaceId>& faces, RegionId r);
    void note_fundamental(FaceId f, RegionId r);
    RegionId new_region(uint32_t size);
    void insert_after(FaceId cursor, FaceId f);
    void take(FaceId cursor, FaceId f);
    void count_striped(FaceId f, int delta);
    bool fan_connects_walk(FaceId n, HalfedgeId ha, HalfedgeId hb, RegionId r) const;

    /// Safe: removing the face keeps the region connected. Bridge: it does not. Unknown: the
    /// cheap tests failed and the region has cycles, so only a search can tell.
    enum class Kind { Safe, Bridge, Unknown };
    struct Classification {
        Kind kind = Kind::Safe;
        bool fundamental = false;
        uint32_t small_side = kNone;  ///< 0: island of `a`, 1: of `b`; kNone until searched
        FaceId a, b;                  ///< N's open neighbours other than T
        HalfedgeId ha, hb;            ///< N's half-edges towards a and b
    };
    Classification classify_local(FaceId n, FaceId from, RegionId r) const;
    bool resolve(Classification& c, FaceId n, RegionId r, size_t budget = SIZE_MAX);
    Classification classify(FaceId n, FaceId from, RegionId r) {
        Classification c = classify_local(n, from, r);
        resolve(c, n, r);
        return c;
    }
    bool fan_connects(FaceId n, HalfedgeId ha, HalfedgeId hb, RegionId r) const;
    /// What a bidirectional search found: the sides met (a and b stay connected without n), the
    /// island of a or of b ran out first (it is in side_[0] or side_[1]), or the budget ran out.
    enum class SearchOutcome : uint8_t { Met, IslandOfA, IslandOfB, OverBudget };
    /// choose_safe()'s first search of each candidate: faces popped at most.
    static constexpr size_t kFirstBudget = 256;
    /// n's open neighbours across ha and hb; `rims`: walk the rim loops beside the search.
    SearchOutcome bidirectional_search(FaceId n, HalfedgeId ha, HalfedgeId hb, RegionId r, size_t budget = SIZE_MAX, bool rims = true);
    /// A walk along one rim loop of a region (the half-edges of its faces whose face across is
    /// not open), one rotation step at a time: `at` is the last rim half-edge reached, `rot` the
    /// half-edge the rotation around to(at) has reached (kNone right after `at`).
    struct RimWalk {
        HalfedgeId start, at, rot;
        bool on = false;
    };
    /// One rotation step of w; true when it reached the next rim half-edge (then in w.at).
    bool rim_step(RimWalk& w, RegionId r) const;
    /// The rim walks beside the search (bidirectional_search()): true when they prove that n's
    /// third edge hc and its vertex v (between ha and hb) lie on different rim loops.
    bool rims_differ(RimWalk (&w)[2], FaceId n, VertexId v, HalfedgeId hc, RegionId r) const;

    /// The faces grow() may take next after t: up to three, in the order they are tried.
    struct Candidates {
        FaceId face[3];
        HalfedgeId he[3];               ///< t's half-edge towards face[i]
        int turn[3] = {0, 0, 0};        ///< +1 right, -1 left, 0 (no in-edge)
        uint32_t order[3] = {0, 1, 2};  ///< indices into face[], most preferred first
        uint32_t n = 0;
        bool dest_adjacent = false;  ///< dest is open but was left out (other faces remain)
    };
    Candidates candidates(FaceId t, RegionId region, FaceId dest) const;
    uint32_t choose_safe(const Candidates& c, FaceId t, RegionId region, Classification (&cls)[3]);
    void end_at_dest(FaceId t, RegionId region, FaceId dest);
    void grow(FaceId cursor, RegionId region, FaceId dest);
    RegionId take_bridge(FaceId cursor, FaceId n, RegionId region, FaceId dest, const Classification& c);
    RegionId take_forced(FaceId cursor, FaceId f, RegionId region, FaceId dest);
    void defer(RegionId region, HalfedgeId anchor);
    void absorb(DeferredId record);
    bool absorb_at_tail();
    bool try_detour(RegionId region, FaceId anchor);
    FaceId choose_seed() const;
    [[nodiscard]] bool has_vertex(FaceId f, VertexId v) const { return face_has_vertex(mesh_, f, v); }
    [[nodiscard]] FaceId face_at_vertex(VertexId v, FaceId avoid) const { return singlestrip::face_at_vertex(mesh_, blocked_, v, avoid); }
    VertexId source_, target_;

    // ---- the steps of run() ----
    void prepare();
    std::pair<FaceId, FaceId> choose_ends();
    [[nodiscard]] long long surface_chi() const;
    void mark_piece(FaceId f);
    RegionId relabel_piece(FaceId f);
    RegionId split_at_seed(FaceId seed, FaceId dest, long long chi_all);
    void absorb_all();
    StripResult finish();
    void check_split_budget() const;
    SplitResult split_at(HalfedgeId h);
};

/// The growth builder as a candidate against a strip it must beat (the matching engine's): an
/// empty result once more than `max_deferred` islands were deferred. Each island costs one split
/// unless a detour splices it in, so the bound is set from the splits the candidate may spend.
/// Otherwise as build_strip_growth(). O(F) when it gives up early.
StripResult build_strip_growth_bounded(Mesh mesh, const StripOptions& options, uint32_t max_deferred);

}  // namespace singlestrip::growth
