// singlestrip — the matching engine's builder, shared by its source files (private header):
//   strip_matching.cpp  pins, the patterned matching, run() and the fallback;
//   matching_bridges.cpp ears and bridges of the dual graph split, the splits any strip needs;
//   matching_repair.cpp faces left short: augmenting paths, Edmonds in balls, splits beside them;
//   matching_forest.cpp augmenting paths from all short faces at once (a breadth-first forest);
//   matching_chains.cpp short faces at the junctions of forced chains: the chains split;
//   matching_joins.cpp  loops and paths labelled, alternating-cycle flips, the joins, one pin;
//   matching_absorb.cpp loops taken into one growing path by end rotations.
// The method and why it ends in one strip: docs/algorithm.md, "The matching engine".
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

#include "bucket_queue.hpp"
#include "core/face_sides.hpp"
#include "core/id_vector.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "strip_controls.hpp"

namespace singlestrip::matching {

using StructId = Id<struct StructTag>;  ///< a loop or path of crossed edges (through the union-find)
using StepId = Id<struct StepTag>;      ///< a step of augment_through_chains()' search

class MatchingBuilder {
public:
    MatchingBuilder(Mesh mesh, const StripOptions& options) : mesh_(std::move(mesh)), opt_(options) {}
    StripResult run();

private:
    Mesh mesh_;
    const StripOptions& opt_;
    // Per half-edge, symmetric across twins (a half-edge and its twin always agree).
    EdgeFlags blocked_;  ///< constraint edge: never crossed
    EdgeFlags matched_;  ///< passable edge not crossed, paired by the matching
    EdgeFlags used_;     ///< crossed by the strip (an edge of the loops and paths); empty until the matching is settled
    // Per face.
    IdVector<FaceId, uint8_t> vlink_;  ///< linked to the virtual face (a pinned end)
    IdVector<FaceId, uint8_t> quota_;  ///< matched edges still wanted
    IdVector<FaceId, StructId> sid_;   ///< structure (loop or path), through uf_
    // Per structure.
    IdVector<StructId, StructId> uf_;     ///< union-find parent
    IdVector<StructId, uint8_t> cycle_;   ///< at a root: the structure is a loop (no free end)
    IdVector<StructId, uint8_t> pinned_;  ///< at a root: holds the virtual face
    FaceId pins_[2] = {kNone, kNone};     ///< source face (or seed) and target face
    uint32_t num_pins_ = 0;
    bool reversed_ = false;  ///< only a target: the walk starts there and is reversed
    StripStats stats_;
    /// (corner, its input vertex) for each input face's corner a split overwrote, oldest first:
    /// with the current corners it gives back the input (input_mesh()) for 8 bytes a split
    /// instead of a 12-byte copy of every face.
    std::vector<std::pair<HalfedgeId, VertexId>> overwritten_;
    std::vector<HalfedgeId> split_log_;  ///< the half-edge of every split, in order
    /// Paths remain: the mesh before the joins (its first pre_merge_splits_ splits) is a fallback
    /// candidate, replayed from the input then instead of kept as a copy (36 bytes a face).
    bool pre_merge_ = false;
    uint32_t pre_merge_splits_ = 0;
    bool chain_splits_ = false;  ///< split_along_chains() split something
    uint32_t ear_splits_ = 0;    ///< split_ears(): ears split
    /// split_bridges(): splits any single strip of the input needs (ears and bridges, docs/algorithm.md steps 3-4)
    uint32_t forced_splits_ = 0;
    // Augmenting search, per face z: the outer face it was reached from, and the step's two
    // edges as corner numbers (h, unmatched, a side of aug_prev_[z]; then e, matched, a side of
    // across(h)): a byte, not two half-edge ids (a 4M-face search: 28 MB of the peak).
    IdVector<FaceId, FaceId> aug_prev_;
    IdVector<FaceId, uint8_t> aug_step_;
    void set_aug_step(FaceId z, HalfedgeId h, HalfedgeId e) {
        aug_step_[z] = static_cast<uint8_t>(Mesh::index_in_face(h) | Mesh::index_in_face(e) << 2);
    }
    [[nodiscard]] HalfedgeId aug_unmatched(FaceId z) const { return Mesh::halfedge(aug_prev_[z], aug_step_[z] & 3u); }
    [[nodiscard]] HalfedgeId aug_matched(FaceId z) const { return Mesh::halfedge(across(aug_unmatched(z)), aug_step_[z] >> 2); }
    std::vector<FaceId> aug_queue_;
    /// augment_fewest_swaps()' queue: expand face x, or (end set) end the path across end.
    struct AugEntry {
        int swaps;
        FaceId x;
        HalfedgeId end;
        [[nodiscard]] int key() const { return swaps; }
    };
    BucketQueue<AugEntry> aug_buckets_;      ///< augment_fewest_swaps()' and forest_pass_fewest()'s queue
    BucketQueue<AugEntry> aug_end_buckets_;  ///< forest_pass_fewest(): queued path ends, cheapest first

