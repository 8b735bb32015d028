// Z-order of face centroids (face_order.hpp).
#include "face_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "singlestrip/mesh.hpp"

namespace singlestrip {
namespace {

constexpr uint32_t kBitsPerAxis = 10;
constexpr uint32_t kDigitBits = 15;  ///< two counting-sort passes over a 30-bit code

/// The bits of x (kBitsPerAxis of them) spread to every third bit.
uint32_t spread3(uint32_t x) {
    x &= 0x3ffu;
    x = (x | (x << 16)) & 0x30000ffu;
    x = (x | (x << 8)) & 0x300f00fu;
    x = (x | (x << 4)) & 0x30c30c3u;
    return (x | (x << 2)) & 0x9249249u;
}

Point3 centroid(const std::vector<Point3>& points, const Triangle& t) {
    Point3 c{};
    for (int i = 0; i < 3; ++i) c[i] = (points[t[0]][i] + points[t[1]][i] + points[t[2]][i]) / 3.0;
    return c;
}

// The box is the points' (one sequential pass), not the centroids': an unused far point only
// coarsens the grid, which costs locality, never correctness.
std::vector<uint32_t> morton_codes(const std::vector<Point3>& points, const std::vector<Triangle>& triangles) {
    Point3 lo{}, hi{};
    for (int i = 0; i < 3; ++i) lo[i] = std::numeric_limits<double>::max(), hi[i] = std::numeric_limits<double>::lowest();
    for (const Point3& p : points)
        for (int i = 0; i < 3; ++i)
            if (std::isfinite(p[i])) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
    std::vector<uint32_t> code(triangles.size());
    const double cells = (1u << kBitsPerAxis) - 1;
    for (size_t f = 0; f < triangles.size(); ++f) {
        const Point3 c = centroid(points, triangles[f]);
        uint32_t key = 0;
        for (int i = 0; i < 3; ++i) {
            const double extent = hi[i] - lo[i];
            const double s = std::isfinite(c[i]) && extent > 0 ? (c[i] - lo[i]) / extent : 0.0;
            key |= spread3(static_cast<uint32_t>(std::clamp(s, 0.0, 1.0) * cells)) << i;
        }
        code[f] = key;
    }
    return code;
}

}  // namespace

std::vector<uint32_t> spatial_face_order(const std::vector<Point3>& points, const std::vector<Triangle>& triangles) {
    const std::vector<uint32_t> code = morton_codes(points, triangles);
    const size_t nf = triangles.size();
    std::vector<uint32_t> order(nf), next(nf);
    for (size_t f = 0; f < nf; ++f) order[f] = static_cast<uint32_t>(f);
    for (uint32_t shift = 0; shift < 3 * kBitsPerAxis; shift += kDigitBits) {
        std::vector<uint32_t> start((1u << kDigitBits) + 1, 0);
        auto digit = [&](uint32_t f) { return (code[f] >> shift) & ((1u << kDigitBits) - 1); };
        for (uint32_t f : order) ++start[digit(f) + 1];
        for (size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
        for (uint32_t f : order) next[start[digit(f)]++] = f;
        order.swap(next);
    }
    return order;
}

double far_neighbour_share(const std::vector<uint32_t>& twin, uint32_t distance) {
    uint64_t interior = 0, far = 0;
    for (size_t h = 0; h < twin.size(); ++h) {
        if (twin[h] == kNone || twin[h] < h) continue;
        ++interior;
        far += twin[h] / 3 - h / 3 >= distance ? 1 : 0;
    }
    return interior ? static_cast<double>(far) / static_cast<double>(interior) : 0.0;
}

}  // namespace singlestrip
