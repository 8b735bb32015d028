// PathOrder (src/algo/path_order.hpp), the matching engine's sequence with reversals, against a plain
// vector doing the same operations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "../src/algo/path_order.hpp"

namespace singlestrip {
namespace {

// Rounds of up to 300 faces, then a few of up to 5000 (deeper trees, longer splay paths).
TEST(PathOrder, RandomOperationsMatchAVector) {
    std::mt19937 rng(7);
    for (int round = 0; round < 26; ++round) {
        const uint32_t n = 1 + rng() % (round < 20 ? 300 : 5000);
        PathOrder order(n);
        std::vector<FaceId> ref, pending(n);
        for (uint32_t i = 0; i < n; ++i) pending[i] = FaceId(i);
        std::shuffle(pending.begin(), pending.end(), rng);
        while (!pending.empty() || ref.size() < n) {
            const uint32_t op = rng() % 5;
            if (op <= 1 && !pending.empty()) {  // append or prepend a batch
                const size_t k = 1 + rng() % std::min<size_t>(pending.size(), 9);
                std::vector<FaceId> batch(pending.end() - k, pending.end());
                pending.resize(pending.size() - k);
                if (op == 0) {
                    order.append(batch);
                    ref.insert(ref.end(), batch.begin(), batch.end());
                } else {
                    order.prepend(batch);
                    ref.insert(ref.begin(), batch.rbegin(), batch.rend());
                }
            } else if (!ref.empty()) {
                const uint32_t k = rng() % (ref.size() + 1);
                if (op == 2) {
                    order.reverse_front(k);
                    std::reverse(ref.begin(), ref.begin() + k);
                } else if (op == 3) {
                    order.reverse_back(k);
                    std::reverse(ref.begin() + k, ref.end());
                } else {
                    const FaceId x = ref[rng() % ref.size()];
                    ASSERT_EQ(ref[order.position(x)], x);
                    const uint32_t p = rng() % ref.size();
                    ASSERT_EQ(order.at(p), ref[p]);
                }
            }
            ASSERT_EQ(order.size(), ref.size());
        }
        EXPECT_EQ(order.items(), ref);
        EXPECT_EQ(order.front(), ref.front());
        EXPECT_EQ(order.back(), ref.back());
    }
}

}  // namespace
}  // namespace singlestrip
