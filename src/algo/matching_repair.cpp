// singlestrip — matching engine: faces the greedy matching left short. Augmenting paths first,
// then Edmonds' blossom algorithm (Boost.Graph) on balls of faces around them, then midpoint splits
// beside the faces still short (colour imbalance of grid-like meshes with holes).
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "matching_builder.hpp"
#include "singlestrip/errors.hpp"

namespace singlestrip::matching {

namespace {

/// Initial matching for boost::matching(): the one already in the mate map.
template <typename Graph, typename MateMap>
struct keep_matching {
    static void find_matching(const Graph&, MateMap) {}
};

}  // namespace

bool MatchingBuilder::augment_from(uint32_t u, std::vector<uint32_t>& stamp, uint32_t mark, size_t budget) {
    std::vector<uint32_t>& queue = aug_queue_;
    queue.assign(1, u);
    stamp[u] = mark;
    for (size_t head = 0; head < queue.size() && queue.size() < budget; ++head) {
        const uint32_t x = queue[head];
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t h = 3 * x + k;
            if (!passable(h) || matched_[h]) continue;
            const uint32_t y = mesh_.neighbor(HalfedgeId(h)).idx();
            if (stamp[y] == mark) continue;
            stamp[y] = mark;
            if (quota_[y] > 0) {  // flip the path back to u
                set_pair(matched_, h, 1);
                for (uint32_t z = x; z != u; z = aug_prev_[z]) {
                    set_pair(matched_, aug_matched_[z], 0);
                    set_pair(matched_, aug_unmatched_[z], 1);
                }
                --quota_[u];
                --quota_[y];
                return true;
            }
            for (uint32_t j = 0; j < 3; ++j) {
                const uint32_t e = 3 * y + j;
                if (!matched_[e]) continue;
                const uint32_t z = mesh_.neighbor(HalfedgeId(e)).idx();
                if (stamp[z] == mark) continue;
                stamp[z] = mark;
                aug_prev_[z] = x;
                aug_unmatched_[z] = h;
                aug_matched_[z] = e;
                queue.push_back(z);
            }
        }
    }
    return false;
}

// Maximum matching (Edmonds' blossoms, Boost.Graph) on the faces within `ball` faces of each
// short face, starting from the current matching; faces matched across the ball's rim stay as
// they are. Where a perfect matching exists (closed surfaces) this finds the alternating paths
// through odd cycles that the plain search misses. True if a ball was cut off by its size (a
// larger one might still help); otherwise the matching is maximum where faces are still short.
bool MatchingBuilder::repair_in_balls(std::vector<uint32_t>& short_faces, size_t ball) {
    bool truncated = false;
    ball_local_.assign(mesh_.num_faces(), kNone);
    if (ball > kBallOneByOne) {  // large balls overlap: one search over their union
        truncated = repair_ball(short_faces, ball);
    } else {
        // A ball that was not cut off is the whole component: Edmonds left its matching maximum,
        // so the component's other short faces need no ball of their own.
        std::vector<uint8_t>& whole = ball_whole_;
        whole.assign(mesh_.num_faces(), 0);
        for (uint32_t s : std::vector<uint32_t>(short_faces))
            if (quota_[s] > 0 && !whole[s]) truncated |= repair_ball({s}, ball, &whole);
    }
    std::erase_if(short_faces, [&](uint32_t f) { return quota_[f] == 0; });
    return truncated;
}

