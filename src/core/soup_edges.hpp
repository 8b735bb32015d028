// singlestrip — internal: the half-edges of a triangle list grouped by undirected edge, the one
// edge pairing the library builds its topology on (Mesh::from_soup, validate.cpp's analysis, the
// constraint-edge checks). The verifier keeps its own independent copy on purpose.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// Half-edge h = 3f + k runs from triangles[f][k] to triangles[f][(k + 1) % 3]. `halfedges` lists
/// them ordered by (smaller end, larger end, h): the half-edges of one undirected edge are
/// adjacent, and start[v] .. start[v + 1] is the range whose smaller end is v.
class SoupEdges {
public:
    /// Leaves out the faces with usable[f] == 0 (when `usable` is given) and any half-edge with an
    /// end >= num_vertices. Two stable counting sorts, no comparisons: O(V + F).
    SoupEdges(const std::vector<Triangle>& triangles, size_t num_vertices, const std::vector<char>* usable = nullptr);

    [[nodiscard]] uint32_t from(uint32_t h) const { return (*triangles_)[h / 3][h % 3]; }
    [[nodiscard]] uint32_t to(uint32_t h) const { return (*triangles_)[h / 3][(h % 3 + 1) % 3]; }
    [[nodiscard]] uint32_t lo(uint32_t h) const { return std::min(from(h), to(h)); }
    [[nodiscard]] uint32_t hi(uint32_t h) const { return std::max(from(h), to(h)); }
    [[nodiscard]] size_t num_vertices() const { return start_.size() - 1; }

    /// Calls fn(lo, hi, first, last) for every undirected edge, in (lo, hi) order; [first, last)
    /// are its half-edges (iterators into halfedges()), ascending.
    template <class Fn>
    void for_each_edge(Fn&& fn) const {
        for (size_t v = 0; v + 1 < start_.size(); ++v) {
            const auto b = halfedges_.begin() + start_[v], e = halfedges_.begin() + start_[v + 1];
            for (auto i = b; i != e;) {
                const uint32_t other = hi(*i);
                auto j = i + 1;
                while (j != e && hi(*j) == other) ++j;
                fn(static_cast<uint32_t>(v), other, i, j);
                i = j;
            }
        }
    }

    /// Whether some half-edge joins a and b (either way). O(log degree).
    [[nodiscard]] bool has_edge(uint32_t a, uint32_t b) const;

private:
    const std::vector<Triangle>* triangles_;
    std::vector<uint32_t> start_, halfedges_;
};

}  // namespace singlestrip
