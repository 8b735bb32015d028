// singlestrip — half-edges grouped by undirected edge (soup_edges.hpp).
#include "soup_edges.hpp"

namespace singlestrip {

SoupEdges::SoupEdges(const std::vector<Triangle>& triangles, size_t num_vertices, const std::vector<char>* usable)
    : triangles_(&triangles), start_(num_vertices + 1, 0) {
    const size_t nf = triangles.size();
    auto for_each_included = [&](auto&& fn) {
        for (size_t f = 0; f < nf; ++f) {
            const Triangle& t = triangles[f];
            if (usable && !(*usable)[f]) continue;
            for (uint32_t k = 0; k < 3; ++k)
                if (t[k] < num_vertices && t[(k + 1) % 3] < num_vertices) fn(static_cast<uint32_t>(3 * f + k));
        }
    };
    // Stable counting sort by the larger end, then by the smaller one: ordered by (lo, hi, h).
    std::vector<uint32_t> by_hi;
    for (int pass = 0; pass < 2; ++pass) {
        std::fill(start_.begin(), start_.end(), 0u);
        for_each_included([&](uint32_t h) { ++start_[(pass == 0 ? hi(h) : lo(h)) + 1]; });
        for (size_t v = 0; v < num_vertices; ++v) start_[v + 1] += start_[v];
        std::vector<uint32_t> out(start_[num_vertices]);
        std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
        if (pass == 0) {
            for_each_included([&](uint32_t h) { out[fill[hi(h)]++] = h; });
            by_hi = std::move(out);
        } else {
            for (uint32_t h : by_hi) out[fill[lo(h)]++] = h;
            halfedges_ = std::move(out);
        }
    }
}

bool SoupEdges::has_edge(uint32_t a, uint32_t b) const {
    const uint32_t l = std::min(a, b), u = std::max(a, b);
    if (u >= num_vertices()) return false;
    const auto first = halfedges_.begin() + start_[l], last = halfedges_.begin() + start_[l + 1];
    const auto it = std::lower_bound(first, last, u, [&](uint32_t h, uint32_t v) { return hi(h) < v; });
    return it != last && hi(*it) == u;
}

}  // namespace singlestrip