// Edmonds on the union of the balls around `short_faces` (repair_in_balls()); true if a ball was
// cut off by its size.
bool MatchingBuilder::repair_ball(const std::vector<uint32_t>& short_faces, size_t ball, std::vector<uint8_t>* whole) {
    std::vector<uint32_t>& local = ball_local_;  // kNone outside the ball, on entry and exit
    std::vector<uint32_t> faces, queue;
    bool truncated = false;
    for (uint32_t s : short_faces) {
        if (local[s] != kNone) continue;
        queue.assign(1, s);
        local[s] = 0;
        for (size_t head = 0; head < queue.size() && queue.size() < ball; ++head)
            for (uint32_t h = 3 * queue[head]; h < 3 * queue[head] + 3; ++h) {
                if (!passable(h)) continue;
                const uint32_t g = mesh_.neighbor(HalfedgeId(h)).idx();
                if (local[g] == kNone) local[g] = 0, queue.push_back(g);
            }
        faces.insert(faces.end(), queue.begin(), queue.end());
        truncated |= queue.size() >= ball;
    }
    if (whole && !truncated)
        for (uint32_t f : faces) (*whole)[f] = 1;
    // Keep faces that take matched edges and whose partners are all inside too. A pinned face
    // takes two: it gets two copies, each linked to all its neighbours (b-matching to matching).
    auto want = [&](uint32_t f) { return std::max(0, static_cast<int>(degree(f)) - (2 - vlink_[f])); };
    std::vector<uint32_t> kept, owner;
    for (uint32_t f : faces) local[f] = want(f) > 0 ? 0 : kNone;
    for (uint32_t f : faces) {
        if (local[f] == kNone) continue;
        bool inside = true;
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h)
            if (matched_[h] && local[mesh_.neighbor(HalfedgeId(h)).idx()] == kNone) inside = false;
        if (inside) kept.push_back(f);
    }
    for (uint32_t f : faces) local[f] = kNone;
    for (uint32_t f : kept) {
        local[f] = static_cast<uint32_t>(owner.size());
        for (int c = 0; c < want(f); ++c) owner.push_back(f);
    }
    // Edges kept in vectors and the graph built in one go: Boost's default edge list allocates
    // per edge.
    using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property, boost::no_property,
                                        boost::no_property, boost::vecS>;
    using Vertex = boost::graph_traits<Graph>::vertex_descriptor;
    const Vertex null = boost::graph_traits<Graph>::null_vertex();
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    std::vector<Vertex> mate(owner.size(), null);
    auto free_copy = [&](uint32_t f) {
        for (uint32_t v = local[f]; v < local[f] + static_cast<uint32_t>(want(f)); ++v)
            if (mate[v] == null) return v;
        return uint32_t{kNone};
    };
    for (uint32_t f : kept)
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) {
            if (!passable(h)) continue;
            const uint32_t g = mesh_.neighbor(HalfedgeId(h)).idx();
            if (local[g] == kNone || local[g] <= local[f]) continue;
            for (int c = 0; c < want(f); ++c)
                for (int d = 0; d < want(g); ++d) edges.emplace_back(local[f] + c, local[g] + d);
            const uint32_t vf = free_copy(f), vg = free_copy(g);
            if (matched_[h] && vf != kNone && vg != kNone) mate[vf] = vg, mate[vg] = vf;
        }
    const Graph graph(edges.begin(), edges.end(), owner.size());
    boost::matching<Graph, Vertex*, boost::property_map<Graph, boost::vertex_index_t>::type, boost::edmonds_augmenting_path_finder,
                    keep_matching, boost::no_matching_verifier>(graph, mate.data(), boost::get(boost::vertex_index, graph));
    for (uint32_t f : kept)
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) matched_[h] = 0;
    for (uint32_t v = 0; v < owner.size(); ++v) {
        if (mate[v] == null || mate[v] < v) continue;
        const uint32_t f = owner[v], g = owner[mate[v]];
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h)
            if (passable(h) && !matched_[h] && mesh_.neighbor(HalfedgeId(h)).idx() == g) {
                set_pair(matched_, h, 1);
                break;
            }
    }
    for (uint32_t f : kept) {
        const int have = matched_[3 * f] + matched_[3 * f + 1] + matched_[3 * f + 2];
        quota_[f] = static_cast<uint8_t>(std::max(0, want(f) - have));
    }
    for (uint32_t f : kept) local[f] = kNone;
    return truncated;
}

