// singlestrip — internal: the Euler characteristic and the genus from counts, the one formula
// the library uses for both (Mesh::euler_characteristic/genus, validate.cpp's mesh_info). The
// verifier keeps its own independent copy on purpose.
#pragma once

#include <cstdint>

namespace singlestrip {

/// chi = V - E + F. No preconditions or errors (counts below 2^63). O(1).
constexpr long long euler_characteristic(uint64_t vertices, uint64_t edges, uint64_t faces) noexcept {
    return static_cast<long long>(vertices) - static_cast<long long>(edges) + static_cast<long long>(faces);
}

/// The genus g of an orientable surface by chi = 2c - 2g - b: (2c - chi - b) / 2, summed over
/// its c components (b boundary loops in all). Meaningful only for a manifold orientable surface
/// (the caller says when it is); otherwise a number without meaning, never an error. O(1).
constexpr long long genus_from_euler(long long euler_characteristic, uint64_t boundary_loops, uint64_t components) noexcept {
    return (2 * static_cast<long long>(components) - euler_characteristic - static_cast<long long>(boundary_loops)) / 2;
}

}  // namespace singlestrip
