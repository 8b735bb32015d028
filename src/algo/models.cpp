// The library's procedural models (models.hpp): `builtin:genus2` and what it is built from.
#include "singlestrip/models.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/soup_edges.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"

namespace singlestrip {
namespace {

void require(bool ok, const char* what) {
    if (!ok) throw RequestError(std::string("generator: ") + what);
}

}  // namespace

TriangleSoup make_grid_cells(uint32_t nx, uint32_t ny, double cell, const std::function<bool(uint32_t, uint32_t)>& keep) {
    require(nx >= 1 && ny >= 1, "grid needs nx, ny >= 1");
    const uint32_t w = nx + 1;
    std::vector<uint32_t> id(static_cast<size_t>(w) * (ny + 1), kNone);
    std::vector<Triangle> raw;
    for (uint32_t j = 0; j < ny; ++j) {
        for (uint32_t i = 0; i < nx; ++i) {
            if (!keep(i, j)) continue;
            const uint32_t a = j * w + i, b = a + 1, c = a + w + 1, d = a + w;  // CCW corners
            // Alternating diagonals keep the mesh symmetric (no preferred direction).
            if ((i + j) % 2 == 0) {
                raw.push_back({a, b, c});
                raw.push_back({a, c, d});
            } else {
                raw.push_back({a, b, d});
                raw.push_back({b, c, d});
            }
        }
    }
    for (const Triangle& t : raw)
        for (uint32_t v : t) id[v] = 0;
    TriangleSoup soup;
    for (uint32_t v = 0; v < id.size(); ++v) {
        if (id[v] == kNone) continue;
        id[v] = static_cast<uint32_t>(soup.points.size());
        soup.points.push_back({(v % w) * cell, (v / w) * cell, 0.0});
    }
    soup.triangles.reserve(raw.size());
    for (const Triangle& t : raw) soup.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});
    return soup;
}

TriangleSoup make_disk_with_holes(uint32_t k, uint32_t resolution) {
    require(resolution >= 1, "disk with holes needs resolution >= 1");
    const uint32_t r = resolution;
    return make_grid_cells((2 * k + 1) * r, 3 * r, 1.0 / r, [r](uint32_t i, uint32_t j) {
        const bool hole_row = j >= r && j < 2 * r;
        const bool hole_col = (i / r) % 2 == 1;  // columns of blocks 1, 3, 5, ... are holes
        return !(hole_row && hole_col);
    });
}

TriangleSoup make_genus_surface(uint32_t g, uint32_t resolution) {
    const TriangleSoup top = make_disk_with_holes(g, resolution);
    const uint32_t nv = static_cast<uint32_t>(top.points.size());
    const double half = 0.3;
    TriangleSoup s;
    s.points.reserve(2 * nv);
    for (const Point3& p : top.points) s.points.push_back({p[0], p[1], half});
    for (const Point3& p : top.points) s.points.push_back({p[0], p[1], -half});
    for (const Triangle& t : top.triangles) s.triangles.push_back(t);
    for (const Triangle& t : top.triangles) s.triangles.push_back({t[0] + nv, t[2] + nv, t[1] + nv});
    // Walls: top boundary half-edge a->b (no b->a) pairs with the bottom's b'->a'; the quad
    // (b, a, a', b') uses b->a and a'->b', so orientation stays consistent.
    std::vector<char> boundary(3 * top.triangles.size(), 0);  // per half-edge of the top grid
    SoupEdges(top.triangles, nv).for_each_edge([&](const SoupEdges::Edge& e) {
        if (e.kind == EdgeKind::boundary) boundary[*e.first] = 1;
    });
    for (uint32_t h = 0; h < boundary.size(); ++h) {
        if (!boundary[h]) continue;
        const uint32_t a = top.triangles[h / 3][h % 3], b = top.triangles[h / 3][(h % 3 + 1) % 3];
        s.triangles.push_back({b, a, a + nv});
        s.triangles.push_back({b, a + nv, b + nv});
    }
    return s;
}

TriangleSoup make_builtin_model() {
    TriangleSoup s = make_genus_surface(2, 8);
    // The same smooth displacement for both layers keeps the plate free of self-intersections.
    for (Point3& p : s.points) p[2] += 0.35 * std::sin(1.3 * p[0]) * std::cos(1.7 * p[1]);
    return s;
}

}  // namespace singlestrip