// Faces the matching left short: local augmenting searches with a growing budget; what is still
// short drops crossed edges instead (each drop leaves a path end).
void MatchingBuilder::repair_short(std::vector<uint32_t>& short_faces) {
    const uint32_t nf = mesh_.num_faces();
    std::vector<uint32_t> stamp(nf, 0);
    aug_prev_.assign(nf, kNone);
    aug_matched_.assign(nf, kNone);
    aug_unmatched_.assign(nf, kNone);
    uint32_t mark = 0;
    for (size_t budget : {size_t{64}, size_t{1024}}) {
        for (uint32_t f : short_faces)
            while (quota_[f] > 0 && augment_from(f, stamp, ++mark, budget)) {
            }
        std::erase_if(short_faces, [&](uint32_t f) { return quota_[f] == 0; });
    }
    // Edmonds from each face alone, bounded so that all of them touch O(F) faces: a face it
    // proves hopeless needs no ball. No upper cap: the last few short faces of a large mesh can
    // be far apart (genus-20 surface, 1.7M faces: two faces past any ball, growth fallback 2.6 s;
    // unbounded, matched in 1.4 s).
    // (An augmenting path never ends at a hopeless face: reversed, it would start there.)
    const size_t budget = std::max<size_t>(16 * size_t{nf} / std::max<size_t>(1, short_faces.size()), 1024);
    std::vector<uint32_t> hopeless;
    std::erase_if(short_faces, [&](uint32_t f) {
        if (quota_[f] == 0) return true;
        const Search r = in_blossom_graph(f) ? blossom_search(f, budget) : Search::Unknown;
        if (r == Search::NoPath) hopeless.push_back(f);
        return r != Search::Unknown;
    });
    std::erase_if(short_faces, [&](uint32_t f) { return quota_[f] == 0; });
    // Edmonds on balls: each face's own, then one search over the union of larger balls (it
    // costs O(ball) per augmenting path).
    // Larger balls only for few faces: many faces still short are structural (no 2-factor).
    for (size_t ball : {size_t{512}, kBallOneByOne, size_t{32768}}) {
        const size_t most = ball == 512 ? SIZE_MAX : ball == kBallOneByOne ? 64 : 16;
        if (short_faces.empty() || short_faces.size() > most) break;
        if (ball > kBallOneByOne) {  // a long plain search first: far cheaper than Edmonds on the union
            for (uint32_t f : short_faces)
                while (quota_[f] > 0 && augment_from(f, stamp, ++mark, size_t{1} << 17)) {
                }
            std::erase_if(short_faces, [&](uint32_t f) { return quota_[f] == 0; });
            if (short_faces.empty()) break;
        }
        if (!repair_in_balls(short_faces, ball)) break;
    }
    short_faces.insert(short_faces.end(), hopeless.begin(), hopeless.end());
}

// Splits an edge of short face u, towards a face with three passable edges if it can;
// the four children get their quotas anew. The ring of four children has two sibling edges, so
// the dual graph gains odd cycles there: a region whose faces alternate like a chessboard (grids
// with holes) has no 2-factor when its two colours differ in number; one split beside a short
// face lets an augmenting path through. False if u has no such edge.
bool MatchingBuilder::split_beside(uint32_t u) {
    uint32_t best = kNone;
    for (uint32_t h = 3 * u; h < 3 * u + 3; ++h) {
        if (!passable(h) || matched_[h]) continue;
        const uint32_t g = mesh_.neighbor(HalfedgeId(h)).idx();
        if (best == kNone || degree(g) == 3) best = h;
    }
    if (best == kNone) return false;
    requota(split(best));
    return true;
}

