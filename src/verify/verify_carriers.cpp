// singlestrip — output faces' parents from the split structure, for outputs that carry no
// parent array (glTF, OBJ, OFF). Every inserted vertex is the midpoint of two earlier vertices
// (the engines append them in creation order); found again, it gives each vertex its carrier,
// the smallest input cell holding it (a vertex, an edge or a face), and each output face the
// input face that holds its three carriers. Needs no tolerance: where float32 rounding makes
// needles collapse (an ear thinner than a float32 step), geometry cannot tell neighbouring
// faces apart, this can. The geometry checks then test what it found like a given parent.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

#include "verify_checks.hpp"

namespace singlestrip::verify_detail {

namespace {

/// The smallest input cell holding a point: vertex a (dim 0), edge {a, b} (dim 1), face a
/// (dim 2); dim 3: unknown.
struct Cell {
    uint8_t dim = 3;
    uint32_t a = 0, b = 0;
};

class Cells {
public:
    explicit Cells(const std::vector<Triangle>& faces) : faces_(faces) {
        face_of_.reserve(3 * faces.size());
        for (uint32_t f = 0; f < faces.size(); ++f)
            for (size_t i = 0; i < 3; ++i) face_of_.push_back({key(faces[f][i], faces[f][(i + 1) % 3]), f});
        std::sort(face_of_.begin(), face_of_.end());
    }

    /// The input face holding the directed edge u -> w, or kNo.
    [[nodiscard]] uint32_t face_of(uint32_t u, uint32_t w) const {
        const uint64_t k = key(u, w);
        const auto it = std::lower_bound(face_of_.begin(), face_of_.end(), std::pair<uint64_t, uint32_t>{k, 0});
        return it != face_of_.end() && it->first == k ? it->second : kNo;
    }
    [[nodiscard]] bool has(uint32_t f, uint32_t v) const { return faces_[f][0] == v || faces_[f][1] == v || faces_[f][2] == v; }

    /// The smallest cell holding both cells' points (and so their midpoint), or dim 3.
    [[nodiscard]] Cell meet(const Cell& x, const Cell& y) const {
        if (x.dim > y.dim) return meet(y, x);
        if (x.dim == 3 || y.dim == 3) return {};
        if (x.dim == 0 && y.dim == 0) {
            if (x.a == y.a) return x;
            return edge_faces(x.a, y.a).empty() ? Cell{} : Cell{1, std::min(x.a, y.a), std::max(x.a, y.a)};
        }
        if (x.dim == 0 && y.dim == 1) {
            if (x.a == y.a || x.a == y.b) return y;
            return face_with(edge_faces(y.a, y.b), {x.a});
        }
        if (y.dim == 2) return holds(y.a, x) ? y : Cell{};
        // Two edges.
        if (x.a == y.a && x.b == y.b) return x;
        return face_with(edge_faces(x.a, x.b), {y.a, y.b});
    }

private:
    static uint64_t key(uint32_t u, uint32_t w) { return (uint64_t{u} << 32) | w; }
    [[nodiscard]] std::vector<uint32_t> edge_faces(uint32_t u, uint32_t w) const {
        std::vector<uint32_t> out;
        for (uint32_t f : {face_of(u, w), face_of(w, u)})
            if (f != kNo) out.push_back(f);
        return out;
    }
    [[nodiscard]] bool holds(uint32_t f, const Cell& c) const {
        if (c.dim == 2) return c.a == f;
        return has(f, c.a) && (c.dim == 0 || has(f, c.b));
    }
    [[nodiscard]] Cell face_with(const std::vector<uint32_t>& cand, std::initializer_list<uint32_t> vs) const {
        for (uint32_t f : cand)
            if (std::all_of(vs.begin(), vs.end(), [&](uint32_t v) { return has(f, v); })) return {2, f, 0};
        return {};
    }

