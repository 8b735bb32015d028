// singlestrip — matching engine: faces the greedy matching left short. Augmenting paths first,
// then Edmonds' blossom algorithm (Boost.Graph) on balls of faces around them, then midpoint splits
// beside the faces still short (colour imbalance of grid-like meshes with holes).
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>

#include <algorithm>
#include <array>
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

bool MatchingBuilder::augment_from(FaceId u, IdVector<FaceId, uint32_t>& stamp, uint32_t mark, size_t budget) {
    std::vector<FaceId>& queue = aug_queue_;
    queue.assign(1, u);
    stamp[u] = mark;
    for (size_t head = 0; head < queue.size() && queue.size() < budget; ++head) {
        const FaceId x = queue[head];
        for (HalfedgeId h : sides(x)) {
            if (!passable(h) || matched_[h]) continue;
            const FaceId y = across(h);
            if (stamp[y] == mark) continue;
            stamp[y] = mark;
            if (quota_[y] > 0) {  // flip the path back to u
                set_pair(matched_, h, 1);
                for (FaceId z = x; z != u; z = aug_prev_[z]) {
                    set_pair(matched_, aug_matched(z), 0);
                    set_pair(matched_, aug_unmatched(z), 1);
                }
                --quota_[u];
                --quota_[y];
                return true;
            }
            for (HalfedgeId e : sides(y)) {
                if (!matched_[e]) continue;
                const FaceId z = across(e);
                if (stamp[z] == mark) continue;
                stamp[z] = mark;
                aug_prev_[z] = x;
                set_aug_step(z, h, e);
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
bool MatchingBuilder::repair_in_balls(std::vector<FaceId>& short_faces, size_t ball) {
    bool truncated = false;
    ball_local_.assign(mesh_.num_faces(), kNone);
    if (ball > kBallOneByOne) {  // large balls overlap: one search over their union
        truncated = repair_ball(short_faces, ball);
    } else {
        // A ball that was not cut off is the whole component: Edmonds left its matching maximum,
        // so the component's other short faces need no ball of their own.
        IdVector<FaceId, uint8_t>& whole = ball_whole_;
        whole.assign(mesh_.num_faces(), 0);
        // The balls together reach at most kBallWork faces per face of the mesh: on a disk with a
        // hole every 200 faces, 42 balls of 8192 faces (of 9639) found nothing in 53 ms.
        size_t work = 0;
        for (FaceId s : std::vector<FaceId>(short_faces))
            if (quota_[s] > 0 && !whole[s] && work < kBallWork * size_t{mesh_.num_faces()}) {
                truncated |= repair_ball({s}, ball, &whole);
                work += ball_reached_;
            }
    }
    // A maximum matching of the ball may leave a face short that was not (a pinned face wants
    // two matched edges, and gives one up to match two short faces): it is short from now on.
    short_faces.insert(short_faces.end(), ball_short_.begin(), ball_short_.end());
    ball_short_.clear();
    std::erase_if(short_faces, [&](FaceId f) { return quota_[f] == 0; });
    return truncated;
}

// Edmonds on the union of the balls around `short_faces` (repair_in_balls()); true if a ball was
// cut off by its size.
bool MatchingBuilder::repair_ball(const std::vector<FaceId>& short_faces, size_t ball, IdVector<FaceId, uint8_t>* whole) {
    // A face's first graph vertex; kNone outside the ball, on entry and exit. While the ball is
    // gathered, BallVertex(0) only marks a face as reached.
    IdVector<FaceId, BallVertex>& local = ball_local_;
    std::vector<FaceId> faces, queue;
    bool truncated = false;
    for (FaceId s : short_faces) {
        if (local[s] != kNone) continue;
        queue.assign(1, s);
        local[s] = BallVertex(0);
        for (size_t head = 0; head < queue.size() && queue.size() < ball; ++head)
            for (HalfedgeId h : sides(queue[head])) {
                if (!passable(h)) continue;
                const FaceId g = across(h);
                if (local[g] == kNone) local[g] = BallVertex(0), queue.push_back(g);
            }
        faces.insert(faces.end(), queue.begin(), queue.end());
        truncated |= queue.size() >= ball;
    }
    ball_reached_ = faces.size();
    if (whole && !truncated)
        for (FaceId f : faces) (*whole)[f] = 1;
    // Keep faces that take matched edges and whose partners are all inside too. A pinned face
    // takes two: it gets two copies, each linked to all its neighbours (b-matching to matching).
    auto want = [&](FaceId f) { return std::max(0, static_cast<int>(degree(f)) - (2 - vlink_[f])); };
    std::vector<FaceId> kept, owner;
    for (FaceId f : faces) local[f] = want(f) > 0 ? BallVertex(0) : BallVertex();
    for (FaceId f : faces) {
        if (local[f] == kNone) continue;
        bool inside = true;
        for (HalfedgeId h : sides(f))
            if (matched_[h] && local[across(h)] == kNone) inside = false;
        if (inside) kept.push_back(f);
    }
    for (FaceId f : faces) local[f] = kNone;
    for (FaceId f : kept) {
        local[f] = BallVertex(static_cast<uint32_t>(owner.size()));
        for (int c = 0; c < want(f); ++c) owner.push_back(f);
    }
    match_ball(kept, owner, want);
    for (FaceId f : kept) local[f] = kNone;
    return truncated;
}

// Edmonds on the graph of the kept faces of a ball: `owner` maps each graph vertex to its face,
// ball_local_ each face to its first vertex; the face's want(f) copies follow it.
template <class Want>
void MatchingBuilder::match_ball(const std::vector<FaceId>& kept, const std::vector<FaceId>& owner, const Want& want) {
    const IdVector<FaceId, BallVertex>& local = ball_local_;
    // Edges kept in vectors and the graph built in one go: Boost's default edge list allocates
    // per edge.
    using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property, boost::no_property,
                                        boost::no_property, boost::vecS>;
    using Vertex = boost::graph_traits<Graph>::vertex_descriptor;
    const Vertex null = boost::graph_traits<Graph>::null_vertex();
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    std::vector<Vertex> mate(owner.size(), null);
    auto free_copy = [&](FaceId f) {
        for (uint32_t v = local[f].idx(); v < local[f].idx() + static_cast<uint32_t>(want(f)); ++v)
            if (mate[v] == null) return BallVertex(v);
        return BallVertex();
    };
    for (FaceId f : kept)
        for (HalfedgeId h : sides(f)) {
            if (!passable(h)) continue;
            const FaceId g = across(h);
            if (local[g] == kNone || local[g] <= local[f]) continue;
            for (int c = 0; c < want(f); ++c)
                for (int d = 0; d < want(g); ++d) edges.emplace_back(local[f].idx() + c, local[g].idx() + d);
            const BallVertex vf = free_copy(f), vg = free_copy(g);
            if (matched_[h] && vf != kNone && vg != kNone) mate[vf.idx()] = vg.idx(), mate[vg.idx()] = vf.idx();
        }
    const Graph graph(edges.begin(), edges.end(), owner.size());
    boost::matching<Graph, Vertex*, boost::property_map<Graph, boost::vertex_index_t>::type, boost::edmonds_augmenting_path_finder,
                    keep_matching, boost::no_matching_verifier>(graph, mate.data(), boost::get(boost::vertex_index, graph));
    for (FaceId f : kept)
        for (HalfedgeId h : sides(f)) matched_[h] = 0;
    for (uint32_t v = 0; v < owner.size(); ++v) {
        if (mate[v] == null || mate[v] < v) continue;
        const FaceId f = owner[v], g = owner[mate[v]];
        for (HalfedgeId h : sides(f))
            if (passable(h) && !matched_[h] && across(h) == g) {
                set_pair(matched_, h, 1);
                break;
            }
    }
    for (FaceId f : kept) {
        const uint8_t before = quota_[f];
        quota_[f] = static_cast<uint8_t>(std::max(0, want(f) - num_matched(f)));
        if (before == 0 && quota_[f] > 0) ball_short_.push_back(f);
    }
}

// Swaps the flip of one step of an augmenting path settles (see augment_fewest_swaps()): x takes h
// as its matched edge, y (across h) too; x's previous partner keeps the edge it took before.
// Counted by swap_test() on the crossed edges before and after, around x and y only.
int MatchingBuilder::step_swaps(FaceId x, HalfedgeId h, bool x_is_root, bool y_is_end) const {
    const HalfedgeId t = mesh_.twin(h);
    const FaceId y = Mesh::face(t);
    const HalfedgeId yp_in = x_is_root ? kNone : mesh_.twin(aug_unmatched(x));  // x's previous partner's matched edge
    const FaceId yp = x_is_root ? FaceId(kNone) : Mesh::face(yp_in);
    // A face's crossed edges before the flip (its cross_ byte: bits 0-2, passable 3-5, vlink 6)
    // and after: x, y and yp cross every passable edge but their new matched one.
    auto new_mask = [&](FaceId f, uint32_t bits) {
        const HalfedgeId m = f == x ? h : f == y ? t : f == yp ? yp_in : HalfedgeId(kNone);
        if (m == kNone) return bits;
        return (bits & ~7u) | (((bits >> 3) & 7u) & ~(1u << Mesh::index_in_face(m)));
    };
    static constexpr std::array<uint8_t, 8> kOnes = {0, 1, 1, 2, 1, 2, 2, 3};
    auto links = [](uint32_t bits) { return kOnes[bits & 7u] + (bits >> 6); };
    // swap_test() of crossed edge a between faces with bytes ba (a's face) and bb (its twin's).
    auto sw = [&](HalfedgeId a, uint32_t ba, uint32_t bb) {
        const uint32_t ia = Mesh::index_in_face(a), ib = Mesh::index_in_face(mesh_.twin(a));
        if (!((ba >> ia) & 1) || links(ba) != 2 || links(bb) != 2) return 0;
        return static_cast<int>(((ba >> ((ia + 2) % 3)) & 1) == ((bb >> ((ib + 1) % 3)) & 1));
    };
    const uint32_t ox = cross_[x], oy = cross_[y], nx = new_mask(x, ox), ny = new_mask(y, oy);
    int d = -sw(h, ox, oy);
    // Around f: its passable edges but `skip` (all of them, or only the crossed ones).
    auto around = [&](FaceId f, HalfedgeId skip, uint32_t of, uint32_t nf, bool all) {
        for (uint32_t k = 0; k < 3; ++k) {
            const HalfedgeId a = Mesh::halfedge(f, k);
            if (a == skip || !((of >> (k + 3)) & 1) || !(all || ((of >> k) & 1))) continue;
            const uint32_t og = cross_[across(a)];
            d += sw(a, nf, new_mask(across(a), og)) - sw(a, of, og);
        }
    };
    around(x, h, ox, nx, true);
    around(y, t, oy, ny, y_is_end);
    return d;
}

// augment_from() taking the path that adds the fewest swaps: best first by the swaps its steps
// settle (step_swaps(); a step may remove some, so this is no exact shortest path), each face
// reached once, from the cheapest face popped before it. A plain breadth-first path through a
// patterned region breaks the pattern along its whole length (turbine.off: 78 short faces added
// 894 swaps); this one follows the pattern where it can (docs/algorithm.md, step 6).
bool MatchingBuilder::augment_fewest_swaps(FaceId u, IdVector<FaceId, uint32_t>& stamp, uint32_t mark, size_t budget) {
    BucketQueue<AugEntry>& heap = aug_buckets_;
    heap.clear();
    heap.push(AugEntry{0, u, kNone});
    stamp[u] = mark;
    aug_prev_[u] = kNone;
    size_t reached = 1;
    while (!heap.empty() && reached < budget) {
        const AugEntry top = heap.pop();
        const FaceId x = top.x;
        if (top.end != kNone) {  // flip the path back to u
            const HalfedgeId h = top.end;
            const FaceId y = across(h);
            if (quota_[y] == 0) continue;
            set_matched(h, 1);
            for (FaceId z = x; z != u; z = aug_prev_[z]) {
                set_matched(aug_matched(z), 0);
                set_matched(aug_unmatched(z), 1);
            }
            --quota_[u];
            --quota_[y];
            return true;
        }
        for (HalfedgeId h : sides(x)) {
            if (!((cross_[x] >> Mesh::index_in_face(h)) & 1)) continue;  // not passable, or matched
            const FaceId y = across(h);
            if (stamp[y] == mark) continue;
            if (quota_[y] > 0) {
                heap.push({top.swaps + step_swaps(x, h, x == u, true), x, h});
                continue;
            }
            stamp[y] = mark;
            const int swaps = top.swaps + step_swaps(x, h, x == u, false);
            for (HalfedgeId e : sides(y)) {
                if (!matched_[e]) continue;
                const FaceId z = across(e);
                if (stamp[z] == mark) continue;
                stamp[z] = mark;
                aug_prev_[z] = x;
                set_aug_step(z, h, e);
                heap.push({swaps, z, kNone});
                ++reached;
            }
        }
    }
    return false;
}

// Faces the matching left short: local augmenting searches with a growing budget; what is still
// short drops crossed edges instead (each drop leaves a path end).
void MatchingBuilder::repair_short(std::vector<FaceId>& short_faces) {
    if (short_faces.empty()) return;
    const uint32_t nf = mesh_.num_faces();
    // The plain searches' and Edmonds' per-face arrays (9 and 17 bytes a face) are never held
    // together: together they were the matching engine's memory peak (genus-20 surface, 2M faces).
    IdVector<FaceId, uint32_t> stamp;
    auto plain_arrays = [&](bool on) {
        if (on) {
            stamp.assign(nf, 0), aug_prev_.assign(nf, kNone), aug_step_.assign(nf, 0);
        } else {
            stamp.reset(), aug_prev_.reset(), aug_step_.reset();
        }
    };
    plain_arrays(true);
    cross_on(!plain_paths_);
    uint32_t mark = 0;
    size_t settled = 0;  // by the last round
    for (size_t budget : {size_t{64}, size_t{1024}}) {
        for (FaceId f : short_faces)
            while (quota_[f] > 0 &&
                   (plain_paths_ ? augment_from(f, stamp, ++mark, budget) : augment_fewest_swaps(f, stamp, ++mark, budget))) {
            }
        settled = std::erase_if(short_faces, [&](FaceId f) { return quota_[f] == 0; });
    }
    // The faces single searches could not settle within budget, all at once (matching_forest.cpp):
    // fewer swaps than exact searches give (libcgal-demo: GL indices -0.64%). Only for a few
    // faces, and not when the round left more faces short than it settled: many faces left are
    // mostly structural, with no path to find, and each pass expands much of the mesh whatever
    // the number of trees (a disk with a hole every 200 faces, 1M: 3,408 left and 90 settled,
    // one pass of 474K faces found nothing; after its splits 454 left, 7 passes of 100-190K faces).
    constexpr size_t kForestMost = 64;  // libcgal-demo: at most 44 left where the forest runs
    if (!plain_paths_ && short_faces.size() >= 2 && short_faces.size() <= kForestMost && settled >= short_faces.size())
        augment_forest_fewest(short_faces, stamp, mark);
    cross_on(false);
    plain_arrays(false);
    if (short_faces.empty()) return;
    // Edmonds from each face alone, bounded so that all of them touch O(F) faces: a face it
    // proves hopeless needs no ball. No upper cap: the last few short faces of a large mesh can
    // be far apart (genus-20 surface, 1.7M faces: two faces past any ball, growth fallback 2.6 s;
    // unbounded, matched in 1.4 s).
    // (An augmenting path never ends at a hopeless face: reversed, it would start there.)
    const size_t budget = std::max<size_t>(16 * size_t{nf} / std::max<size_t>(1, short_faces.size()), 1024);
    // After 32 searches in a row ran out of budget the rest are taken as such too: on a disk with
    // a hole every 200 faces all 3,408 did (a sixth of the stage), on libcgal-demo none did.
    constexpr uint32_t kGiveUp = 32;
    std::vector<FaceId> hopeless, exhausted;
    uint32_t in_a_row = 0;
    std::erase_if(short_faces, [&](FaceId f) {
        if (quota_[f] == 0) return true;
        Search r = Search::Exhausted;
        if (in_a_row < kGiveUp) r = in_blossom_graph(f) ? blossom_search(f, budget) : Search::Unknown;
        in_a_row = r == Search::Exhausted ? in_a_row + 1 : 0;
        if (r == Search::NoPath) hopeless.push_back(f);
        if (r == Search::Exhausted) exhausted.push_back(f);
        return r != Search::Unknown;
    });
    std::erase_if(short_faces, [&](FaceId f) { return quota_[f] == 0; });
    release_blossom_arrays();
    if (exhausted.size() >= 2) {
        plain_arrays(true);
        augment_forest(exhausted, stamp, mark);
    }
    // Edmonds on balls: each face's own, then one search over the union of larger balls (it
    // costs O(ball) per augmenting path).
    // Larger balls only for few faces: many faces still short are structural (no 2-factor).
    // A face whose exact search reached more faces than a 512-face ball holds skips that ball
    // (a disk with a hole every 200 faces: 3,408 balls, none found a path, a third of the stage).
    for (size_t ball : {size_t{512}, kBallOneByOne, size_t{32768}}) {
        if (ball > 512) {
            std::erase_if(exhausted, [&](FaceId f) { return quota_[f] == 0; });
            short_faces.insert(short_faces.end(), exhausted.begin(), exhausted.end());
            exhausted.clear();
        }
        const size_t most = ball == 512 ? SIZE_MAX : ball == kBallOneByOne ? 64 : 16;
        if (ball == 512 && short_faces.empty()) continue;
        if (short_faces.empty() || short_faces.size() > most) break;
        if (ball > kBallOneByOne) {  // a long plain search first: far cheaper than Edmonds on the union
            if (stamp.empty()) plain_arrays(true);
            for (FaceId f : short_faces)
                while (quota_[f] > 0 && augment_from(f, stamp, ++mark, size_t{1} << 17)) {
                }
            std::erase_if(short_faces, [&](FaceId f) { return quota_[f] == 0; });
            if (short_faces.empty()) break;
        }
        if (!repair_in_balls(short_faces, ball) && exhausted.empty()) break;
    }
    plain_arrays(false);
    short_faces.insert(short_faces.end(), exhausted.begin(), exhausted.end());
    short_faces.insert(short_faces.end(), hopeless.begin(), hopeless.end());
}

// Splits an edge of short face u, towards a face with three passable edges if it can;
// the four children get their quotas anew. The ring of four children has two sibling edges, so
// the dual graph gains odd cycles there: a region whose faces alternate like a chessboard (grids
// with holes) has no 2-factor when its two colours differ in number; one split beside a short
// face lets an augmenting path through. False if u has no such edge.
bool MatchingBuilder::split_beside(FaceId u) {
    HalfedgeId best = kNone;
    for (HalfedgeId h : sides(u)) {
        if (!passable(h) || matched_[h]) continue;
        if (best == kNone || degree(across(h)) == 3) best = h;
    }
    if (best == kNone) return false;
    requota(split(best));
    return true;
}

void MatchingBuilder::requota(const SplitResult& sr) {
    for (FaceId f : {sr.f_a, sr.f_b, sr.g_a, sr.g_b})
        quota_[f] = static_cast<uint8_t>(std::max(0, static_cast<int>(degree(f)) - (2 - vlink_[f]) - num_matched(f)));
}

void MatchingBuilder::settle_leftovers() {
    std::vector<FaceId> short_faces;
    auto collect = [&] {
        short_faces.clear();
        for (FaceId f : mesh_.faces())
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
    if (short_faces.size() > (ends_free() ? 2 : 0) && augment_all_through_chains(short_faces)) {
        chain_splits_ = true;
        collect();
        repair_short(short_faces);
    }
    if (chain_splits_) stats_.parity_splits += 1;
    // Still short: the matching is maximum there; splits beside short faces, while they help.
    for (uint32_t round = 0; round < 4 && !short_faces.empty(); ++round) {
        const size_t before = short_faces.size();
        bool any = false;
        for (FaceId u : std::vector<FaceId>(short_faces))
            if (quota_[u] > 0) any |= split_beside(u);
        if (!any) break;
        collect();
        repair_short(short_faces);
        stats_.parity_splits += 1;
        if (short_faces.size() >= before) break;
    }
    if (opt_.polish) polish();
    if (opt_.validate_each_split) check_matching();
    // Not held during the searches above, whose arrays are the engine's memory peak (a 4M-face
    // disk with holes: 12 MB of 315).
    used_.assign(mesh_.num_halfedges(), 0);
    for (HalfedgeId h : mesh_.halfedges()) used_[h] = passable(h) && !matched_[h];
    for (FaceId f : short_faces)
        for (uint32_t k = 0; k < 3 && quota_[f] > 0; ++k)
            if (used_[Mesh::halfedge(f, k)]) {
                set_pair(used_, Mesh::halfedge(f, k), 0);
                --quota_[f];
            }
    stats_.unmatched = static_cast<uint32_t>(short_faces.size());
    if (short_faces.empty() && !chain_splits_) pre_merge_ = false;  // loops only: no fallback ahead
    release_repair_scratch();
}

// The searches' per-face arrays (9 bytes a face and a queue) are not used after the matching: free
// them before the joins build theirs (issue 17's peak memory).
void MatchingBuilder::release_repair_scratch() {
    auto release = [](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); };
    release(aug_prev_), release(aug_step_), release(aug_queue_);
    aug_buckets_ = {}, aug_end_buckets_ = {};
    release(bl_stamp_), release(bl_seen_), release(bl_base_), release(bl_parent_), release(bl_label_);
    release(bl_touched_), release(bl_queue_), release(bl_merge_);
    release(ball_local_), release(ball_whole_), release(ball_short_);
}

// The matching's invariant: a face has exactly its wanted matched edges less its quota, all
// passable and symmetric across twins.
void MatchingBuilder::check_matching() const {
    for (FaceId f : mesh_.faces()) {
        int have = 0;
        for (HalfedgeId h : sides(f)) {
            if (!matched_[h]) continue;
            if (!passable(h) || !matched_[mesh_.twin(h)])
                throw InternalError("matching engine: face " + std::to_string(f.idx()) + " is matched across a closed or one-sided edge");
            ++have;
        }
        const int want = std::max(0, static_cast<int>(degree(f)) - (2 - vlink_[f]));
        if (have + quota_[f] != want)
            throw InternalError("matching engine: face " + std::to_string(f.idx()) + " has " + std::to_string(have) +
                                " matched edges and quota " + std::to_string(quota_[f]) + " but wants " + std::to_string(want));
    }
}

}  // namespace singlestrip::matching
