// singlestrip — matching engine: augmenting paths from all short faces at once (step 6).
//
// One breadth-first forest grows from every short face in lockstep; where an outer face of one
// tree meets an outer face (or the root) of another across an unmatched edge, the two root paths
// and that edge form an augmenting path, and both trees stop for the rest of the pass. A pass
// costs O(F) at most however many faces are short, where one search per face (Edmonds from a
// single root) costs about the area between short faces each: the last faces of a large mesh are
// far apart (bunny00: 44 faces, 240 us each). Blossoms are not followed: what a pass leaves goes
// on to the exact single-root searches (docs/algorithm.md, step 6).
//
// The fewest-swap forest (forest_pass_fewest()) grows the same trees best first by the swaps
// their paths settle, as augment_fewest_swaps() does for one root: where single-root searches
// give up, it settles the rest along the pattern instead of across it.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "matching_builder.hpp"

namespace singlestrip::matching {

// Flips the tree path from outer face z back to its root: each step's edge into the inner face
// becomes matched, the inner face's edge to z unmatched.
void MatchingBuilder::flip_to_root(FaceId z) {
    for (; aug_prev_[z] != kNone; z = aug_prev_[z]) {
        set_matched(aug_matched(z), 0);
        set_matched(aug_unmatched(z), 1);
    }
}

// One pass of the forest over the faces in `roots` (each with quota > 0); stamp values from
// base on are this pass's (2t: outer face of tree t, 2t + 1: inner). Returns the paths flipped.
uint32_t MatchingBuilder::forest_pass(const std::vector<FaceId>& roots, IdVector<FaceId, uint32_t>& stamp, uint32_t base, size_t& work) {
    std::vector<FaceId>& queue = aug_queue_;
    queue.clear();
    std::vector<uint8_t> dead(roots.size(), 0);
    auto tree = [&](FaceId f) { return stamp[f] >= base ? (stamp[f] - base) / 2 : UINT32_MAX; };
    for (uint32_t t = 0; t < roots.size(); ++t) {
        stamp[roots[t]] = base + 2 * t;
        aug_prev_[roots[t]] = kNone;
        queue.push_back(roots[t]);
    }
    uint32_t found = 0;
    for (size_t head = 0; head < queue.size(); ++head) {
        const FaceId x = queue[head];
        const uint32_t t = tree(x);
        if (dead[t]) continue;
        ++work;
        for (HalfedgeId h : sides(x)) {
            if (!passable(h) || matched_[h]) continue;
            const FaceId y = across(h);
            const uint32_t ty = tree(y);
            if (ty != UINT32_MAX) {
                if (ty == t || dead[ty] || (stamp[y] - base) % 2 != 0) continue;
                set_pair(matched_, h, 1);  // outer meets outer: root(t) ~ x - y ~ root(ty)
                flip_to_root(x), flip_to_root(y);
                --quota_[roots[t]], --quota_[roots[ty]];
                dead[t] = dead[ty] = 1;
                ++found;
                break;
            }
            stamp[y] = base + 2 * t + 1;
            for (HalfedgeId e : sides(y)) {
                if (!matched_[e]) continue;
                const FaceId z = across(e);
                if (tree(z) != UINT32_MAX) continue;
                stamp[z] = base + 2 * t;
                aug_prev_[z] = x;
                set_aug_step(z, h, e);
                queue.push_back(z);
            }
        }
    }
    return found;
}

// Forest passes while they flip paths for at least one root in kForestYield and their work stays
// within kForestWork faces per face. A pass that settles fewer met mostly structural shortfalls
// (colour imbalance), which parity splits settle: on a 10M grid with a hole every 70 x 70 cells,
// 17 passes of 4.9M faces each settled 138, 69, 46, ... 5 of ~5,000 roots, a third of the stage.
void MatchingBuilder::augment_forest(std::vector<FaceId>& short_faces, IdVector<FaceId, uint32_t>& stamp, uint32_t& mark) {
    size_t work = 0;
    while (short_faces.size() >= 2 && work < kForestWork * size_t{mesh_.num_faces()}) {
        const uint32_t base = mark + 1, roots = static_cast<uint32_t>(short_faces.size());
        mark += 2 * roots;
        const uint32_t found = forest_pass(short_faces, stamp, base, work);
        std::erase_if(short_faces, [&](FaceId f) { return quota_[f] == 0; });
        if (found == 0 || found * kForestYield < roots) break;
    }
}

// forest_pass() best first by swaps (step_swaps(); a step may remove some, so the order is no
// exact shortest path): an outer face x meeting outer face y of another tree across h is queued
// as an end costing the two tree paths plus the step, and flipped when it is the cheapest entry.
// Swap-removing chains make costs negative, and the search would wander along them: once an end
// is queued, kEndWait more expansions at most, then every queued end is taken cheapest first. A
// pass stops once a quarter of its trees are matched: the rest grew among the matched trees'
// faces, and a new pass gives them those faces back (docs/algorithm.md, step 6).
uint32_t MatchingBuilder::forest_pass_fewest(const std::vector<FaceId>& roots, IdVector<FaceId, uint32_t>& stamp, uint32_t base,
                                             size_t& work) {
    BucketQueue<AugEntry>&heap = aug_buckets_, &ends = aug_end_buckets_;
    heap.clear(), ends.clear();
    std::vector<uint8_t> dead(roots.size(), 0);
    auto tree = [&](FaceId f) { return stamp[f] >= base ? (stamp[f] - base) / 2 : UINT32_MAX; };
    for (uint32_t t = 0; t < roots.size(); ++t) {
        stamp[roots[t]] = base + 2 * t;
        aug_prev_[roots[t]] = kNone;
        aug_swaps_[roots[t]] = 0;
        heap.push({0, roots[t], kNone});
    }
    const size_t limit = kFewestWork * size_t{mesh_.num_faces()};
    enum class Ends { None, Waiting, Taking, Late } mode = Ends::None;
    size_t since = 0;                // work when the first end of the wait was queued
    uint32_t found = 0, before = 0;  // paths flipped; before the ends were taken
    while ((!heap.empty() || !ends.empty()) && work < limit && 4 * found < roots.size()) {
        if (mode == Ends::Waiting && work - since > kEndWait) mode = Ends::Taking, before = found;
        if (mode == Ends::Taking && ends.empty()) mode = found > before ? Ends::None : Ends::Late;  // Late: none was live
        const bool take = !ends.empty() && (mode == Ends::Taking || heap.empty() || ends.top().swaps <= heap.top().swaps);
        const AugEntry top = (take ? ends : heap).pop();
        const FaceId x = top.x;
        const uint32_t t = tree(x);
        if (dead[t]) continue;
        if (top.end != kNone) {  // root(t) ~ x - y ~ root(ty)
            const uint32_t ty = tree(across(top.end));
            if (dead[ty]) continue;
            set_matched(top.end, 1);
            flip_to_root(x), flip_to_root(across(top.end));
            --quota_[roots[t]], --quota_[roots[ty]];
            dead[t] = dead[ty] = 1;
            ++found;
            if (mode != Ends::Taking) mode = Ends::None;
            continue;
        }
        ++work;
        const bool root = aug_prev_[x] == kNone;
        for (HalfedgeId h : sides(x)) {
            if (!passable(h) || matched_[h]) continue;
            const FaceId y = across(h);
            const uint32_t ty = tree(y);
            if (ty != UINT32_MAX) {  // an outer face of another live tree: an end
                if (ty == t || dead[ty] || (stamp[y] - base) % 2 != 0) continue;
                ends.push({top.swaps + step_swaps(x, h, root, true) + aug_swaps_[y], x, h});
                if (mode == Ends::None) mode = Ends::Waiting, since = work;
                continue;
            }
            stamp[y] = base + 2 * t + 1;
            const int swaps = top.swaps + step_swaps(x, h, root, false);
            for (HalfedgeId e : sides(y)) {
                if (!matched_[e]) continue;
                const FaceId z = across(e);
                if (tree(z) != UINT32_MAX) continue;
                stamp[z] = base + 2 * t;
                aug_prev_[z] = x, set_aug_step(z, h, e);
                aug_swaps_[z] = swaps;
                heap.push({swaps, z, kNone});
            }
        }
    }
    return found;
}

// Fewest-swap forest passes while they flip paths and their work stays within kFewestWork faces
// per face.
void MatchingBuilder::augment_forest_fewest(std::vector<FaceId>& short_faces, IdVector<FaceId, uint32_t>& stamp, uint32_t& mark) {
    size_t work = 0;
    aug_swaps_.assign(mesh_.num_faces(), 0);
    while (short_faces.size() >= 2 && work < kFewestWork * size_t{mesh_.num_faces()}) {
        const uint32_t base = mark + 1;
        mark += 2 * static_cast<uint32_t>(short_faces.size());
        const uint32_t found = forest_pass_fewest(short_faces, stamp, base, work);
        std::erase_if(short_faces, [&](FaceId f) { return quota_[f] == 0; });
        if (found == 0) break;
    }
    aug_swaps_.reset();
}

}  // namespace singlestrip::matching
