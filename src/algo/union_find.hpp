// Disjoint sets over 0..n-1 (path halving, union by size), shared by the algorithms that group
// faces or corners (repair's fans, the replayed cycles' regions) and by the tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace singlestrip {

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), 0u); }
    /// The representative of x's set. Amortised O(log n).
    uint32_t find(uint32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    /// Merges the sets of a and b; false when they were already one.
    bool unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        if (size_[a] < size_[b]) std::swap(a, b);
        parent_[b] = a;
        size_[a] += size_[b];
        return true;
    }

private:
    std::vector<uint32_t> parent_, size_;
};

}  // namespace singlestrip
