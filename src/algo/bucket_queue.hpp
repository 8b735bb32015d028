// singlestrip — a priority queue over small integer keys (buckets), for the fewest-swap searches.
// Keys may go below the smallest popped so far (a search step may remove swaps). The buckets form
// a ring indexed by key modulo its size (Dial's queue), which doubles when the keys queued at once
// span more: over a whole search the keys may span far more than they do at any one time (a
// best-first forest over a 4M-face disk with holes: 458K keys over the search, about a thousand
// at once; buckets for the whole span, with the room of the drained ones, were 51 MB).
// push() is O(1) amortized, pop() O(1) plus the empty buckets it passes; a binary heap paid
// O(log n) for both.
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
    /// Empties the queue; buckets keep their room (the searches run many times, small).
    void clear() {
        if (size_ > 0)
            for (long k = lo_; k <= hi_; ++k) at(k).reset();
        size_ = 0;
    }
    [[nodiscard]] bool empty() const { return size_ == 0; }
    [[nodiscard]] size_t size() const { return size_; }
    void push(const T& e) {
        const long key = e.key();
        if (size_ == 0) {
            lo_ = hi_ = key;
        } else if (key < lo_ || key > hi_) {
            const long lo = std::min(lo_, key), hi = std::max(hi_, key);
            if (static_cast<size_t>(hi - lo) >= ring_.size()) regrow(static_cast<size_t>(hi - lo) + 1);
            lo_ = lo, hi_ = hi;
        }
        if (ring_.empty()) regrow(1);
        at(key).v.push_back(e);
        ++size_;
    }
    /// The entry of the least key. \pre !empty().
    [[nodiscard]] const T& top() {
        while (at(lo_).head == at(lo_).v.size()) at(lo_++).drain();
        return at(lo_).v[at(lo_).head];
    }
    T pop() {
        const T e = top();
        at(lo_).advance();
        --size_;
        return e;
    }

private:
    struct Bucket {
        std::vector<T> v;
        size_t head = 0;  ///< v[head..] still queued
        void reset() { v.clear(), head = 0; }
        // Popped entries are dropped once they are half of a large bucket (O(1) amortized): a
        // best-first search puts most faces under one key.
        void advance() {
            if (++head >= kLarge && 2 * head >= v.size()) {
                v.erase(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(head));
                head = 0;
            }
        }
        // A bucket popped to the end gives its room back: the ring may hold 10^5 buckets, and
        // room for up to 4096 entries kept in each was 23 MB of a 4M-face search's peak.
        void drain() { std::vector<T>().swap(v), head = 0; }
        static constexpr size_t kLarge = 4096;  ///< entries
    };
    std::vector<Bucket> ring_;  ///< key k in ring_[k mod size]; size a power of two
    size_t size_ = 0;           ///< entries queued
    long lo_ = 0, hi_ = 0;      ///< queued keys lie in [lo_, hi_] when size_ > 0

    Bucket& at(long key) { return ring_[static_cast<size_t>(key) & (ring_.size() - 1)]; }
    void regrow(size_t span) {
        size_t n = ring_.empty() ? 64 : ring_.size();
        while (n < span) n *= 2;
        std::vector<Bucket> next(n);
        if (size_ > 0)
            for (long k = lo_; k <= hi_; ++k) next[static_cast<size_t>(k) & (n - 1)] = std::move(at(k));
        ring_ = std::move(next);
    }
};

}  // namespace singlestrip
