// singlestrip — a sequence of faces with position queries, joins and reversals (a splay tree
// keyed by position, Sleator & Tarjan 1985). The matching engine keeps its growing strip in one
// to rotate a path end (Pósa's rotation: the end links to a face inside the path, and the part
// between them turns round), which needs to know on which side of that face the end lies.
// Rotations touch faces near the path's ends, which a splay tree keeps near its root: amortized
// O(log d) for a face d places from a face used just before (a treap paid O(log n) every time).
#pragma once

#include <cstdint>
#include <vector>

#include "core/id_vector.hpp"
#include "singlestrip/mesh.hpp"

namespace singlestrip {

class PathOrder {
public:
    /// Room for faces 0..n-1 (a face is its own tree node); none is in the sequence yet. O(n).
    explicit PathOrder(uint32_t n);

    /// Appends `items` (not yet in the sequence) at the back, in order. O(k) amortized.
    void append(const std::vector<FaceId>& items);
    /// Puts `items` before the front, items[0] next to the old front and items.back() first (the
    /// path grows from its front end as it does from its back end). O(k) amortized.
    void prepend(const std::vector<FaceId>& items);
    /// append() with the items given one by one: next() returns each, then kNone (a walk feeds
    /// the sequence without an array of its own). Returns the last item, kNone if none.
    template <class Next>
    FaceId append_from(Next&& next) {
        FaceId last = kNone;
        const FaceId t = build(next, last);
        root_ = join(root_, t);
        return last;
    }
    /// prepend() with the items given one by one (items[0] first); returns the last (the new front).
    template <class Next>
    FaceId prepend_from(Next&& next) {
        FaceId last = kNone;
        const FaceId t = build(next, last);
        if (t != kNone) node_[t].flip ^= 1;  // built in order, then reversed lazily
        root_ = join(t, root_);
        return last;
    }
    /// Position of face x (0 = front). \pre x is in the sequence. O(log n) amortized.
    [[nodiscard]] uint32_t position(FaceId x);
    /// Face at position k. \pre k < size(). O(log n) amortized.
    [[nodiscard]] FaceId at(uint32_t k);
    /// Reverses positions [0, k) (front part) or [k, size) (back part). O(log n) amortized.
    void reverse_front(uint32_t k);
    void reverse_back(uint32_t k);
    [[nodiscard]] uint32_t size() const { return count(root_); }
    [[nodiscard]] FaceId front() { return at(0); }
    [[nodiscard]] FaceId back() { return at(size() - 1); }
    /// The whole sequence, front to back. O(n).
    [[nodiscard]] std::vector<FaceId> items();

private:
    // A tree node is a face; kNone is no node. One 16-byte record per node (the matching
    // engine's peak at 10M faces includes it: 20 bytes cost 3 more per face).
    struct Node {
        FaceId left{}, right{}, parent{};
        uint32_t size : 31 = 1;  ///< faces in the subtree (< 2^31: face ids are 32-bit)
        uint32_t flip : 1 = 0;   ///< the subtree's order is reversed (not yet pushed down)
    };
    static_assert(sizeof(Node) == 16);
    IdVector<FaceId, Node> node_;
    FaceId root_;
    std::vector<FaceId> up_;     ///< scratch of splay()
    std::vector<FaceId> spine_;  ///< scratch of build()

    [[nodiscard]] uint32_t count(FaceId x) const { return x == kNone ? 0 : node_[x].size; }
    void push(FaceId x);
    void pull(FaceId x);
    void rotate(FaceId x);
    /// Makes x the root (flips above it pushed down first).
    void splay(FaceId x);
    /// The node at position k of the subtree of t, splayed to the root of the whole tree.
    FaceId find(FaceId t, uint32_t k);
    /// a then b (both roots or kNone); the new root.
    [[nodiscard]] FaceId join(FaceId a, FaceId b);
    /// A fixed hash of the face: a heap order that makes a built tree balanced in expectation.
    [[nodiscard]] static uint32_t priority(FaceId x);

    /// Cartesian tree by priority() of the items next() gives, in linear time with the right
    /// spine on a stack (O(log k) expected), so a loop is fed in without an array of its own;
    /// `last` = the last item.
    template <class Next>
    [[nodiscard]] FaceId build(Next& next, FaceId& last) {
        spine_.clear();
        for (FaceId x = next(); x != kNone; x = next()) {
            last = x;
            node_[x] = Node{};
            FaceId below = kNone;
            while (!spine_.empty() && priority(spine_.back()) < priority(x)) {
                below = spine_.back();
                spine_.pop_back();
                pull(below);
            }
            node_[x].left = below;
            if (below != kNone) node_[below].parent = x;
            if (!spine_.empty()) node_[spine_.back()].right = x, node_[x].parent = spine_.back();
            spine_.push_back(x);
        }
        while (spine_.size() > 1) {
            pull(spine_.back());
            spine_.pop_back();
        }
        if (spine_.empty()) return kNone;
        pull(spine_.front());
        node_[spine_.front()].parent = kNone;
        return spine_.front();
    }
};

}  // namespace singlestrip
