// singlestrip — matching engine: faces left short at the junctions of forced chains (faces with
// two passable edges, which every strip crosses through), e.g. one-face-wide corridors between
// holes. No 2-factor exists there; splitting the chain faces between two short faces gives one.
// docs/algorithm.md, "The matching engine", step 6.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "bucket_queue.hpp"
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

// Alternating paths whose unmatched steps may run along forced chains, grown from every short
// face at once as a forest, fewest chain faces first (each costs two triangles): from an outer
// face x (a root, or the mate z of a face y reached) across an unmatched edge and along its
// chain to a face y. A short y, or an outer face of another tree, ends a path: the two trees'
// paths and the step between them. No blossoms (what it misses goes to the fallback). Searches
// from one root at a time spent their budgets on one side of a mesh whose short faces lay on
// both (random diagonals with a hole every 10 x 10 cells, 1M faces: 20 faces left short, the
// growth fallback, +12.6% in 6 s). Applying a path changes the matching near it, so each is
// checked against the matching of the moment first; passes repeat while they find paths.
bool MatchingBuilder::augment_all_through_chains(const std::vector<FaceId>& short_faces) {
    constexpr size_t kChainWork = 16;  // faces walked per mesh face, all passes together
    size_t left = 0;
    for (FaceId u : short_faces) left += quota_[u];
    const size_t keep = ends_free() ? 2 : 0;
    const size_t most = kChainWork * size_t{mesh_.num_faces()};
    ChainForest cf;
    for (FaceId u : short_faces)
        if (quota_[u] > 0 && !vlink_[u]) cf.roots.push_back(u);
    size_t work = 0;
    bool any = false;
    while (left > keep && cf.roots.size() >= 2 && work < most) {
        if (chain_forest_pass(cf, left, keep, work, most) == 0) break;
        any = true;
        std::erase_if(cf.roots, [&](FaceId f) { return quota_[f] == 0; });
        std::sort(cf.roots.begin(), cf.roots.end());
        cf.roots.erase(std::unique(cf.roots.begin(), cf.roots.end()), cf.roots.end());
    }
    return any;
}

// One pass of the chain forest from cf.roots; the paths it applies (their count) end two short
// faces each, and the faces their local searches leave short join cf.roots for the next pass.
uint32_t MatchingBuilder::chain_forest_pass(ChainForest& cf, size_t& left, size_t keep, size_t& work, size_t most) {
    cf.tree.assign(mesh_.num_faces(), 0);
    cf.reach.assign(mesh_.num_faces(), kNone);
    cf.steps.clear();
    cf.alive.assign(cf.roots.size(), 1);
    // Ties in push order, so that every tree grows (by root order, one tree took the mesh).
    struct Entry {
        int cost;
        uint32_t tree;
        StepId at;  ///< kNone: the tree's root
        [[nodiscard]] int key() const { return cost; }
    };
    BucketQueue<Entry> queue;
    for (uint32_t t = 0; t < cf.roots.size(); ++t) {
        cf.tree[cf.roots[t]] = t + 1;
        queue.push({0, t, kNone});
    }
    uint32_t found = 0;
    std::vector<std::pair<uint32_t, StepId>> grown;
    while (!queue.empty() && left > keep && work < most) {
        const Entry e = queue.pop();
        ++work;
        if (!cf.alive[e.tree]) continue;
        if (e.at != kNone && cf.steps[e.at.idx()].z == kNone) {
            const size_t before = cf.roots.size();
            if (apply_chain_meeting(cf, e.at, work)) ++found, left = left - std::min<size_t>(left, 2) + (cf.roots.size() - before);
            continue;
        }
        grown.clear();
        chain_grow(cf, e.at, static_cast<uint32_t>(e.cost), e.tree, grown, work);
        for (const auto& [cost, s] : grown) queue.push({static_cast<int>(cost), e.tree, s});
    }
    return found;
}