    [[nodiscard]] FaceId across(HalfedgeId h) const { return mesh_.neighbor(h); }
    [[nodiscard]] bool passable(HalfedgeId h) const { return !mesh_.is_boundary(h) && !blocked_[h]; }
    [[nodiscard]] uint32_t degree(FaceId f) const {
        return passable(Mesh::halfedge(f, 0)) + passable(Mesh::halfedge(f, 1)) + passable(Mesh::halfedge(f, 2));
    }
    /// Matched edges of f.
    [[nodiscard]] int num_matched(FaceId f) const {
        return matched_[Mesh::halfedge(f, 0)] + matched_[Mesh::halfedge(f, 1)] + matched_[Mesh::halfedge(f, 2)];
    }
    /// Links of f in the loops-and-paths graph, the virtual face included.
    [[nodiscard]] uint32_t hdeg(FaceId f) const {
        return used_[Mesh::halfedge(f, 0)] + used_[Mesh::halfedge(f, 1)] + used_[Mesh::halfedge(f, 2)] + vlink_[f];
    }
    /// The crossed half-edge of f other than `in` (the one a walk entered by; kNone at a start):
    /// the next step of a walk along a loop or path, kNone at its end.
    [[nodiscard]] HalfedgeId next_crossed(FaceId f, HalfedgeId in) const {
        HalfedgeId out = kNone;
        for (HalfedgeId h : sides(f))
            if (used_[h] && h != in) out = h;
        return out;
    }
    void set_pair(EdgeFlags& a, HalfedgeId h, uint8_t value) {
        a[h] = value;
        a[mesh_.twin(h)] = value;
    }
    StructId find(StructId s) {
        while (uf_[s] != s) s = uf_[s] = uf_[uf_[s]];
        return s;
    }
    /// 1 if the GL strip needs a swap at crossed half-edge h, where crossed(e) tells which edges
    /// the strip crosses: the turns in h's two faces (their edges left uncrossed) pivot on the
    /// same endpoint of h. Path ends make no turn. One test for the loops (used_) and for a
    /// candidate matching (pattern_cost()).
    template <class Crossed>
    [[nodiscard]] int swap_test(HalfedgeId h, const Crossed& crossed) const {
        const HalfedgeId t = mesh_.twin(h);
        auto links = [&](FaceId x) {
            return crossed(Mesh::halfedge(x, 0)) + crossed(Mesh::halfedge(x, 1)) + crossed(Mesh::halfedge(x, 2)) + vlink_[x];
        };
        if (links(Mesh::face(h)) != 2 || links(Mesh::face(t)) != 2) return 0;
        // f's uncrossed edge touches from(h) iff prev(h) is; g's iff next(t) is (to(t) = from(h)).
        return crossed(Mesh::prev(h)) == crossed(Mesh::next(t));
    }

