// singlestrip — a sequence of faces with O(log n) position queries, splits, joins and reversals
// (an implicit treap). The matching engine keeps its growing strip in one to rotate a path end
// (Pósa's rotation: the end links to a face inside the path, and the part between them turns
// round), which needs to know on which side of that face the end lies.
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

    /// Appends `items` (not yet in the sequence) at the back, in order. O(k + log n).
    void append(const std::vector<FaceId>& items);
    /// Puts `items` before the front, items[0] next to the old front and items.back() first (the
    /// path grows from its front end as it does from its back end). O(k + log n).
    void prepend(const std::vector<FaceId>& items);
    /// append() with the items given one by one: next() returns each, then kNone (a walk feeds
    /// the sequence without an array of its own). Returns the last item, kNone if none.
    template <class Next>
    FaceId append_from(Next&& next) {
        FaceId last = kNone;
        const FaceId t = build(next, last);
        root_ = merge(root_, t);
        return last;
    }
    /// prepend() with the items given one by one (items[0] first); returns the last (the new front).
    template <class Next>
    FaceId prepend_from(Next&& next) {
        FaceId last = kNone;
        const FaceId t = build(next, last);
        if (t != kNone) flip_[t] ^= 1;  // built in order, then reversed lazily
        root_ = merge(t, root_);
        return last;
    }
    /// Position of face x (0 = front). \pre x is in the sequence. O(log n) expected.
    [[nodiscard]] uint32_t position(FaceId x);
    /// Face at position k. \pre k < size(). O(log n) expected.
    [[nodiscard]] FaceId at(uint32_t k);
    /// Reverses positions [0, k) (front part) or [k, size) (back part). O(log n) expected.
    void reverse_front(uint32_t k);
    void reverse_back(uint32_t k);
    [[nodiscard]] uint32_t size() const { return count(root_); }
    [[nodiscard]] FaceId front() { return at(0); }
    [[nodiscard]] FaceId back() { return at(size() - 1); }
    /// The whole sequence, front to back. O(n).
    [[nodiscard]] std::vector<FaceId> items();

private:
    // A tree node is a face; kNone is no node.
    IdVector<FaceId, FaceId> left_, right_, parent_;
    IdVector<FaceId, uint32_t> size_;
    IdVector<FaceId, uint8_t> flip_;  ///< the subtree's order is reversed (not yet pushed down)
    FaceId root_;
    std::vector<FaceId> up_;  ///< scratch of position()

    [[nodiscard]] static uint32_t priority(FaceId x);
    /// Faces in the subtree of x (0 for kNone).
    [[nodiscard]] uint32_t count(FaceId x) const { return x == kNone ? 0 : size_[x]; }
    void push(FaceId x);
    void pull(FaceId x);
    std::vector<FaceId> spine_;  ///< scratch of build()

    /// Cartesian tree by priority of the items next() gives, in linear time (the right spine on
    /// a stack); `last` = the last item.
    template <class Next>
    [[nodiscard]] FaceId build(Next& next, FaceId& last) {
        spine_.clear();
        for (FaceId x = next(); x != kNone; x = next()) {
            last = x;
            right_[x] = parent_[x] = kNone;
            flip_[x] = 0;
            FaceId below = kNone;
            while (!spine_.empty() && priority(spine_.back()) < priority(x)) {
                below = spine_.back();
                spine_.pop_back();
                pull(below);
            }
            left_[x] = below;
            if (!spine_.empty()) right_[spine_.back()] = x;
            spine_.push_back(x);
        }
        while (spine_.size() > 1) {
            pull(spine_.back());
            spine_.pop_back();
        }
        if (spine_.empty()) return kNone;
        pull(spine_.front());
        parent_[spine_.front()] = kNone;
        return spine_.front();
    }
    [[nodiscard]] FaceId merge(FaceId a, FaceId b);
    void split(FaceId t, uint32_t k, FaceId& a, FaceId& b);
};

}  // namespace singlestrip