// Grows tree t from its outer face reached by step `at` (its root when kNone): the steps added,
// with their costs, go to `out`, those meeting another tree or a short face among them.
void MatchingBuilder::chain_grow(ChainForest& cf, StepId at, uint32_t cost, uint32_t t, std::vector<std::pair<uint32_t, StepId>>& out,
                                 size_t& work) {
    const FaceId x = at == kNone ? cf.roots[t] : cf.steps[at.idx()].z;
    for (HalfedgeId h : sides(x)) {
        if (!passable(h) || matched_[h]) continue;
        uint32_t faces = 0;
        const FaceId y = chain_end(h, faces);
        work += faces;
        if (y == kNone || vlink_[y] || cf.tree[y] == t + 1) continue;
        FaceId z = kNone;
        uint32_t beyond = 0;  // the other tree's chain faces from its root to y
        if (const uint32_t ty = cf.tree[y]; ty != 0) {
            const StepId r = cf.reach[y];
            if (!cf.alive[ty - 1] || (r != kNone && cf.steps[r.idx()].y == y)) continue;  // ended, or y is inner
            beyond = r == kNone ? 0 : cf.steps[r.idx()].cost;
        } else if (quota_[y] == 0) {
            z = mate_of(y);
            if (z == kNone || cf.tree[z] != 0) continue;
        }
        const StepId s(static_cast<uint32_t>(cf.steps.size()));
        cf.steps.push_back({at, h, faces, cost + faces, t, x, y, z});
        if (z != kNone) cf.tree[y] = cf.tree[z] = t + 1, cf.reach[y] = cf.reach[z] = s;
        out.emplace_back(cost + faces + beyond, s);
    }
}

// Step s still holds in the matching of the moment: h unmatched from x along the same chain to
// y, and x short (a root) or the mate of the step before's y.
bool MatchingBuilder::chain_step_holds(const ChainForest& cf, StepId s) const {
    const ChainStep& st = cf.steps[s.idx()];
    if (Mesh::face(st.h) != st.x || !passable(st.h) || matched_[st.h] || vlink_[st.y]) return false;
    if (st.prev == kNone) {
        if (quota_[st.x] == 0) return false;
    } else if (const FaceId py = cf.steps[st.prev.idx()].y; quota_[py] != 0 || mate_of(py) != st.x) {
        return false;
    }
    uint32_t faces = 0;
    return chain_end(st.h, faces) == st.y && faces == st.faces;
}

// The tree path to meeting step m, the step, and the other tree's path from its y: applied when
// every step still holds (true), else both trees end (a later pass grows them anew).
bool MatchingBuilder::apply_chain_meeting(ChainForest& cf, StepId m, size_t& work) {
    const ChainStep meet = cf.steps[m.idx()];
    const uint32_t ty = cf.tree[meet.y];
    if (ty != 0 && !cf.alive[ty - 1]) return false;  // the other tree's path was applied
    cf.alive[meet.tree] = 0;
    if (ty != 0) cf.alive[ty - 1] = 0;
    std::vector<ChainStep> path;  // the meeting step first: the one whose y keeps its matched edge
    bool holds = ty == 0 || cf.reach[meet.y] == kNone ? quota_[meet.y] > 0 : true;
    auto take = [&](StepId from) {
        for (StepId s = from; s != kNone && holds; s = cf.steps[s.idx()].prev) {
            holds = chain_step_holds(cf, s);
            work += 1 + cf.steps[s.idx()].faces;
            path.push_back(cf.steps[s.idx()]);
        }
    };
    take(m);
    if (ty != 0 && cf.reach[meet.y] != kNone) {
        const FaceId ry = cf.steps[cf.reach[meet.y].idx()].y;
        holds = holds && quota_[ry] == 0 && mate_of(ry) == meet.y;
        take(cf.reach[meet.y]);
    }
    if (!holds) return false;
    for (FaceId f : apply_chain_path(path)) cf.roots.push_back(f);
    cf.tree.resize(mesh_.num_faces(), 0);
    cf.reach.resize(mesh_.num_faces(), kNone);
    return true;
}

// The face matched to y (kNone if y has no matched edge).
FaceId MatchingBuilder::mate_of(FaceId y) const {
    for (HalfedgeId e : sides(y))
        if (matched_[e]) return across(e);
    return kNone;
}

// Applies an alternating path whose first step meets its end: every other step's y gives up its
// matched edge, then each step is matched or its chain split (split_chain), and the faces the
// splits leave wanting are matched locally; returns those still short.
std::vector<FaceId> MatchingBuilder::apply_chain_path(const std::vector<ChainStep>& path) {
    for (size_t i = 1; i < path.size(); ++i) {
        const FaceId y = path[i].y;
        for (HalfedgeId e : sides(y))
            if (matched_[e]) {
                ++quota_[y];
                ++quota_[across(e)];
                set_pair(matched_, e, 0);
            }
    }
    std::vector<FaceId> wanting;
    for (const ChainStep& st : path) {
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
    aug_step_.resize(nf);
    for (FaceId f : wanting)
        while (quota_[f] > 0 && augment_from(f, ch_stamp_, ++ch_mark_, 64)) {
        }
    std::erase_if(wanting, [&](FaceId f) { return quota_[f] == 0 || vlink_[f]; });
    return wanting;
}

}  // namespace singlestrip::matching