    void choose_pins();
    SplitResult split(HalfedgeId h);
    void split_ears();
    void set_quotas();
    struct DualBridges {
        std::vector<HalfedgeId> to_split;  ///< bridges with kMinBridgeSide faces or more on each side
        uint32_t all = 0;                  ///< every bridge
        uint32_t on_one_path = 0;          ///< the most bridges one path of faces crosses
    };
    DualBridges dual_bridges() const;
    bool may_have_bridges() const;
    static constexpr uint32_t kMinBridgeSide = 16;
    void split_bridges();
    bool chain_reaches_branch(FaceId f, FaceId from) const;
    void match_fans();
    static constexpr uint32_t kFanValence = 32;  ///< fans of this many faces or more: one loop
    /// A candidate matching: matched edges and the quotas still open.
    struct Pattern {
        EdgeFlags matched;
        IdVector<FaceId, uint8_t> quota;
    };
    static constexpr uint32_t kParallelPattern = 16384;  ///< faces from which the two greedy orders run at once
    void match_patterned(bool mates, Pattern& p);
    /// The turn pattern's rule across crossed edge e of a face whose matched edge is m: the face
    /// across e should match the edge that touches to(e) if m touches from(e), and the other way
    /// round (then the two turns alternate). kNone if m is neither of e's neighbours in its face.
    [[nodiscard]] HalfedgeId alternate(HalfedgeId m, HalfedgeId e) const {
        const HalfedgeId t = mesh_.twin(e);
        return m == Mesh::prev(e) ? Mesh::prev(t) : m == Mesh::next(e) ? Mesh::next(t) : HalfedgeId(kNone);
    }
    HalfedgeId seed_direction(FaceId s, size_t& credit) const;
    /// A zigzag band of the pattern from a seed: its faces, whether it closed into a loop, and
    /// whether it met one of its faces again (crossed itself).
    struct Band {
        uint32_t faces = 1;
        bool loop = false;
        bool crossed = false;
    };
    Band follow_band(FaceId s, HalfedgeId m) const;
    static constexpr uint32_t kBandProbe = 4096;  ///< faces a seed's band is followed at most
    void choose_pattern();
    [[nodiscard]] long pattern_cost(const Pattern& p) const;
    bool augment_from(FaceId u, IdVector<FaceId, uint32_t>& stamp, uint32_t mark, size_t budget);
    bool augment_fewest_swaps(FaceId u, IdVector<FaceId, uint32_t>& stamp, uint32_t mark, size_t budget);
    /// Swaps settled by one step of augment_fewest_swaps(): x takes h as its matched edge.
    [[nodiscard]] int step_swaps(FaceId x, HalfedgeId h, bool x_is_root, bool y_is_end) const;
    /// While the fewest-swap searches run (empty otherwise), per face: bits 0-2 its edges crossed
    /// (passable, not matched), bits 3-5 passable, bit 6 vlink_. step_swaps() reads one byte a
    /// face, not six edges' flags (it was the searches' top self-time). Kept by set_matched().
    IdVector<FaceId, uint8_t> cross_;
    [[nodiscard]] uint8_t cross_bits(FaceId f) const {
        uint32_t b = static_cast<uint32_t>(vlink_[f]) << 6;
        for (uint32_t k = 0; k < 3; ++k) {
            const HalfedgeId a = Mesh::halfedge(f, k);
            b |= static_cast<uint32_t>(passable(a)) << (k + 3) | static_cast<uint32_t>(passable(a) && !matched_[a]) << k;
        }
        return static_cast<uint8_t>(b);
    }
    void cross_on(bool on) {
        if (!on) return cross_.reset();
        cross_.assign(mesh_.num_faces(), 0);
        for (FaceId f : mesh_.faces()) cross_[f] = cross_bits(f);
    }
    /// set_pair(matched_, h, value), cross_ kept.
    void set_matched(HalfedgeId h, uint8_t value) {
        set_pair(matched_, h, value);
        if (cross_.empty()) return;
        cross_[Mesh::face(h)] = cross_bits(Mesh::face(h));
        cross_[across(h)] = cross_bits(across(h));
    }
    // All short faces' augmenting paths at once (matching_forest.cpp).
    void augment_forest(std::vector<FaceId>& short_faces, IdVector<FaceId, uint32_t>& stamp, uint32_t& mark);
    uint32_t forest_pass(const std::vector<FaceId>& roots, IdVector<FaceId, uint32_t>& stamp, uint32_t base, size_t& work);
    void augment_forest_fewest(std::vector<FaceId>& short_faces, IdVector<FaceId, uint32_t>& stamp, uint32_t& mark);
    uint32_t forest_pass_fewest(const std::vector<FaceId>& roots, IdVector<FaceId, uint32_t>& stamp, uint32_t base, size_t& work);
    IdVector<FaceId, int32_t> aug_swaps_;  ///< forest_pass_fewest(): swaps of the tree path to each outer face
    /// forest_pass_fewest(): faces expanded after an end is found before the cheapest ends are taken.
    static constexpr size_t kEndWait = 256;
    static constexpr size_t kFewestWork = 1;  ///< fewest-swap forest: faces expanded per mesh face at most
    void flip_to_root(FaceId z);
    static constexpr size_t kForestWork = 8;     ///< forest passes: faces expanded per mesh face at most
    static constexpr uint32_t kForestYield = 8;  ///< forest passes: roots per path settled, at most, for another pass
    // Augmenting path from one short face through blossoms (matching_blossom.cpp).
    /// Exhausted: the budget ran out (no path among the faces reached); Unknown: the search met
    /// faces its graph does not model (pinned faces wanting two matched edges).
    enum class Search { Found, NoPath, Unknown, Exhausted };
    Search blossom_search(FaceId root, size_t budget);
    void release_work_arrays() noexcept;
    /// Gives blossom_search()'s per-face arrays back (the next search makes them again).
    void release_blossom_arrays() noexcept { bl_stamp_.reset(), bl_seen_.reset(), bl_base_.reset(), bl_label_.reset(), bl_parent_.reset(); }
    [[nodiscard]] bool in_blossom_graph(FaceId f) const;
    [[nodiscard]] HalfedgeId mate_edge(FaceId f) const;
    FaceId blossom_base(FaceId f);
    FaceId blossom_lca(FaceId a, FaceId b);
    void blossom_mark(FaceId v, FaceId b, HalfedgeId into_v);
    void blossom_contract(FaceId v, FaceId to, HalfedgeId h);
    void blossom_augment(FaceId end);
    void blossom_touch(FaceId f);
    // Per face, valid where bl_stamp_ == bl_search_ (reset lazily: a search costs what it touches).
    IdVector<FaceId, uint32_t> bl_stamp_, bl_seen_;
    IdVector<FaceId, FaceId> bl_base_;
    IdVector<FaceId, HalfedgeId> bl_parent_;  ///< half-edge into the face
    IdVector<FaceId, uint8_t> bl_label_;      ///< 0, odd or even in the tree
    std::vector<FaceId> bl_touched_, bl_queue_, bl_merge_;
    uint32_t bl_search_ = 0, bl_mark_ = 0;
    void settle_leftovers();
    // Opt-in polishing of a perfect matching (matching_polish.cpp, StripOptions::polish).
    struct PolishScratch {
        IdVector<FaceId, uint32_t> stamp, in_set;
        uint32_t mark = 0, set_mark = 0;
        std::vector<FaceId> faces;                             ///< the path's faces and their neighbours
        std::vector<std::pair<HalfedgeId, HalfedgeId>> steps;  ///< (matched by the path, unmatched by it)
    };
    static constexpr size_t kPolishBudget = 64;  ///< faces a polishing search reaches at most
    void polish();
    bool polish_at(FaceId f, HalfedgeId m, PolishScratch& s);
    [[nodiscard]] int swaps_among(const std::vector<FaceId>& faces, const IdVector<FaceId, uint32_t>& in_set, uint32_t mark) const;
    void release_repair_scratch();
    void check_matching() const;
    void repair_short(std::vector<FaceId>& short_faces);
    bool split_beside(FaceId u);
    void requota(const SplitResult& sr);
    [[nodiscard]] FaceId chain_end(HalfedgeId h, uint32_t& faces) const;
    void split_chain(HalfedgeId h, uint32_t faces, std::vector<FaceId>* wanting);
    /// A step of the chain forest (matching_chains.cpp): from outer face x across unmatched h and
    /// along a forced chain of `faces` faces to y; z, y's mate then, is the next outer face.
    struct ChainStep {
        StepId prev;  ///< the step whose z is x (kNone: x is the tree's root)
        HalfedgeId h;
        uint32_t faces, cost;  ///< chain faces of this step, and of the tree path up to it
        uint32_t tree;
        FaceId x, y, z;  ///< z = kNone: a step that meets another tree (or a short face) at y
    };
    /// The chain forest's trees: per face, tree + 1 (0: none) and, for outer faces, the step
    /// whose z it is (kNone: the root; for inner faces, the step whose y it is).
    struct ChainForest {
        IdVector<FaceId, uint32_t> tree;
        IdVector<FaceId, StepId> reach;
        std::vector<ChainStep> steps;
        std::vector<FaceId> roots;
        std::vector<uint8_t> alive;
    };
    bool augment_all_through_chains(const std::vector<FaceId>& short_faces);
    uint32_t chain_forest_pass(ChainForest& cf, size_t& left, size_t keep, size_t& work, size_t most);
    void chain_grow(ChainForest& cf, StepId at, uint32_t cost, uint32_t t, std::vector<std::pair<uint32_t, StepId>>& out, size_t& work);
    [[nodiscard]] bool chain_step_holds(const ChainForest& cf, StepId s) const;
    bool apply_chain_meeting(ChainForest& cf, StepId m, size_t& work);
    [[nodiscard]] FaceId mate_of(FaceId y) const;
    std::vector<FaceId> apply_chain_path(const std::vector<ChainStep>& path);
    IdVector<FaceId, uint32_t> ch_stamp_;
    uint32_t ch_mark_ = 0;
    bool split_along_chains(const std::vector<FaceId>& short_faces);
    bool repair_in_balls(std::vector<FaceId>& short_faces, size_t ball);
    bool repair_ball(const std::vector<FaceId>& short_faces, size_t ball, IdVector<FaceId, uint8_t>* whole = nullptr);
    template <class Want>
    void match_ball(const std::vector<FaceId>& kept, const std::vector<FaceId>& owner, const Want& want);
    static constexpr size_t kBallOneByOne = 8192;
    using BallVertex = Id<struct BallVertexTag>;  ///< a vertex of the graph a ball's search builds
    IdVector<FaceId, BallVertex> ball_local_;
    IdVector<FaceId, uint8_t> ball_whole_;  ///< faces of a ball that was its whole component
    size_t ball_reached_ = 0;               ///< faces the last repair_ball() gathered
    std::vector<FaceId> ball_short_;        ///< faces a ball's matching left short that were not
    static constexpr size_t kBallWork = 2;  ///< one-by-one balls: faces gathered per mesh face at most
    void label_structures();
    void merge_all();
    void merge_by_cost();
    [[nodiscard]] int split_join_cost(HalfedgeId h) const;
    void reduce_loops();
    void absorb_loops();
    friend class PathGrower;
    /// The faces of a loop cut open at its crossed half-edge `cut`, from cut's face round to the
    /// face across it: the generator returns one per call, then kNone. Reads used_ as it goes.
    [[nodiscard]] auto loop_from(HalfedgeId cut) const {
        return [this, cut, in = cut, f = Mesh::face(cut)]() mutable -> FaceId {
            const FaceId here = f;
            if (here == kNone) return here;
            const HalfedgeId out = next_crossed(here, in);
            if (out == kNone || out == mesh_.twin(cut)) {
                f = kNone;
            } else {
                in = mesh_.twin(out);
                f = Mesh::face(in);
            }
            return here;
        };
    }
    [[nodiscard]] int swap_at(HalfedgeId h) const {
        return swap_test(h, [&](HalfedgeId e) { return used_[e] != 0; });
    }
    int swaps_around(std::initializer_list<FaceId> faces) const;
    bool flip_alternating(FaceId f1, bool one_end);
    std::vector<FaceId> flipped_faces_;  ///< faces whose edges a flip changed (reduce_loops())
    bool meets_first(FaceId from, FaceId back, FaceId good, FaceId bad) const;
    bool try_merge(HalfedgeId h, bool allow_split);
    void join(HalfedgeId h, StructId a, StructId b, bool cycle, bool pinned);
    void rotate_into(HalfedgeId h, StructId a, StructId b);
    void merge_by_split(HalfedgeId h, StructId a, StructId b);
    [[nodiscard]] uint32_t num_structures();
    bool single_strip_ready();
    /// The faces in strip order, and `swaps` (as count_swaps() gives them).
    std::vector<uint32_t> walk(uint32_t& swaps) const;
    StripResult finish(std::vector<uint32_t> order, uint32_t swaps);
    StripResult finish_or_grow(std::vector<uint32_t> order, uint32_t swaps);
    bool growth_may_win() const;
    bool mostly_tree() const;
    bool many_ears() const;
    bool mostly_tree_before_splits();
    StripResult grow_unsplit();
    /// finish_or_grow(): the splits of the strip the growth candidates must beat (grow()).
    uint32_t beat_splits_ = kNoBound;
    static constexpr uint32_t kNoBound = UINT32_MAX, kDeferSlack = 64;
    static constexpr uint64_t kGrowthWorthPercent = 1;  ///< finish_or_grow(): extra triangles from which growth may win
    StripResult grow(Mesh mesh, uint32_t splits) const;
    std::pair<StripResult, StripResult> grow_two(Mesh a, uint32_t splits_a, Mesh b, uint32_t splits_b) const;
    static constexpr uint32_t kParallelGrowMax = 4u << 20;  ///< faces up to which grow_two() uses two threads
    void keep_better(StripResult& r, StripResult alt) const;
    StripResult as_fallback(StripResult r) const;
    StripResult fallback(bool split_mesh_too = true);
    StripResult retry_or_fallback();
    bool plain_paths_ = false;  ///< step 6 by shortest augmenting paths (the retry before the fallback)
    /// One pin only (a source, a target or a seed face): first built as one loop with no pin,
    /// cut at a face of the pin (run()); `pinned_only_` is the retry with the pin, when that
    /// loop does not come out.
    bool loop_mode_ = false, pinned_only_ = false;
    FaceId loop_pin_ = kNone;  ///< loop mode: the seed face, else kNone (a face at the vertex)
    /// Two short faces may stay as the strip's two ends: no pin, and no loop to be cut at one.
    [[nodiscard]] bool ends_free() const { return num_pins_ == 0 && !loop_mode_; }
    [[nodiscard]] FaceId loop_start() const;
    StripResult rerun(bool plain_paths, bool pinned_only);
    Mesh input_mesh() const;
    Mesh pre_merge_mesh(const Mesh& original) const;
};

}  // namespace singlestrip::matching