void MatchingBuilder::requota(const SplitResult& sr) {
    for (uint32_t f : {sr.f_a.idx(), sr.f_b.idx(), sr.g_a.idx(), sr.g_b.idx()}) {
        const int have = matched_[3 * f] + matched_[3 * f + 1] + matched_[3 * f + 2];
        quota_[f] = static_cast<uint8_t>(std::max(0, static_cast<int>(degree(f)) - (2 - vlink_[f]) - have));
    }
}

void MatchingBuilder::settle_leftovers() {
    std::vector<uint32_t> short_faces;
    auto collect = [&] {
        short_faces.clear();
        for (uint32_t f = 0; f < mesh_.num_faces(); ++f)
            if (quota_[f] > 0) short_faces.push_back(f);
    };
    collect();
    repair_short(short_faces);
    if (!short_faces.empty()) {  // the growth builder may have to finish (fallback())
        pre_merge_ = true;
        pre_merge_splits_ = stats_.splits;
    }
    chain_splits_ = !short_faces.empty() && split_along_chains(short_faces);
    if (chain_splits_) {
        collect();
        repair_short(short_faces);
    }
    // Then alternating paths whose steps may run along forced chains (split), leaving two.
    if (short_faces.size() > (num_pins_ == 0 ? 2 : 0) && augment_all_through_chains(short_faces)) {
        chain_splits_ = true;
        collect();
        repair_short(short_faces);
    }
    if (chain_splits_) stats_.parity_splits += 1;
    // Still short: the matching is maximum there; splits beside short faces, while they help.
    for (uint32_t round = 0; round < 4 && !short_faces.empty(); ++round) {
        const size_t before = short_faces.size();
        bool any = false;
        for (uint32_t u : std::vector<uint32_t>(short_faces))
            if (quota_[u] > 0) any |= split_beside(u);
        if (!any) break;
        collect();
        repair_short(short_faces);
        stats_.parity_splits += 1;
        if (short_faces.size() >= before) break;
    }
    if (opt_.validate_each_split) check_matching();
    const uint32_t nf = mesh_.num_faces();
    for (uint32_t h = 0; h < 3 * nf; ++h) used_[h] = passable(h) && !matched_[h];
    for (uint32_t f : short_faces)
        for (uint32_t k = 0; k < 3 && quota_[f] > 0; ++k)
            if (used_[3 * f + k]) {
                set_pair(used_, 3 * f + k, 0);
                --quota_[f];
            }
    stats_.unmatched = static_cast<uint32_t>(short_faces.size());
    if (short_faces.empty() && !chain_splits_) pre_merge_ = false;  // loops only: no fallback ahead
    release_repair_scratch();
}

// The searches' per-face arrays (up to 28 bytes per face) are not used after the matching: free
// them before the joins build theirs (issue 17's peak memory).
void MatchingBuilder::release_repair_scratch() {
    auto release = [](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); };
    release(aug_prev_), release(aug_matched_), release(aug_unmatched_), release(aug_queue_);
    release(bl_stamp_), release(bl_seen_), release(bl_base_), release(bl_parent_), release(bl_label_);
    release(bl_touched_), release(bl_queue_), release(bl_merge_);
    release(ball_local_), release(ball_whole_);
}

// The matching's invariant: a face has exactly its wanted matched edges less its quota, all
// passable and symmetric across twins.
void MatchingBuilder::check_matching() const {
    for (uint32_t f = 0; f < mesh_.num_faces(); ++f) {
        int have = 0;
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) {
            if (!matched_[h]) continue;
            if (!passable(h) || !matched_[twin_of(h)])
                throw InternalError("matching engine: face " + std::to_string(f) + " is matched across a closed or one-sided edge");
            ++have;
        }
        const int want = std::max(0, static_cast<int>(degree(f)) - (2 - vlink_[f]));
        if (have + quota_[f] != want)
            throw InternalError("matching engine: face " + std::to_string(f) + " has " + std::to_string(have) +
                                " matched edges and quota " + std::to_string(quota_[f]) + " but wants " + std::to_string(want));
    }
}

}  // namespace singlestrip::matching
