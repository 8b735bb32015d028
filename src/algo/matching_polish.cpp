// singlestrip — matching engine, opt-in (StripOptions::polish): fewer swaps in the settled matching.
// For each face with a swap on one of its crossed edges, the face and its mate are unmatched and
// matched again by the fewest-swap augmenting path (augment_fewest_swaps()); the new path is kept
// only when the swaps counted on the faces around it drop. docs/algorithm.md, step 6.
#include <utility>
#include <vector>

#include "matching_builder.hpp"
#include "singlestrip/errors.hpp"

namespace singlestrip::matching {

// Swaps on the crossed edges of the faces in `faces` (each edge once), as the loops would have
// them (swap_test() on the current matching).
int MatchingBuilder::swaps_among(const std::vector<FaceId>& faces, const IdVector<FaceId, uint32_t>& in_set, uint32_t mark) const {
    auto crossed = [&](HalfedgeId a) { return passable(a) && !matched_[a]; };
    int swaps = 0;
    for (FaceId f : faces)
        for (HalfedgeId a : sides(f)) {
            if (!crossed(a)) continue;
            const FaceId g = across(a);
            if (in_set[g] != mark || f < g) swaps += swap_test(a, crossed);
        }
    return swaps;
}

// One attempt at face f (matched across m to g): rematch f by the fewest-swap path, which must end
// at g (the only other face short); keep it if the swaps around the path drop. True if kept.
bool MatchingBuilder::polish_at(FaceId f, HalfedgeId m, PolishScratch& s) {
    const FaceId g = across(m);
    set_matched(m, 0);
    ++quota_[f], ++quota_[g];
    if (!augment_fewest_swaps(f, s.stamp, ++s.mark, kPolishBudget) || quota_[g] != 0) {
        if (quota_[f] == 0) throw InternalError("matching engine: a polishing path ended away from its face's mate");
        set_matched(m, 1);
        --quota_[f], --quota_[g];
        return false;
    }
    // The path from g back to f: g's new matched edge, then each step's pair of edges.
    s.steps.clear(), s.faces.assign(1, g);
    ++s.set_mark;
    HalfedgeId gh = kNone;
    for (HalfedgeId a : sides(g))
        if (matched_[a]) gh = a;
    if (gh == m) return false;  // the path is m itself: the matching is as it was
    s.steps.push_back({gh, kNone});
    for (FaceId z = across(gh); z != f; z = aug_prev_[z]) {
        s.faces.push_back(z), s.faces.push_back(Mesh::face(aug_matched(z)));
        s.steps.push_back({aug_unmatched(z), aug_matched(z)});
    }
    s.faces.push_back(f);
    for (FaceId q : s.faces) s.in_set[q] = s.set_mark;
    for (size_t i = 0, n = s.faces.size(); i < n; ++i)
        for (HalfedgeId a : sides(s.faces[i]))
            if (passable(a) && s.in_set[across(a)] != s.set_mark) s.in_set[across(a)] = s.set_mark, s.faces.push_back(across(a));
    const int after = swaps_among(s.faces, s.in_set, s.set_mark);
    auto apply = [&](bool new_path) {
        for (const auto& [on, off] : s.steps) {
            set_matched(on, new_path);
            if (off != kNone) set_matched(off, !new_path);
        }
        set_matched(m, !new_path);
    };
    apply(false);
    if (after >= swaps_among(s.faces, s.in_set, s.set_mark)) return false;
    apply(true);
    return true;
}

// Every face with a swap, once, in face order: O(kPolishBudget) each, O(F) in all.
void MatchingBuilder::polish() {
    const uint32_t nf = mesh_.num_faces();
    // Faces still short take no part: with their quotas hidden, every path must end at the
    // unmatched mate (F29 came from a path that ended at another short face).
    std::vector<std::pair<FaceId, uint8_t>> hidden;
    for (FaceId f : mesh_.faces())
        if (quota_[f] > 0) hidden.emplace_back(f, quota_[f]), quota_[f] = 0;
    PolishScratch s;
    s.stamp.assign(nf, 0), s.in_set.assign(nf, 0);
    aug_prev_.assign(nf, kNone), aug_step_.assign(nf, 0);
    cross_on(true);  // augment_fewest_swaps() reads it
    auto crossed = [&](HalfedgeId a) { return passable(a) && !matched_[a]; };
    for (FaceId f : mesh_.faces()) {
        if (quota_[f] != 0 || vlink_[f] || degree(f) != 3) continue;
        int swaps = 0;
        HalfedgeId m = kNone;
        for (HalfedgeId a : sides(f)) {
            if (matched_[a]) m = a;
            if (crossed(a)) swaps += swap_test(a, crossed);
        }
        if (swaps == 0 || m == kNone || vlink_[across(m)] || degree(across(m)) != 3) continue;
        if (polish_at(f, m, s)) ++stats_.polished;
    }
    cross_on(false);
    for (const auto& [f, q] : hidden) quota_[f] = q;
}

}  // namespace singlestrip::matching
