// singlestrip — a priority queue over small integer keys (buckets), for the fewest-swap searches.
// Keys may go below the smallest popped so far (a search step may remove swaps), so the buckets
// grow at either end (by doubling). push() is O(1) amortized, pop() O(1) plus the empty buckets it passes; a
// binary heap paid O(log n) for both (the searches' queue holds up to ~1000 entries).
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace singlestrip {

/// T: an entry with an `int key() const`. Entries of one key come out first in, first out.
template <class T>
class BucketQueue {
public:
    void clear() {
        for (size_t i = 0; i < used_; ++i) buckets_[i].v.clear(), buckets_[i].head = 0;
        used_ = size_ = cur_ = 0;
    }
    [[nodiscard]] bool empty() const { return size_ == 0; }
    [[nodiscard]] size_t size() const { return size_; }
    void push(const T& e) {
        const int key = e.key();
        if (used_ == 0) base_ = key;
        // Room below for at least as many keys as are in use: a chain of steps that each remove a
        // swap lowers the key by one per push, and a shift per push cost O(range) each (a grid
        // with sparse holes, 1M: a quarter of the strip stage).
        if (key < base_) shift(std::max(static_cast<size_t>(base_ - key), used_));
        const size_t i = static_cast<size_t>(key - base_);
        if (i >= used_) grow(i + 1);
        buckets_[i].v.push_back(e);
        if (i < cur_ || size_ == 0) cur_ = i;
        ++size_;
    }
    /// The entry of the least key. \pre !empty().
    [[nodiscard]] const T& top() {
        while (buckets_[cur_].head == buckets_[cur_].v.size()) ++cur_;
        return buckets_[cur_].v[buckets_[cur_].head];
    }
    T pop() {
        const T e = top();
        ++buckets_[cur_].head;
        --size_;
        return e;
    }

private:
    struct Bucket {
        std::vector<T> v;
        size_t head = 0;  ///< v[head..] still queued
        void swap(Bucket& o) noexcept { v.swap(o.v), std::swap(head, o.head); }
    };
    std::vector<Bucket> buckets_;           ///< [0, used_): keys base_ + i; the rest spare, empty
    size_t used_ = 0, size_ = 0, cur_ = 0;  ///< cur_: no entry below it
    int base_ = 0;

    void grow(size_t n) {
        if (buckets_.size() < n) buckets_.resize(n);
        used_ = n;
    }
    void shift(size_t by) {  // room for `by` keys below base_
        grow(used_ + by);
        for (size_t i = used_; i-- > by;) buckets_[i].swap(buckets_[i - by]);
        base_ -= static_cast<int>(by);
        cur_ += by;
    }
};

}  // namespace singlestrip
