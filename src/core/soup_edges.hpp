// singlestrip — internal: the half-edges of a triangle list grouped by undirected edge and each
// edge classified, the one edge pairing the library builds its topology on (Mesh::from_soup,
// validate.cpp's analysis, repair.cpp, the generators in models.cpp, the constraint-edge check).
// The verifier keeps its own independent copy on purpose.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// What an undirected edge of a soup is, by the half-edges on it: the one classification the
/// library's topology uses (Mesh::from_soup, validate.cpp's analysis, repair.cpp).
enum class EdgeKind : uint8_t {
    boundary,      ///< one half-edge
    manifold,      ///< two half-edges running opposite ways: an interior edge
    inconsistent,  ///< two half-edges running the same way: the faces disagree on orientation
    non_manifold,  ///< three or more half-edges
};

/// Half-edge h = 3f + k runs from triangles[f][k] to triangles[f][(k + 1) % 3]. `halfedges` lists
/// them ordered by (smaller end, larger end, h): the half-edges of one undirected edge are
/// adjacent, and start[v] .. start[v + 1] is the range whose smaller end is v.
/// The triangles must outlive the SoupEdges and keep their vertices while it is used.
class SoupEdges {
public:
    using Iterator = std::vector<uint32_t>::const_iterator;

    /// One undirected edge: its ends lo < hi, its kind, its half-edges [first, last) ascending.
    struct Edge {
        uint32_t lo, hi;
        EdgeKind kind;
        Iterator first, last;
        [[nodiscard]] size_t num_halfedges() const { return static_cast<size_t>(last - first); }
    };

    /// Leaves out the faces with usable[f] == 0 (when `usable` is given) and any half-edge with an
    /// end >= num_vertices. A counting sort by the smaller end and insertion sorts of each end's
    /// few half-edges, or two stable counting sorts where an end has many: O(V + F). No errors (a
    /// face that repeats a vertex gives half-edges with lo == hi, grouped like any other).
    SoupEdges(const std::vector<Triangle>& triangles, size_t num_vertices, const std::vector<char>* usable = nullptr);

    [[nodiscard]] uint32_t from(uint32_t h) const { return (*triangles_)[h / 3][h % 3]; }
    [[nodiscard]] uint32_t to(uint32_t h) const { return (*triangles_)[h / 3][(h % 3 + 1) % 3]; }
    [[nodiscard]] uint32_t lo(uint32_t h) const { return std::min(from(h), to(h)); }
    [[nodiscard]] uint32_t hi(uint32_t h) const { return std::max(from(h), to(h)); }
    [[nodiscard]] size_t num_vertices() const { return start_.size() - 1; }

    /// The kind of the edge whose half-edges are [first, last) (one group of halfedges()). O(1).
    [[nodiscard]] EdgeKind classify(Iterator first, Iterator last) const {
        const auto n = last - first;
        if (n == 1) return EdgeKind::boundary;
        if (n > 2) return EdgeKind::non_manifold;
        return from(first[0]) == from(first[1]) ? EdgeKind::inconsistent : EdgeKind::manifold;
    }

    /// Calls fn(const Edge&) for every undirected edge, in (lo, hi) order. O(V + F) in all.
    template <class Fn>
    void for_each_edge(Fn&& fn) const {
        for_each_edge(0, num_vertices(), fn);
    }
    /// The same for the edges whose smaller end is in [v_begin, v_end).
    template <class Fn>
    void for_each_edge(size_t v_begin, size_t v_end, Fn&& fn) const {
        for (size_t v = v_begin; v < v_end; ++v) {
            const Iterator b = halfedges_.begin() + start_[v], e = halfedges_.begin() + start_[v + 1];
            for (Iterator i = b; i != e;) {
                const uint32_t other = hi(*i);
                Iterator j = i + 1;
                while (j != e && hi(*j) == other) ++j;
                fn(Edge{static_cast<uint32_t>(v), other, classify(i, j), i, j});
                i = j;
            }
        }
    }

    /// Sets twin[h0] = h1 and twin[h1] = h0 for the two half-edges of a manifold or inconsistent
    /// edge (twin indexed by half-edge). \pre e.num_halfedges() == 2.
    static void pair(const Edge& e, std::vector<uint32_t>& twin) {
        twin[e.first[0]] = e.first[1];
        twin[e.first[1]] = e.first[0];
    }

    /// The smaller end below which half the half-edges lie (to split for_each_edge in two). O(log V).
    [[nodiscard]] uint32_t middle_vertex() const {
        const uint32_t half = start_.back() / 2;
        return static_cast<uint32_t>(std::lower_bound(start_.begin(), start_.end(), half) - start_.begin());
    }

    /// Whether some half-edge joins a and b (either way). O(log degree).
    [[nodiscard]] bool has_edge(uint32_t a, uint32_t b) const;

private:
    void sort_by_smaller_end(const std::vector<char>* usable);
    void insertion_sort(uint32_t first, uint32_t last, std::vector<uint32_t>& his);
    void sort_two_pass(const std::vector<char>* usable);
    const std::vector<Triangle>* triangles_;
    std::vector<uint32_t> start_, halfedges_;
};

}  // namespace singlestrip
