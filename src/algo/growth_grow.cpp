// singlestrip — the growth builder's main loop: the candidates after the current face in turn
// order, the first safe one taken, or a bridge taken with one island deferred.
#include <cstdint>
#include <string>
#include <utility>

#include "growth_builder.hpp"
#include "singlestrip/errors.hpp"

namespace singlestrip::growth {

// The open neighbours of t in `region`, dest left out while anything else is left, in the order
// they are tried.
Builder::Candidates Builder::candidates(FaceId t, RegionId region, FaceId dest) const {
    Candidates c;
    for (const HalfedgeId h : sides(t)) {
        const FaceId g = open_neighbor(h, region);
        if (g == kNone) continue;
        if (g == dest && region_size_[region] > 1) {
            c.dest_adjacent = true;
            continue;
        }
        c.face[c.n] = g;
        c.he[c.n++] = h;
    }
    // Turn of each candidate relative to the in-edge of t.
    const FaceId pv = prev_[t];
    const HalfedgeId hin = pv == kNone ? HalfedgeId() : mesh_.shared_halfedge(t, pv);
    for (uint32_t i = 0; i < c.n; ++i) c.turn[i] = hin == kNone ? 0 : (c.he[i] == Mesh::next(hin) ? +1 : -1);
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
uint32_t Builder::choose_safe(const Candidates& c, FaceId t, RegionId region, Classification (&cls)[3]) {
    // Cheap tests first for every candidate considered; searches only if none passes.
    // Without greedy turns only the preferred neighbour is considered (paper, Algorithm 1).
    const uint32_t considered = opt_.greedy ? c.n : 1;
    uint32_t chosen = kNone;
    // In preference order: safe by the cheap tests, or by a search of bounded cost (O(1)
    // per step, so a long search is never spent on a face we might not take). The cheap
    // tests of a candidate run only when the ones before it are not safe (a cavity test
    // around a high-valence vertex is not O(1) either).
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
void Builder::end_at_dest(FaceId t, RegionId region, FaceId dest) {
    const Classification c = classify(dest, t, region);
    if (c.kind == Kind::Bridge) {
        const HalfedgeId large_he = c.small_side == 0 ? c.hb : c.ha;
        const RegionId large = take_bridge(t, dest, region, kNone, c);
        defer(large, mesh_.twin(large_he));
        return;
    }
    if (c.fundamental) note_fundamental(dest, region);
    take(t, dest);
    defer(region, mesh_.twin(c.ha));
}

// Grows the strip after `cursor` through region `region`; if dest != kNone the region must end
// with dest (it is spliced before an existing strip face).
void Builder::grow(FaceId cursor, RegionId region, FaceId dest) {
    FaceId t = cursor;
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
            const FaceId n = c.face[c.order[chosen]];
            if (cls[chosen].fundamental) note_fundamental(n, region);
            last_turn_ = c.turn[c.order[chosen]];
            take(t, n);
            t = n;
            continue;
        }
        // Every candidate considered is a bridge: take the first anyway, continue into one island
        // and defer the other (relabelled, so R stays connected: invariant G).
        const FaceId n = c.face[c.order[0]];
        last_turn_ = c.turn[c.order[0]];
        resolve(cls[0], n, region);
        region = take_bridge(t, n, region, dest, cls[0]);
        t = n;
    }
}

// Takes n (a bridge of `region`, classified in c) after cursor: the island holding dest, or the
// larger one, stays the region to grow; the other is relabelled if needed and deferred,
// anchored at n. Returns the region to continue in.
RegionId Builder::take_bridge(FaceId cursor, FaceId n, RegionId region, FaceId dest, const Classification& c) {
    const uint32_t small = c.small_side;
    const HalfedgeId small_he = small == 0 ? c.ha : c.hb;
    const HalfedgeId large_he = small == 0 ? c.hb : c.ha;
    take(cursor, n);  // first, so that n counts in neither island below
    const uint32_t small_size = static_cast<uint32_t>(side_[small].size());
    const long long beta_small = 1 - chi_of(side_[small], region);
    const RegionId r_small = new_region(small_size);
    region_size_[region] -= small_size;
    region_beta_[r_small] = beta_small;
    region_beta_[region] -= beta_small;
    if (region_beta_[region] < 0 || beta_small < 0)
        throw InternalError("strip builder: negative cycle count after a bridge (topology tracking broken)");
    bool dest_in_small = false;
    for (const FaceId f : side_[small]) {
        region_[f] = r_small;
        dest_in_small |= f == dest;
    }
    if (dest_in_small) {
        defer(region, mesh_.twin(large_he));
        return r_small;
    }
    defer(r_small, mesh_.twin(small_he));
    return region;
}

// Takes f after cursor when f is forced (no choice): if f is a bridge of its region, the island
// without dest is deferred. Returns the region to continue in.
RegionId Builder::take_forced(FaceId cursor, FaceId f, RegionId region, FaceId dest) {
    const Classification c = classify(f, cursor, region);
    if (c.kind == Kind::Bridge) return take_bridge(cursor, f, region, dest, c);
    if (c.fundamental) note_fundamental(f, region);
    take(cursor, f);
    return region;
}

}  // namespace singlestrip::growth
