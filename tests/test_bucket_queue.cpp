// BucketQueue (src/algo/bucket_queue.hpp), the fewest-swap searches' queue, against a reference:
// std::map of key -> FIFO. Keys far below and above those queued, falling runs, large buckets
// popped while pushed to, and clear() between searches.
#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <map>
#include <random>

#include "../src/algo/bucket_queue.hpp"

namespace {

struct Entry {
    int k;
    uint32_t id;
    [[nodiscard]] int key() const { return k; }
};

class Reference {
public:
    void push(Entry e) { by_key_[e.k].push_back(e.id), ++size_; }
    uint32_t pop() {
        auto it = by_key_.begin();
        const uint32_t id = it->second.front();
        it->second.pop_front();
        if (it->second.empty()) by_key_.erase(it);
        --size_;
        return id;
    }
    [[nodiscard]] int top_key() const { return by_key_.begin()->first; }
    [[nodiscard]] size_t size() const { return size_; }
    void clear() { by_key_.clear(), size_ = 0; }

private:
    std::map<int, std::deque<uint32_t>> by_key_;
    size_t size_ = 0;
};

// Pops one entry from both and checks they agree (the least key, first in first out).
void pop_both(singlestrip::BucketQueue<Entry>& q, Reference& ref) {
    ASSERT_FALSE(q.empty());
    ASSERT_EQ(q.top().k, ref.top_key());
    ASSERT_EQ(q.pop().id, ref.pop());
    ASSERT_EQ(q.size(), ref.size());
}

TEST(BucketQueue, MatchesAnOrderedMapOnRandomSearches) {
    std::mt19937 rng(7);
    singlestrip::BucketQueue<Entry> q;
    uint32_t id = 0;
    for (int search = 0; search < 60; ++search) {
        Reference ref;
        q.clear();
        // Keys drift like a search's: around the last popped, sometimes far (a long chain of
        // swap-removing steps), sometimes the same key many times (a large bucket).
        int at = static_cast<int>(rng() % 2001) - 1000;
        const int spread = search % 3 == 0 ? 5000 : 8;  // pop() passes the empty keys between
        const int steps = 2000 + static_cast<int>(rng() % 20000);
        for (int s = 0; s < steps; ++s) {
            const uint32_t op = rng() % 10;
            if (op < 6 || ref.size() == 0) {
                const int key = op == 0 ? at + static_cast<int>(rng() % (2 * spread + 1)) - spread : at + static_cast<int>(rng() % 3) - 1;
                q.push({key, id}), ref.push({key, id}), ++id;
                ASSERT_EQ(q.size(), ref.size());
            } else {
                at = ref.top_key();
                pop_both(q, ref);
            }
        }
        // Half the searches end with entries still queued (a search that found its path).
        if (search % 2 == 0)
            while (ref.size() > 0) pop_both(q, ref);
    }
}

TEST(BucketQueue, FallingKeysAndOneLargeBucket) {
    singlestrip::BucketQueue<Entry> q;
    Reference ref;
    uint32_t id = 0;
    // A falling run far below the first key, then 50K entries under one key popped while pushed.
    q.push({1000, id}), ref.push({1000, id}), ++id;
    for (int k = 999; k > -300000; k -= 7) q.push({k, id}), ref.push({k, id}), ++id;
    for (int i = 0; i < 50000; ++i) {
        q.push({-400000, id}), ref.push({-400000, id}), ++id;
        if (i % 2 == 1) pop_both(q, ref);
    }
    while (ref.size() > 0) pop_both(q, ref);
    EXPECT_TRUE(q.empty());
    q.push({5, id});
    EXPECT_EQ(q.top().k, 5);
}

}  // namespace
