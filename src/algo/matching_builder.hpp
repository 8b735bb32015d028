// singlestrip — the matching engine's builder, shared by its source files (private header):
//   strip_matching.cpp  pins, ear and bridge splits, the patterned matching, run() and the fallback;
//   matching_repair.cpp faces left short: augmenting paths, Edmonds in balls, splits beside them;
//   matching_chains.cpp short faces at the junctions of forced chains: the chains split;
//   matching_joins.cpp  loops and paths labelled, alternating-cycle flips, the joins;
//   matching_absorb.cpp loops taken into one growing path by end rotations.
// The method and why it ends in one strip: docs/algorithm.md, "The matching engine".
#pragma once

#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"

namespace singlestrip::matching {

class MatchingBuilder {
public:
    MatchingBuilder(Mesh mesh, const StripOptions& options) : mesh_(std::move(mesh)), opt_(options) {}
    StripResult run();

private:
    Mesh mesh_;
    const StripOptions& opt_;
    // Per half-edge, symmetric across twins (a half-edge and its twin always agree).
    std::vector<uint8_t> blocked_;  ///< constraint edge: never crossed
    std::vector<uint8_t> matched_;  ///< passable edge not crossed, paired by the matching
    std::vector<uint8_t> used_;     ///< crossed by the strip (an edge of the loops and paths)
    // Per face.
    std::vector<uint8_t> vlink_;  ///< linked to the virtual face (a pinned end)
    std::vector<uint8_t> quota_;  ///< matched edges still wanted
    std::vector<uint32_t> sid_;   ///< structure (loop or path) id, through uf_
    // Per structure id.
    std::vector<uint32_t> uf_;           ///< union-find parent
    std::vector<uint8_t> cycle_;         ///< at a root: the structure is a loop (no free end)
    std::vector<uint8_t> pinned_;        ///< at a root: holds the virtual face
    uint32_t pins_[2] = {kNone, kNone};  ///< source face (or seed) and target face
    uint32_t num_pins_ = 0;
    bool reversed_ = false;  ///< only a target: the walk starts there and is reversed
    StripStats stats_;
    /// (corner, its input vertex) for each input face's corner a split overwrote, oldest first:
    /// with the current corners it gives back the input (input_mesh()) for 8 bytes a split
    /// instead of a 12-byte copy of every face.
    std::vector<std::pair<uint32_t, uint32_t>> overwritten_;
    std::vector<uint32_t> split_log_;  ///< the half-edge of every split, in order
    /// Paths remain: the mesh before the joins (its first pre_merge_splits_ splits) is a fallback
    /// candidate, replayed from the input then instead of kept as a copy (36 bytes a face).
    bool pre_merge_ = false;
    uint32_t pre_merge_splits_ = 0;
    bool chain_splits_ = false;  ///< split_along_chains() split something
    // Augmenting search, per face: the outer face it was reached from and the two edges used.
    std::vector<uint32_t> aug_prev_, aug_matched_, aug_unmatched_, aug_queue_;

    // The engine keeps flat per-half-edge and per-face arrays, so it navigates by plain index.
    [[nodiscard]] uint32_t across(uint32_t h) const { return mesh_.neighbor(HalfedgeId(h)).idx(); }
    [[nodiscard]] uint32_t twin_of(uint32_t h) const { return mesh_.twin(HalfedgeId(h)).idx(); }
    [[nodiscard]] static uint32_t face_of(uint32_t h) { return h / 3; }
    [[nodiscard]] bool passable(uint32_t h) const { return !mesh_.is_boundary(HalfedgeId(h)) && !blocked_[h]; }
    [[nodiscard]] uint32_t degree(uint32_t f) const { return passable(3 * f) + passable(3 * f + 1) + passable(3 * f + 2); }
    /// Links of f in the loops-and-paths graph, the virtual face included.
    [[nodiscard]] uint32_t hdeg(uint32_t f) const { return used_[3 * f] + used_[3 * f + 1] + used_[3 * f + 2] + vlink_[f]; }
    void set_pair(std::vector<uint8_t>& a, uint32_t h, uint8_t value) {
        a[h] = value;
        a[mesh_.twin(HalfedgeId(h)).idx()] = value;
    }
    uint32_t find(uint32_t s) {
        while (uf_[s] != s) s = uf_[s] = uf_[uf_[s]];
        return s;
    }

