// singlestrip — half-edges grouped by undirected edge (soup_edges.hpp).
#include "soup_edges.hpp"

#include "two_halves.hpp"

namespace singlestrip {

namespace {

constexpr uint32_t kSmallBucket = 64;  ///< insertion sort up to this many half-edges at one end

/// Calls fn(h) for every half-edge of a usable face whose two ends are below nv, h ascending.
template <class Fn>
void for_each_included(const std::vector<Triangle>& triangles, size_t nv, const std::vector<char>* usable, Fn&& fn) {
    for (size_t f = 0; f < triangles.size(); ++f) {
        const Triangle& t = triangles[f];
        if (usable && !(*usable)[f]) continue;
        for (uint32_t k = 0; k < 3; ++k)
            if (t[k] < nv && t[(k + 1) % 3] < nv) fn(static_cast<uint32_t>(3 * f + k));
    }
}

}  // namespace

SoupEdges::SoupEdges(const std::vector<Triangle>& triangles, size_t num_vertices, const std::vector<char>* usable)
    : triangles_(&triangles), start_(num_vertices + 1, 0) {
    for_each_included(triangles, num_vertices, usable, [&](uint32_t h) { ++start_[lo(h) + 1]; });
    uint32_t largest = 0;
    for (size_t v = 0; v < num_vertices; ++v) largest = std::max(largest, start_[v + 1]);
    if (largest <= kSmallBucket)
        sort_by_smaller_end(usable);
    else
        sort_two_pass(usable);
}

// One counting sort by the smaller end (start_ holds the counts), then each end's few
// half-edges insertion-sorted by the larger one: stable, so h stays ascending. `his` keeps the
// larger ends beside the half-edges so the sort reads no triangle twice.
void SoupEdges::sort_by_smaller_end(const std::vector<char>* usable) {
    const size_t nv = num_vertices();
    for (size_t v = 0; v < nv; ++v) start_[v + 1] += start_[v];
    halfedges_.resize(start_[nv]);
    std::vector<uint32_t> his(halfedges_.size());
    {
        std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
        for_each_included(*triangles_, nv, usable, [&](uint32_t h) {
            const uint32_t a = from(h), b = to(h), at = fill[std::min(a, b)]++;
            halfedges_[at] = h;
            his[at] = std::max(a, b);
        });
    }
    // Each end's range is its own: two halves of the ends sort at once on a large soup.
    run_in_two_halves(middle_vertex(), static_cast<uint32_t>(nv), halfedges_.size() >= 3 * kTwoThreadFaces,
                      [&](uint32_t v_begin, uint32_t v_end) {
                          for (uint32_t v = v_begin; v < v_end; ++v) insertion_sort(start_[v], start_[v + 1], his);
                      });
}

void SoupEdges::insertion_sort(uint32_t first, uint32_t last, std::vector<uint32_t>& his) {
    for (uint32_t i = first + 1; i < last; ++i) {
        const uint32_t h = halfedges_[i], key = his[i];
        uint32_t j = i;
        for (; j > first && his[j - 1] > key; --j) {
            halfedges_[j] = halfedges_[j - 1];
            his[j] = his[j - 1];
        }
        halfedges_[j] = h;
        his[j] = key;
    }
}

// A vertex of high valence: stable counting sorts by the larger end, then by the smaller one
// (linear whatever the valence).
void SoupEdges::sort_two_pass(const std::vector<char>* usable) {
    const size_t nv = num_vertices();
    std::vector<uint32_t> by_hi;
    for (int pass = 0; pass < 2; ++pass) {
        std::fill(start_.begin(), start_.end(), 0u);
        for_each_included(*triangles_, nv, usable, [&](uint32_t h) { ++start_[(pass == 0 ? hi(h) : lo(h)) + 1]; });
        for (size_t v = 0; v < nv; ++v) start_[v + 1] += start_[v];
        std::vector<uint32_t> out(start_[nv]);
        std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
        if (pass == 0) {
            for_each_included(*triangles_, nv, usable, [&](uint32_t h) { out[fill[hi(h)]++] = h; });
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
