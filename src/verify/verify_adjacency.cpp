// singlestrip — the verifier's own half-edge adjacency of a triangle list (verify_checks.hpp):
// faces, twins, manifold fans, Euler characteristic and boundary loops. Garbage is recorded as
// problems, never thrown.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "verify_checks.hpp"

namespace singlestrip::verify_detail {

namespace {

struct UnionFind {
    std::vector<uint32_t> p;
    explicit UnionFind(size_t n) : p(n) { std::iota(p.begin(), p.end(), 0u); }
    uint32_t find(uint32_t x) {
        while (p[x] != x) x = p[x] = p[p[x]];
        return x;
    }
    void unite(uint32_t a, uint32_t b) { p[find(a)] = find(b); }
};
bool same_vertex_set(const Triangle& a, const Triangle& b) {
    Triangle x = a, y = b;
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    return x == y;
}

// Faces with an index out of range or a repeated vertex are not ok.
void check_faces(Adjacency& a, const std::string& what) {
    const size_t F = a.faces.size();
    const size_t num_points = a.num_points;
    const std::vector<Triangle>& faces = a.faces;
    a.face_ok.assign(F, true);
    for (size_t f = 0; f < F; ++f) {
        const Triangle& t = faces[f];
        bool ok = t[0] < num_points && t[1] < num_points && t[2] < num_points;
        if (!ok) {
            a.problem(what + " face " + std::to_string(f) + " " + tri_str(t) + ": vertex index out of range (" +
                      std::to_string(num_points) + " vertices)");
        } else if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            a.problem(what + " face " + std::to_string(f) + " " + tri_str(t) + ": repeated vertex");
            ok = false;
        }
        a.face_ok[f] = ok;
    }
}

// Outgoing half-edges per vertex, each bucket ordered by (target, id): a stable counting sort
// by target, then one by source (linear; a comparison sort per bucket was verify's largest cost).
void bucket_outgoing(Adjacency& a) {
    const size_t F = a.faces.size();
    const size_t num_points = a.num_points;
    const std::vector<Triangle>& faces = a.faces;
    std::vector<uint32_t> by_to;
    {
        std::vector<uint32_t> count(num_points + 1, 0);
        for (uint32_t f = 0; f < F; ++f)
            if (a.face_ok[f])
                for (uint32_t v : faces[f]) ++count[v + 1];
        for (size_t v = 0; v < num_points; ++v) count[v + 1] += count[v];
        by_to.resize(count[num_points]);
        for (uint32_t f = 0; f < F; ++f)
            if (a.face_ok[f])
                for (uint32_t i = 0; i < 3; ++i) by_to[count[faces[f][(i + 1) % 3]]++] = 3 * f + i;
    }
    a.out_offset.assign(num_points + 1, 0);
    for (uint32_t h : by_to) ++a.out_offset[a.from(h) + 1];
    for (size_t v = 0; v < num_points; ++v) a.out_offset[v + 1] += a.out_offset[v];
    a.out_he.resize(a.out_offset[num_points]);
    {
        std::vector<uint32_t> fill(a.out_offset.begin(), a.out_offset.end() - 1);
        for (uint32_t h : by_to) a.out_he[fill[a.from(h)]++] = h;
    }
}

// Twins between the first half-edges of each (from, to) group; repeated directed half-edges and
// duplicate faces are problems.
void pair_twins(Adjacency& a, const std::string& what) {
    const size_t F = a.faces.size();
    const size_t num_points = a.num_points;
    const std::vector<Triangle>& faces = a.faces;
    a.twin.assign(3 * F, kNo);
    std::vector<bool> canonical(3 * F, false);  // first half-edge of its (from,to) group
    for (size_t v = 0; v < num_points; ++v) {
        auto first = a.out_he.begin() + a.out_offset[v], last = a.out_he.begin() + a.out_offset[v + 1];
        for (auto it = first; it != last; ++it) {
            if (it != first && a.to(*it) == a.to(*(it - 1))) {
                const uint32_t h = *it, g = *(it - 1);
                if (same_vertex_set(faces[h / 3], faces[g / 3]))
                    a.problem(what + " faces " + std::to_string(g / 3) + " and " + std::to_string(h / 3) + " are the same triangle " +
                              tri_str(faces[h / 3]) + " (duplicate face)");
                else
                    a.problem(what + " edge (" + std::to_string(a.from(h)) + "," + std::to_string(a.to(h)) +
                              ") is traversed in the same direction by faces " + std::to_string(g / 3) + " and " + std::to_string(h / 3) +
                              " (flipped face, or more than two faces on an edge)");
            } else {
                canonical[*it] = true;
            }
        }
    }
    // Twins between canonical half-edges (find() returns the canonical one: symmetric).
    for (uint32_t h = 0; h < 3 * F; ++h) {
        if (!canonical[h]) continue;
        const uint32_t t = a.find(a.to(h), a.from(h));
        if (t != kNo) a.twin[h] = t;
    }
    // A duplicate with the opposite orientation: all three edges glued to one face.
    for (uint32_t f = 0; f < F; ++f) {
        const uint32_t t0 = a.twin[3 * f], t1 = a.twin[3 * f + 1], t2 = a.twin[3 * f + 2];
        if (t0 != kNo && t1 != kNo && t2 != kNo && t0 / 3 == t1 / 3 && t1 / 3 == t2 / 3 && f < t0 / 3)
            a.problem(what + " faces " + std::to_string(f) + " and " + std::to_string(t0 / 3) + " are the same triangle " +
                      tri_str(faces[f]) + " with opposite orientations (duplicate face)");
    }
}

// Referenced vertices, edges, boundary vertices and the Euler characteristic. Returns the first
// corner seen at each vertex (kNo for an unreferenced one).
std::vector<uint32_t> count_elements(Adjacency& a) {
    const size_t F = a.faces.size();
    const size_t num_points = a.num_points;
    std::vector<uint32_t> first_corner(num_points, kNo);
    a.on_boundary.assign(num_points, false);
    for (uint32_t f = 0; f < F; ++f) {
        if (!a.face_ok[f]) continue;
        for (uint32_t i = 0; i < 3; ++i) {
            const uint32_t h = 3 * f + i;
            if (first_corner[a.from(h)] == kNo) {
                first_corner[a.from(h)] = h;
                ++a.referenced_vertices;
            }
            if (a.twin[h] == kNo) {
                ++a.edges;
                a.on_boundary[a.from(h)] = true;
                a.on_boundary[a.to(h)] = true;
            } else if (h < a.twin[h]) {
                ++a.edges;
            }
        }
    }
    long long valid_faces = 0;
    for (bool ok : a.face_ok) valid_faces += ok ? 1 : 0;
    a.euler = a.referenced_vertices - a.edges + valid_faces;
    return first_corner;
}

// Vertex manifoldness: corners around a vertex joined across shared edges must form one fan.
void check_fans(Adjacency& a, const std::vector<uint32_t>& first_corner, const std::string& what) {
    const size_t F = a.faces.size();
    UnionFind uf(3 * F);
    for (uint32_t f = 0; f < F; ++f) {
        if (!a.face_ok[f]) continue;
        for (uint32_t i = 0; i < 3; ++i) {
            const uint32_t h = 3 * f + i;  // corner at from(h), outgoing half-edge h
            const uint32_t t = a.twin[h];
            if (t != kNo) {
                // twin runs to(h)->from(h); its face's corner at from(h) is corner of next(t).
                const uint32_t tn = 3 * (t / 3) + (t % 3 + 1) % 3;
                uf.unite(h, tn);
            }
        }
    }
    for (uint32_t f = 0; f < F; ++f) {
        if (!a.face_ok[f]) continue;
        for (uint32_t i = 0; i < 3; ++i) {
            const uint32_t h = 3 * f + i;
            const uint32_t v = a.from(h);
            if (uf.find(h) != uf.find(first_corner[v])) {
                a.problem(what + " vertex " + std::to_string(v) + " is non-manifold (its faces form more than one fan; seen at face " +
                          std::to_string(f) + ")");
                // Merge so that each extra fan is reported once.
                uf.unite(h, first_corner[v]);
            }
        }
    }
}

// Boundary loops: components of the boundary-edge graph.
void count_boundary_loops(Adjacency& a) {
    const size_t F = a.faces.size();
    const size_t num_points = a.num_points;
    UnionFind uf(num_points);
    for (uint32_t h = 0; h < 3 * F; ++h)
        if (a.face_ok[h / 3] && a.twin[h] == kNo) uf.unite(a.from(h), a.to(h));
    for (uint32_t v = 0; v < num_points; ++v)
        if (a.on_boundary[v] && uf.find(v) == v) ++a.boundary_loops;
}

}  // namespace

Adjacency build_adjacency(size_t num_points, const std::vector<Triangle>& faces, const std::string& what) {
    Adjacency a;
    a.num_points = num_points;
    a.faces = faces;
    check_faces(a, what);
    bucket_outgoing(a);
    pair_twins(a, what);
    const std::vector<uint32_t> first_corner = count_elements(a);
    check_fans(a, first_corner, what);
    count_boundary_loops(a);
    return a;
}

}  // namespace singlestrip::verify_detail
