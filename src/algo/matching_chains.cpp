// singlestrip — matching engine: faces left short at the junctions of forced chains (faces with
// two passable edges, which every strip crosses through), e.g. one-face-wide corridors between
// holes. No 2-factor exists there; splitting the chain faces between two short faces gives one.
// docs/algorithm.md, "The matching engine", step 6.
#include <algorithm>
#include <cstdint>
#include <queue>
#include <vector>

#include "matching_builder.hpp"

namespace singlestrip::matching {

// From a face across h, over faces with two passable edges (a forced chain), to the first other
// face, which it returns (kNone past F steps: a chain closing on itself); `faces` counts the
// chain. Pinned faces end a chain and are never split.
FaceId MatchingBuilder::chain_end(HalfedgeId h, uint32_t& faces) const {
    faces = 0;
    for (FaceId g = across(h); faces <= mesh_.num_faces(); g = across(h), ++faces) {
        if (degree(g) != 2 || vlink_[g]) return g;
        const HalfedgeId in = mesh_.twin(h);
        for (HalfedgeId e : sides(g))
            if (e != in && passable(e)) h = e;
    }
    return kNone;
}

// Splits every edge of the chain from short face u across h but the last. Each split moves the
// missing matched edge one face along: the two children of the face being left pair up across
// their sibling edge, the child holding the next chain edge wants one, and the last of them meets
// the short face at the far end. +2 triangles per chain face. (Splitting every other edge also
// gives a perfect matching, but each split leaves a ring of four whose two exits are matched: a
// loop of its own, and its join costs the split saved.)
void MatchingBuilder::split_chain(HalfedgeId h, uint32_t faces, std::vector<FaceId>* wanting) {
    for (uint32_t i = 0; i < faces; ++i) {
        const FaceId g = across(h);
        const HalfedgeId in = mesh_.twin(h);
        FaceId next = kNone;
        for (HalfedgeId e : sides(g))
            if (e != in && passable(e)) next = across(e);
        const SplitResult sr = split(h);
        requota(sr);
        if (wanting)
            for (FaceId c : {sr.f_a, sr.f_b, sr.g_a, sr.g_b})
                if (quota_[c] > 0) wanting->push_back(c);
        for (FaceId c : {sr.g_a, sr.g_b})
            for (HalfedgeId e : sides(c))
                if (passable(e) && across(e) == next) h = e;
    }
}

// Faces still short whose neighbours start forced chains (junctions of one-face-wide
// corridors: no 2-factor, and no split beside one face helps, by parity) are paired along the
// shortest chains first, and each pair's chain is split (split_chain). False if none paired.
bool MatchingBuilder::split_along_chains(const std::vector<FaceId>& short_faces) {
    struct Candidate {
        uint32_t faces;
        FaceId u, w;
        HalfedgeId h;
    };
    std::vector<Candidate> found;
    for (FaceId u : short_faces) {
        if (quota_[u] == 0 || vlink_[u]) continue;
        for (HalfedgeId h : sides(u)) {
            if (!passable(h) || matched_[h]) continue;
            uint32_t faces = 0;
            const FaceId w = chain_end(h, faces);
            if (w != kNone && w != u && quota_[w] > 0 && !vlink_[w] && faces > 0 && u < w) found.push_back({faces, u, w, h});
        }
    }
    std::stable_sort(found.begin(), found.end(), [](const Candidate& a, const Candidate& b) { return a.faces < b.faces; });
    IdVector<FaceId, uint8_t> paired(mesh_.num_faces(), 0);
    std::vector<Candidate> chosen;
    for (const Candidate& c : found) {
        if (paired[c.u] || paired[c.w]) continue;
        paired[c.u] = paired[c.w] = 1;
        chosen.push_back(c);
    }
    // Two faces left short become the strip's two ends (settle_leftovers()): without pins, the
    // longest chain is left unsplit when it would pair the last two.
    size_t left = 0;
    for (FaceId u : short_faces) left += quota_[u] > 0 && !paired[u];
    if (left == 0 && ends_free() && !chosen.empty()) chosen.pop_back();
    // Only chain faces and the near end are split, so the other chosen chains stay as found.
    for (const Candidate& c : chosen) split_chain(c.h, c.faces, nullptr);
    return !chosen.empty();
}

// An alternating path from short face u whose unmatched steps may run along forced chains: from
// an outer face (u, or the mate of a face reached) across an unmatched edge and along its chain to
// a face y; a short y ends the path, else y's mate is the next outer face. Fewest chain faces
// first (each costs two triangles), within `budget` outer faces; no blossoms (a heuristic: what
// it misses goes to the fallback). Applying it unmatches each y from its mate and then matches
// or splits (split_chain) each step; the faces the splits leave wanting are matched locally.
bool MatchingBuilder::augment_through_chains(FaceId u, size_t budget) {
    ch_stamp_.resize(mesh_.num_faces(), 0);
    ++ch_mark_;
    std::vector<ChainStep> steps;
    using Entry = std::pair<uint32_t, StepId>;  // (chain faces so far, step, kNone for u)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    queue.push({0, kNone});
    ch_stamp_[u] = ch_mark_;
    for (size_t popped = 0; !queue.empty() && popped < budget; ++popped) {
        const auto [cost, at] = queue.top();
        queue.pop();
        const FaceId x = at == kNone ? u : mate_of(steps[at.idx()].y);
        if (at != kNone && quota_[steps[at.idx()].y] > 0) return apply_chain_path(steps, at), true;
        for (HalfedgeId h : sides(x)) {
            if (!passable(h) || matched_[h]) continue;
            uint32_t faces = 0;
            const FaceId y = chain_end(h, faces);
            if (y == kNone || vlink_[y] || ch_stamp_[y] == ch_mark_) continue;
            const bool end = quota_[y] > 0;
            if (!end && (mate_of(y) == kNone || ch_stamp_[mate_of(y)] == ch_mark_)) continue;
            ch_stamp_[y] = ch_mark_;
            if (!end) ch_stamp_[mate_of(y)] = ch_mark_;
            steps.push_back({at, h, faces, y});
            queue.push({cost + faces, StepId(static_cast<uint32_t>(steps.size() - 1))});
        }
    }
    return false;
}

// Short faces that no chain joins to another short face directly: alternating paths through
// chains, until two are left (the strip's ends; none with pins). A search that fails spends its
// whole budget, one that succeeds rarely more than a few hundred steps: after kGiveUp failures
// in a row the rest are left to the splits (a disk with a hole every 200 faces: 3,408 searches,
// none found a path, 40% of the engine's time).
bool MatchingBuilder::augment_all_through_chains(const std::vector<FaceId>& short_faces) {
    constexpr uint32_t kGiveUp = 32;
    size_t left = 0;
    for (FaceId u : short_faces) left += quota_[u];
    const size_t keep = ends_free() ? 2 : 0;
    const size_t budget = std::max<size_t>(1024, 16 * size_t{mesh_.num_faces()} / std::max<size_t>(1, short_faces.size()));
    bool any = false;
    uint32_t failed = 0;
    for (FaceId u : short_faces) {
        if (left <= keep || failed == kGiveUp) break;
        if (quota_[u] == 0 || vlink_[u]) continue;
        if (!augment_through_chains(u, budget)) {
            ++failed;
            continue;
        }
        failed = 0;
        any = true;
        left -= std::min<size_t>(left, 2);
    }
    return any;
}

// The face matched to y (kNone if y has no matched edge).
FaceId MatchingBuilder::mate_of(FaceId y) const {
    for (HalfedgeId e : sides(y))
        if (matched_[e]) return across(e);
    return kNone;
}

void MatchingBuilder::apply_chain_path(const std::vector<ChainStep>& steps, StepId last) {
    std::vector<StepId> path;
    for (StepId s = last; s != kNone; s = steps[s.idx()].prev) path.push_back(s);
    // Every y but the last gives up its matched edge: it and its mate want one again.
    for (StepId s : path) {
        const FaceId y = steps[s.idx()].y;
        if (s == last) continue;
        for (HalfedgeId e : sides(y))
            if (matched_[e]) {
                ++quota_[y];
                ++quota_[across(e)];
                set_pair(matched_, e, 0);
            }
    }
    std::vector<FaceId> wanting;
    for (StepId s : path) {
        const ChainStep& st = steps[s.idx()];
        if (st.faces > 0) {
            split_chain(st.h, st.faces, &wanting);
            wanting.push_back(st.y);
            continue;
        }
        set_pair(matched_, st.h, 1);
        --quota_[Mesh::face(st.h)];
        --quota_[st.y];
    }
    // The chain searches' stamps serve (their marks only grow): an array of F per path made the
    // paths of a comb of 8000 spiked teeth quadratic (1.7 s at 120K faces).
    const uint32_t nf = mesh_.num_faces();
    ch_stamp_.resize(nf, 0);
    aug_prev_.resize(nf);
    aug_matched_.resize(nf);
    aug_unmatched_.resize(nf);
    for (FaceId f : wanting)
        while (quota_[f] > 0 && augment_from(f, ch_stamp_, ++ch_mark_, 64)) {
        }
}

}  // namespace singlestrip::matching
