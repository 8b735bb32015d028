// Z-order of face centroids (face_order.hpp).
#include "face_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "singlestrip/mesh.hpp"
#include "singlestrip/vec3.hpp"

namespace singlestrip {
namespace {

constexpr uint32_t kBitsPerAxis = 10;
constexpr uint32_t kDigitBits = 10;  ///< three counting-sort passes over a 30-bit code (1024 buckets stay in cache)

/// The bits of x (kBitsPerAxis of them) spread to every third bit.
uint32_t spread3(uint32_t x) {
    x &= 0x3ffu;
    x = (x | (x << 16)) & 0x30000ffu;
    x = (x | (x << 8)) & 0x300f00fu;
    x = (x | (x << 4)) & 0x30c30c3u;
    return (x | (x << 2)) & 0x9249249u;
}

Point3 centroid(const std::vector<Point3>& points, const Triangle& t) {
    return vec3::centroid(points[t[0]], points[t[1]], points[t[2]]);
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
            // In halves: the extent of coordinates near +-1.7e308 overflows; s NaN-free.
            const double extent = hi[i] * 0.5 - lo[i] * 0.5;
            const double s = std::isfinite(c[i]) && extent > 0 ? (c[i] * 0.5 - lo[i] * 0.5) / extent : 0.0;
            key |= spread3(static_cast<uint32_t>(std::clamp(s >= 0 ? s : 0.0, 0.0, 1.0) * cells)) << i;
        }
        code[f] = key;
    }
    return code;
}

}  // namespace

std::vector<uint32_t> spatial_face_order(const std::vector<Point3>& points, const std::vector<Triangle>& triangles) {
    const size_t nf = triangles.size();
    // (code, face) in one word, so each pass reads its keys in sequence.
    std::vector<uint64_t> keys(nf), next(nf);
    {
        const std::vector<uint32_t> code = morton_codes(points, triangles);
        for (size_t f = 0; f < nf; ++f) keys[f] = uint64_t{code[f]} << 32 | f;
    }
    for (uint32_t shift = 32; shift < 32 + 3 * kBitsPerAxis; shift += kDigitBits) {
        std::vector<size_t> start((size_t{1} << kDigitBits) + 1, 0);
        auto digit = [&](uint64_t k) { return static_cast<size_t>(k >> shift) & ((size_t{1} << kDigitBits) - 1); };
        for (uint64_t k : keys) ++start[digit(k) + 1];
        for (size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
        for (uint64_t k : keys) next[start[digit(k)]++] = k;
        keys.swap(next);
    }
    std::vector<uint32_t> order(nf);
    for (size_t i = 0; i < nf; ++i) order[i] = static_cast<uint32_t>(keys[i]);
    return order;
}

namespace {

constexpr size_t kMinFaces = size_t{1} << 18;

/// Whether the consecutive faces' lowest vertices jump far in more than a quarter of the steps:
/// an eighth of the numbers (at most 32768) is far, a sweep's rows are much shorter.
bool numbers_scattered(const std::vector<Triangle>& t, size_t num_vertices) {
    const auto far = static_cast<uint32_t>(std::clamp<size_t>(num_vertices / 8, 256, 32768));
    constexpr double kMaxScattered = 0.25;  ///< a sweep's rows jump about once a row
    size_t scattered = 0;
    uint32_t last = 0;
    for (size_t f = 0; f < t.size(); ++f) {
        const uint32_t low = std::min({t[f][0], t[f][1], t[f][2]});
        scattered += f > 0 && (low > last ? low - last : last - low) >= far ? 1 : 0;
        last = low;
    }
    return static_cast<double>(scattered) > kMaxScattered * static_cast<double>(t.size());
}

}  // namespace

std::vector<uint32_t> locality_order(const TriangleSoup& soup) {
    const auto& t = soup.triangles;
    if (t.size() < kMinFaces) return {};
    for (const Triangle& tri : t)
        if (std::max({tri[0], tri[1], tri[2]}) >= soup.points.size()) return {};
    if (!numbers_scattered(t, soup.points.size())) return {};
    return spatial_face_order(soup.points, t);
}

std::vector<uint32_t> locality_vertex_order(const TriangleSoup& soup) {
    if (soup.triangles.size() < kMinFaces || !numbers_scattered(soup.triangles, soup.points.size())) return {};
    const size_t nv = soup.points.size();
    std::vector<char> seen(nv, 0);
    std::vector<uint32_t> origin;
    origin.reserve(nv);
    for (const Triangle& t : soup.triangles)
        for (const uint32_t v : t)
            if (!seen[v]) seen[v] = 1, origin.push_back(v);
    for (uint32_t v = 0; v < nv; ++v)
        if (!seen[v]) origin.push_back(v);
    return origin;
}

std::vector<uint32_t> inverse_permutation(const std::vector<uint32_t>& p) {
    std::vector<uint32_t> inv(p.size());
    for (uint32_t i = 0; i < p.size(); ++i) inv[p[i]] = i;
    return inv;
}

void permute_vertices(TriangleSoup& soup, const std::vector<uint32_t>& origin, bool back) {
    const size_t nv = origin.size();
    const std::vector<uint32_t> to = back ? origin : inverse_permutation(origin);  // current number -> new
    std::vector<Point3> points(nv);
    for (uint32_t v = 0; v < nv; ++v) points[to[v]] = soup.points[v];
    soup.points = std::move(points);
    for (Triangle& t : soup.triangles)
        for (uint32_t& v : t) v = to[v];
    for (VertexAttribute& a : soup.attributes) {
        std::vector<double> values(a.values.size());
        const size_t c = a.components;
        for (uint32_t v = 0; v < nv; ++v) std::copy_n(a.values.begin() + v * c, c, values.begin() + to[v] * c);
        a.values = std::move(values);
    }
}

}  // namespace singlestrip
