// singlestrip — internal: growth of the arrays a split mesh appends to.
#pragma once

#include <algorithm>
#include <cstddef>

namespace singlestrip {

/// Makes room for n elements, growing by an eighth instead of doubling: splits add a few percent
/// to arrays of F elements, and doubling would hold up to twice their memory (issue 17's peak).
/// Still geometric, so appends stay amortised O(1).
template <class Vec>
void reserve_gently(Vec& v, size_t n) {
    if (n > v.capacity()) v.reserve(std::max(n, v.capacity() + v.capacity() / 8 + 64));
}

}  // namespace singlestrip
