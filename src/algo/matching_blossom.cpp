// singlestrip — matching engine: an augmenting path from one short face, through odd cycles.
// Edmonds, "Paths, trees, and flowers" (1965): one alternating tree grown breadth-first from the
// root, blossoms contracted by merging their bases (union-find, as in Gabow 1976). The search touches only the faces it
// reaches, so its cost follows the distance to the nearest other short face, where Edmonds in a
// ball (matching_repair.cpp) pays for the whole ball. A search that ends without a path proves
// that none starts at the root (later augmentations cannot create one), so the root needs no ball.
#include <cstdint>
#include <vector>

#include "matching_builder.hpp"

namespace singlestrip::matching {

namespace {
constexpr uint8_t kOdd = 1, kEven = 2;  // tree labels
}  // namespace

// Faces of the matching graph: those wanting exactly one matched edge. Faces wanting two (pinned
// faces of degree 3) are left out, and a search that meets one is not a proof.
bool MatchingBuilder::in_blossom_graph(FaceId f) const {
    return degree(f) + vlink_[f] == 3;
}

HalfedgeId MatchingBuilder::mate_edge(FaceId f) const {
    for (HalfedgeId h : sides(f))
        if (matched_[h]) return h;
    return kNone;
}

FaceId MatchingBuilder::blossom_base(FaceId f) {
    while (bl_base_[f] != f) f = bl_base_[f] = bl_base_[bl_base_[f]];
    return f;
}

// First common base of a and b going up the tree (both even, in the same tree).
FaceId MatchingBuilder::blossom_lca(FaceId a, FaceId b) {
    ++bl_mark_;
    for (;;) {
        a = blossom_base(a);
        bl_seen_[a] = bl_mark_;
        const HalfedgeId m = mate_edge(a);
        if (m == kNone) break;  // the root
        a = Mesh::face(bl_parent_[across(m)]);
    }
    for (;;) {
        b = blossom_base(b);
        if (bl_seen_[b] == bl_mark_) return b;
        b = Mesh::face(bl_parent_[across(mate_edge(b))]);
    }
}

// Walks from v up to base b, pointing parents along the cycle (into_v: a half-edge from the child
// into v), listing the bases met, to be merged into b (union-find, so a contraction costs its
// path only), and queueing the odd faces met, which are even inside the blossom.
void MatchingBuilder::blossom_mark(FaceId v, FaceId b, HalfedgeId into_v) {
    while (blossom_base(v) != b) {
        const FaceId u = across(mate_edge(v)), bv = blossom_base(v), bu = blossom_base(u);
        bl_parent_[v] = into_v;
        into_v = mesh_.twin(bl_parent_[u]);
        const FaceId next = Mesh::face(bl_parent_[u]);
        if (bl_label_[u] == kOdd) bl_label_[u] = kEven, bl_queue_.push_back(u);
        bl_merge_.push_back(bv);
        bl_merge_.push_back(bu);
        v = next;
    }
}

// The walks see the bases as they were (a walk passes through a sub-blossom to its base), so the
// bases are merged after both.
void MatchingBuilder::blossom_contract(FaceId v, FaceId to, HalfedgeId h) {
    const FaceId b = blossom_lca(v, to);
    bl_merge_.clear();
    blossom_mark(v, b, mesh_.twin(h));
    blossom_mark(to, b, h);
    for (FaceId x : bl_merge_) bl_base_[x] = b;
}

// Flips the alternating path that ends at the exposed face `end`.
void MatchingBuilder::blossom_augment(FaceId end) {
    for (FaceId v = end; v != kNone;) {
        const HalfedgeId h = bl_parent_[v], old = mate_edge(Mesh::face(h));
        set_pair(matched_, h, 1);
        if (old != kNone) set_pair(matched_, old, 0);
        v = old == kNone ? FaceId() : across(old);
    }
}

void MatchingBuilder::blossom_touch(FaceId f) {
    if (bl_stamp_[f] == bl_search_) return;
    bl_stamp_[f] = bl_search_;
    bl_base_[f] = f;  // union-find parent: the blossom's base at the root
    bl_label_[f] = 0;
    bl_parent_[f] = kNone;
    bl_touched_.push_back(f);
}

MatchingBuilder::Search MatchingBuilder::blossom_search(FaceId root, size_t budget) {
    const uint32_t nf = mesh_.num_faces();
    if (bl_stamp_.size() != nf) {
        bl_stamp_.assign(nf, 0), bl_seen_.assign(nf, 0);
        bl_base_.resize(nf), bl_label_.resize(nf), bl_parent_.resize(nf);
    }
    ++bl_search_;
    bl_touched_.clear();
    bl_queue_.clear();
    blossom_touch(root);
    bl_label_[root] = kEven;
    bl_queue_.push_back(root);
    bool exact = true;
    for (size_t head = 0; head < bl_queue_.size(); ++head) {
        if (bl_touched_.size() > budget) return exact ? Search::Exhausted : Search::Unknown;
        const FaceId v = bl_queue_[head];
        for (HalfedgeId h : sides(v)) {
            if (!passable(h) || matched_[h]) continue;
            const FaceId to = across(h);
            if (!in_blossom_graph(to)) {
                // A face that takes no matched edge is no vertex of the graph (as in the balls).
                exact &= degree(to) + vlink_[to] <= 2 && num_matched(to) == 0;
                continue;
            }
            blossom_touch(to);
            if (blossom_base(v) == blossom_base(to)) continue;
            if (bl_label_[to] == kEven) {
                blossom_contract(v, to, h);
            } else if (bl_label_[to] == 0) {
                bl_label_[to] = kOdd;
                bl_parent_[to] = h;
                const HalfedgeId m = mate_edge(to);
                if (m == kNone) {
                    blossom_augment(to);
                    quota_[root] = 0;
                    quota_[to] = 0;
                    return Search::Found;
                }
                const FaceId w = across(m);
                if (!in_blossom_graph(w)) {
                    exact = false;
                    continue;
                }
                blossom_touch(w);
                bl_label_[w] = kEven;
                bl_queue_.push_back(w);
            }
        }
    }
    return exact ? Search::NoPath : Search::Unknown;
}

}  // namespace singlestrip::matching