    const std::vector<Triangle>& faces_;
    std::vector<std::pair<uint64_t, uint32_t>> face_of_;  // (directed input edge, its face), sorted
};

/// Output vertex -> neighbouring output vertices (CSR).
struct Neighbours {
    std::vector<uint32_t> offset, list;
    Neighbours(size_t n, const std::vector<Triangle>& faces) : offset(n + 1, 0) {
        auto in_range = [n](const Triangle& t) { return t[0] < n && t[1] < n && t[2] < n; };  // garbage is skipped
        for (const Triangle& t : faces)
            if (in_range(t))
                for (uint32_t v : t) offset[v + 1] += 2;
        for (size_t i = 0; i < n; ++i) offset[i + 1] += offset[i];
        list.resize(offset[n]);
        std::vector<uint32_t> fill(offset.begin(), offset.end() - 1);
        for (const Triangle& t : faces)
            if (in_range(t))
                for (size_t i = 0; i < 3; ++i) {
                    list[fill[t[i]]++] = t[(i + 1) % 3];
                    list[fill[t[i]]++] = t[(i + 2) % 3];
                }
    }
};

/// The engines' midpoint (vec3::mid): halves added only where the sum overflows.
double half_sum(double a, double b) {
    const double s = a + b;
    return std::isfinite(s) ? s * 0.5 : a * 0.5 + b * 0.5;
}

bool same_stored(const Point3& computed, const Point3& stored, bool float32) {
    for (size_t k = 0; k < 3; ++k)
        if (float32 ? static_cast<float>(computed[k]) != static_cast<float>(stored[k]) : computed[k] != stored[k]) return false;
    return true;
}

/// Vertices below s reachable from s through vertices above it: the ends of the edge s split,
/// even after later splits of its halves put inserted vertices between (at most kReach visited,
/// kEnds kept: the pairs tried stay bounded around a vertex of high valence).
void earlier_ends(uint32_t s, const Neighbours& nb, std::vector<uint32_t>& seen, std::vector<uint32_t>& stack, std::vector<uint32_t>& out) {
    constexpr size_t kReach = 256, kEnds = 128;
    out.clear();
    stack.assign(1, s);
    seen[s] = s;
    size_t visited = 0;
    while (!stack.empty() && visited < kReach) {
        const uint32_t v = stack.back();
        stack.pop_back();
        ++visited;
        for (uint32_t i = nb.offset[v]; i < nb.offset[v + 1]; ++i) {
            const uint32_t w = nb.list[i];
            if (seen[w] == s) continue;
            seen[w] = s;
            if (w >= s) {
                stack.push_back(w);
                continue;
            }
            out.push_back(w);
            if (out.size() == kEnds) return;
        }
    }
}

/// Every face around s whose other corners are known fits in one input face with s in cell c.
bool fits_around(uint32_t s, const Cell& c, const Neighbours& nb, const Cells& cells, const std::vector<Cell>& cell) {
    for (uint32_t i = nb.offset[s]; i < nb.offset[s + 1]; i += 2) {
        const uint32_t a = nb.list[i], b = nb.list[i + 1];
        if (a < s && b < s && cells.meet(cells.meet(cell[a], cell[b]), c).dim != 2) return false;
    }
    return true;
}

/// A face with three input vertices is its own parent when it is an input face; one with two
/// lies in the one input face holding the directed edge between them (a child keeps its
/// parent's orientation; the face across holds that edge reversed); the others in the face
/// holding their vertices' carriers.
uint32_t parent_of(const Triangle& t, size_t n, const Cells& cells, const std::vector<Cell>& cell) {
    for (size_t i = 0; i < 3; ++i) {
        const uint32_t u = t[i], w = t[(i + 1) % 3], x = t[(i + 2) % 3];
        if (u >= n || w >= n) continue;
        const uint32_t f = cells.face_of(u, w);
        if (x < n) return f != kNo && cells.has(f, x) ? f : kNo;
        return f;
    }
    const Cell c = cells.meet(cells.meet(cell[t[0]], cell[t[1]]), cell[t[2]]);
    return c.dim == 2 ? c.a : kNo;
}

}  // namespace

std::vector<uint32_t> parents_from_splits(const VerifyInput& in) {
    const size_t n = in.in_points.size(), N = in.out_points.size();
    std::vector<uint32_t> parent(in.out_faces.size(), kNo);
    if (N < n) return parent;
    const Cells cells(in.in_faces);
    const Neighbours nb(N, in.out_faces);
    std::vector<Cell> cell(N);
    std::vector<Point3> exact(in.in_points);  // positions as the engine computed them
    exact.resize(N);
    for (uint32_t v = 0; v < n; ++v) cell[v] = {0, v, 0};
    std::vector<uint32_t> seen(N, kNo), stack, ends;
    for (uint32_t s = static_cast<uint32_t>(n); s < N; ++s) {
        earlier_ends(s, nb, seen, stack, ends);
        // Nearest ends first (pairs by their farther member); where float32 rounding makes
        // several pairs meet at s, a carrier every face around s fits in.
        for (size_t j = 1; j < ends.size() && cell[s].dim == 3; ++j)
            for (size_t i = 0; i < j; ++i) {
                const Point3 &x = exact[ends[i]], &y = exact[ends[j]];
                const Point3 mid{half_sum(x[0], y[0]), half_sum(x[1], y[1]), half_sum(x[2], y[2])};
                if (!same_stored(mid, in.out_points[s], in.float32)) continue;
                const Cell c = cells.meet(cell[ends[i]], cell[ends[j]]);
                if (c.dim == 3 || !fits_around(s, c, nb, cells, cell)) continue;
                cell[s] = c;
                exact[s] = mid;
                break;
            }
    }
    for (size_t f = 0; f < in.out_faces.size(); ++f) {
        const Triangle& t = in.out_faces[f];
        if (t[0] >= N || t[1] >= N || t[2] >= N) continue;
        parent[f] = parent_of(t, n, cells, cell);
    }
    return parent;
}

}  // namespace singlestrip::verify_detail