    void choose_pins();
    SplitResult split(uint32_t h);
    void split_ears();
    void set_quotas();
    std::vector<uint32_t> dual_bridges() const;
    static constexpr uint32_t kMinBridgeSide = 16;
    void split_bridges();
    bool chain_reaches_branch(uint32_t f, uint32_t from) const;
    void match_fans();
    static constexpr uint32_t kFanValence = 32;  ///< fans of this many faces or more: one loop
    void match_patterned(bool mates);
    void choose_pattern();
    [[nodiscard]] long pattern_cost() const;
    bool augment_from(uint32_t u, std::vector<uint32_t>& stamp, uint32_t mark, size_t budget);
    // Augmenting path from one short face through blossoms (matching_blossom.cpp).
    enum class Search { Found, NoPath, Unknown };
    Search blossom_search(uint32_t root, size_t budget);
    [[nodiscard]] bool in_blossom_graph(uint32_t f) const;
    [[nodiscard]] uint32_t mate_edge(uint32_t f) const;
    uint32_t blossom_base(uint32_t f);
    uint32_t blossom_lca(uint32_t a, uint32_t b);
    void blossom_mark(uint32_t v, uint32_t b, uint32_t into_v);
    void blossom_contract(uint32_t v, uint32_t to, uint32_t h);
    void blossom_augment(uint32_t end);
    void blossom_touch(uint32_t f);
    // Per face, valid where bl_stamp_ == bl_search_ (reset lazily: a search costs what it touches).
    std::vector<uint32_t> bl_stamp_, bl_seen_, bl_base_, bl_parent_;  ///< parent: half-edge into the face
    std::vector<uint8_t> bl_label_;                                   ///< 0, odd or even in the tree
    std::vector<uint32_t> bl_touched_, bl_queue_, bl_merge_;
    uint32_t bl_search_ = 0, bl_mark_ = 0;
    void settle_leftovers();
    void release_repair_scratch();
    void check_matching() const;
    void repair_short(std::vector<uint32_t>& short_faces);
    bool split_beside(uint32_t u);
    void requota(const SplitResult& sr);
    [[nodiscard]] uint32_t chain_end(uint32_t h, uint32_t& faces) const;
    void split_chain(uint32_t h, uint32_t faces, std::vector<uint32_t>* wanting);
    struct ChainStep {
        uint32_t prev, h, faces, y;  ///< prev: the step that reached the face h leaves (kNone: the root)
    };
    bool augment_through_chains(uint32_t u, size_t budget);
    bool augment_all_through_chains(const std::vector<uint32_t>& short_faces);
    [[nodiscard]] uint32_t mate_of(uint32_t y) const;
    void apply_chain_path(const std::vector<ChainStep>& steps, uint32_t last);
    std::vector<uint32_t> ch_stamp_;
    uint32_t ch_mark_ = 0;
    bool split_along_chains(const std::vector<uint32_t>& short_faces);
    bool repair_in_balls(std::vector<uint32_t>& short_faces, size_t ball);
    bool repair_ball(const std::vector<uint32_t>& short_faces, size_t ball, std::vector<uint8_t>* whole = nullptr);
    static constexpr size_t kBallOneByOne = 8192;
    std::vector<uint32_t> ball_local_;
    std::vector<uint8_t> ball_whole_;  ///< faces of a ball that was its whole component
    void label_structures();
    void merge_all();
    void merge_by_cost();
    [[nodiscard]] int split_join_cost(uint32_t h) const;
    void reduce_loops();
    void absorb_loops();
    friend class PathGrower;
    std::vector<uint32_t> loop_from(uint32_t cut) const;
    int swap_at(uint32_t h) const;
    int swaps_around(std::initializer_list<uint32_t> faces) const;
    bool flip_alternating(uint32_t f1);
    std::vector<uint32_t> flipped_faces_;  ///< faces whose edges a flip changed (reduce_loops())
    bool meets_first(uint32_t from, uint32_t back, uint32_t good, uint32_t bad) const;
    bool try_merge(uint32_t h, bool allow_split);
    void join(uint32_t h, uint32_t a, uint32_t b, bool cycle, bool pinned);
    void rotate_into(uint32_t h, uint32_t a, uint32_t b);
    void merge_by_split(uint32_t h, uint32_t a, uint32_t b);
    bool single_strip_ready();
    std::vector<uint32_t> walk() const;
    StripResult finish(std::vector<uint32_t> order);
    StripResult finish_or_grow(std::vector<uint32_t> order);
    StripResult grow(Mesh mesh, uint32_t splits) const;
    void keep_better(StripResult& r, StripResult alt) const;
    StripResult as_fallback(StripResult r) const;
    StripResult fallback();
    Mesh input_mesh() const;
    Mesh pre_merge_mesh(const Mesh& original) const;
};

}  // namespace singlestrip::matching
