// singlestrip — the growth builder's deferred islands spliced back into the strip: free at
// the tail, by a zero-cost detour between two consecutive faces, else by one midpoint split.
#include <algorithm>
#include <cstdint>
#include <string>

#include "growth_builder.hpp"
#include "singlestrip/errors.hpp"

namespace singlestrip::growth {

// Splices a deferred region into the strip at the face it was cut from (its host): the host and
// the region's anchor face are split at the midpoint of their shared edge; the host's two
// children keep the host's in- and out-edges, the anchor's two children become the first and
// last face of the region's own strip, which is grown between them.
void Builder::absorb(DeferredId record) {
    Deferred& d = deferred_[record];
    d.done = true;
    const RegionId region = d.region;
    const HalfedgeId ha = d.anchor;  // in the anchor face
    const HalfedgeId hh = mesh_.twin(ha);
    if (hh == kNone) throw InternalError("strip builder: deferred region lost its host");
    const FaceId host = Mesh::face(hh);
    const FaceId anchor = Mesh::face(ha);
    if (!striped_[host] || !in_region(anchor, region))
        throw InternalError("strip builder: deferred region " + std::to_string(region.idx()) + " has a bad anchor");
    if (try_detour(region, anchor)) return;
    if (host == tail_ && target_ == kNone) {  // free: the strip simply continues into the region
        const RegionId r = take_forced(host, anchor, region, kNone);
        grow(anchor, r, kNone);
        return;
    }
    const FaceId p = prev_[host], n = next_[host];
    const SplitResult s = split_at(hh);
    region_[s.f_b] = kNone;
    fundamental_[s.f_b] = fundamental_[host];
    time_[s.f_b] = time_[host];
    region_[s.g_a] = region;
    ++region_size_[region];
    // c0 keeps the host's in-edge, c1 its out-edge; a0 is the anchor child beside c0.
    bool fa_first;
    if (p != kNone)
        fa_first = mesh_.shared_halfedge(s.f_a, p) != kNone;
    else if (n != kNone)
        fa_first = mesh_.shared_halfedge(s.f_a, n) == kNone;
    else
        fa_first = source_ == kNone || has_vertex(s.f_a, source_);
    const FaceId c0 = fa_first ? s.f_a : s.f_b, c1 = fa_first ? s.f_b : s.f_a;
    const FaceId a0 = fa_first ? s.g_a : s.g_b, a1 = fa_first ? s.g_b : s.g_a;
    // Host slot (index f_a) becomes c0 -> c1.
    if (fa_first)
        insert_after(s.f_a, s.f_b);
    else
        insert_after(p, s.f_b);  // p == kNone inserts at the head
    // Normally the region goes between the children: c0 -> a0 ... a1 -> c1. At the ends of the
    // strip the region may instead go first (a1 ... a0 -> c0 -> c1) or last (c0 -> c1 -> a1 ... a0)
    // so that the first face keeps the source vertex and the last face the target (§5.2).
    FaceId cursor = c0, first = a0, last = a1;
    if (p == kNone && source_ != kNone && !has_vertex(c0, source_)) {
        cursor = kNone;
        first = a1;
        last = a0;
    } else if (n == kNone && target_ != kNone && !has_vertex(c1, target_)) {
        cursor = c1;
        first = a1;
        last = a0;
    }
    const RegionId r = take_forced(cursor, first, region, last);
    grow(first, r, last);
}

// Zero-cost splice: if two consecutive strip faces x -> y touch the region at faces r1 (beside x)
// and r2 (beside y), with r1 != r2 unless the region is that single face, the region's own
// strip r1 ... r2 goes between them and no split is needed. O(min(region size, kScanLimit)).
bool Builder::try_detour(RegionId region, FaceId anchor) {
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
        const FaceId f = scratch_[i];
        for (const HalfedgeId h : sides(f)) {
            const FaceId g = open_neighbor(h, region);
            if (g != kNone && stamp_[g] != stamp_base_) {
                stamp_[g] = stamp_base_;
                scratch_.push_back(g);
            }
        }
    }
    scan_credit_ -= std::min(scan_credit_, scratch_.size());
    const bool single = region_size_[region] == 1;
    for (const FaceId r1 : scratch_) {
        // Unrolled as the other loops over a face's sides (GCC's size estimate falls just short).
#pragma GCC unroll 3
        for (const HalfedgeId h : sides(r1)) {
            if (!passable(h)) continue;
            const FaceId x = mesh_.neighbor(h);
            if (!striped_[x]) continue;
            const FaceId y = next_[x];
            if (y == kNone) continue;
            for (const HalfedgeId hy : sides(y)) {
                if (!passable(hy)) continue;
                const FaceId r2 = mesh_.neighbor(hy);
                if (!in_region(r2, region) || (r2 == r1) != single) continue;
                ++stats_.detours;
                const RegionId r = take_forced(x, r1, region, single ? FaceId() : r2);
                grow(r1, r, single ? FaceId() : r2);
                return true;
            }
        }
    }
    return false;
}

bool Builder::absorb_at_tail() {
    for (const HalfedgeId h : sides(tail_)) {
        if (!passable(h)) continue;
        const FaceId g = mesh_.neighbor(h);
        if (striped_[g]) continue;
        const DeferredId rec = deferred_of_region_[region_[g]];
        if (rec == kNone || deferred_[rec].done) continue;
        deferred_[rec].anchor = mesh_.twin(h);
        absorb(rec);
        return true;
    }
    return false;
}

// Splices the deferred regions: first any that touch the tail (free), then the rest, newest
// first (absorbing one may defer more).
void Builder::absorb_all() {
    for (;;) {
        if (target_ == kNone && absorb_at_tail()) continue;
        DeferredId rec;
        while (!deferred_.empty()) {
            if (!deferred_.back().done) {
                rec = DeferredId(static_cast<uint32_t>(deferred_.size() - 1));
                break;
            }
            deferred_.pop_back();
        }
        if (rec == kNone) break;
        absorb(rec);
    }
}

}  // namespace singlestrip::growth
