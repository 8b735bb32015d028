// Test fixtures: procedural test meshes; see fixtures.hpp for the counts of each.
#include "fixtures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "singlestrip/errors.hpp"

namespace singlestrip {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr uint32_t kUnused = 0xffffffffu;

void require(bool ok, const char* what) {
    if (!ok) throw RequestError(std::string("generator: ") + what);
}

uint64_t edge_key(uint32_t a, uint32_t b) {
    return (uint64_t{a} << 32) | b;
}

/// Directed edges a->b of the soup mapped to their face.
std::unordered_map<uint64_t, uint32_t> directed_edges(const TriangleSoup& soup) {
    std::unordered_map<uint64_t, uint32_t> map;
    map.reserve(soup.triangles.size() * 3);
    for (uint32_t f = 0; f < soup.triangles.size(); ++f) {
        const Triangle& t = soup.triangles[f];
        for (int k = 0; k < 3; ++k) map[edge_key(t[k], t[(k + 1) % 3])] = f;
    }
    return map;
}

/// Removes the faces marked in `removed` and the vertices no remaining face uses (indices
/// compacted, order kept).
TriangleSoup drop_faces(const TriangleSoup& in, const std::vector<char>& removed) {
    std::vector<uint32_t> id(in.points.size(), kUnused);
    for (size_t f = 0; f < in.triangles.size(); ++f)
        if (!removed[f])
            for (uint32_t v : in.triangles[f]) id[v] = 0;
    TriangleSoup out;
    for (uint32_t v = 0; v < id.size(); ++v) {
        if (id[v] == kUnused) continue;
        id[v] = static_cast<uint32_t>(out.points.size());
        out.points.push_back(in.points[v]);
    }
    for (size_t f = 0; f < in.triangles.size(); ++f) {
        if (removed[f]) continue;
        const Triangle& t = in.triangles[f];
        out.triangles.push_back({id[t[0]], id[t[1]], id[t[2]]});
    }
    return out;
}

/// Adds `m` points on a circle of radius r in the plane z=0, the first at angle 0; returns the
/// index of the first.
uint32_t add_circle(TriangleSoup& s, uint32_t m, double r) {
    const uint32_t first = static_cast<uint32_t>(s.points.size());
    for (uint32_t j = 0; j < m; ++j) {
        const double a = 2 * kPi * j / m;
        s.points.push_back({r * std::cos(a), r * std::sin(a), 0});
    }
    return first;
}

/// Closes the circle of n points starting at `first` (radius 1, z=0, CCW from +z) with a disk
/// facing -z: rings of halving size (each max(3, ceil(n/2))) zipped to the previous one by angle,
/// then one triangle. Radial gaps follow the ring spacing, so every triangle is well shaped and
/// every cap vertex has a small valence (a polygon triangulated from its own corners alone would
/// have slivers of width ~1/n^2, which no double-precision midpoint check can place).
void add_ring_cap(TriangleSoup& s, uint32_t first, uint32_t n) {
    double r = 1.0;
    // Reversed corners: the cap is CW seen from +z, i.e. outward (down).
    auto add = [&](uint32_t a, uint32_t b, uint32_t c) { s.triangles.push_back({a, c, b}); };
    while (n > 3) {
        const uint32_t m = std::max(3u, (n + 1) / 2);
        r *= 1.0 - 0.3 * 2 * kPi / n;
        const uint32_t inner = add_circle(s, m, r);
        // Zip the rings from the aligned pair (outer 0, inner 0): advance the ring whose next point
        // comes first by angle; n + m triangles close the band.
        uint32_t i = 0, j = 0;
        while (i < n || j < m) {
            const bool outer_next = j == m || (i < n && uint64_t{i + 1} * m <= uint64_t{j + 1} * n);
            if (outer_next) {
                add(inner + j % m, first + i, first + (i + 1) % n);
                ++i;
            } else {
                add(inner + j, first + i % n, inner + (j + 1) % m);
                ++j;
            }
        }
        first = inner;
        n = m;
    }
    add(first, first + 1, first + 2);
}

/// Two triangles (a, b, c), (a, c, d) per cell of a rows x cols parameter grid, where
/// a = id(i, j), b = id(i+1, j), c = id(i+1, j+1), d = id(i, j+1); `id` wraps as the surface does.
template <class Id>
void add_quads(TriangleSoup& s, uint32_t rows, uint32_t cols, Id id) {
    for (uint32_t i = 0; i < rows; ++i) {
        for (uint32_t j = 0; j < cols; ++j) {
            const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            s.triangles.push_back({a, b, c});
            s.triangles.push_back({a, c, d});
        }
    }
}

}  // namespace

TriangleSoup make_single_triangle() {
    TriangleSoup s;
    s.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.8660254037844386, 0}};
    s.triangles = {{0, 1, 2}};
    return s;
}

TriangleSoup make_two_triangles() {
    return make_grid_cells(1, 1, 1.0, [](uint32_t, uint32_t) { return true; });
}

TriangleSoup make_fan(uint32_t k) {
    require(k >= 1, "fan needs k >= 1");
    // Each wedge stays below pi (CCW) and the whole fan below 2 pi (open).
    const double step = std::min(kPi / 3, 1.5 * kPi / k);
    TriangleSoup s;
    s.points.push_back({0, 0, 0});
    for (uint32_t i = 0; i <= k; ++i) s.points.push_back({std::cos(i * step), std::sin(i * step), 0});
    for (uint32_t i = 0; i < k; ++i) s.triangles.push_back({0, i + 1, i + 2});
    return s;
}

TriangleSoup make_corridor(uint32_t k) {
    require(k >= 1, "corridor needs k >= 1");
    TriangleSoup s;
    // Even vertices on the top row, odd ones on the bottom row: the GL strip 0,1,2,... is CCW.
    for (uint32_t i = 0; i < k + 2; ++i) s.points.push_back({0.5 * i, i % 2 == 0 ? 1.0 : 0.0, 0});
    for (uint32_t i = 0; i < k; ++i) {
        if (i % 2 == 0)
            s.triangles.push_back({i, i + 1, i + 2});
        else
            s.triangles.push_back({i + 1, i, i + 2});
    }
    return s;
}

TriangleSoup make_circle_polygon(uint32_t n, double radius, Point3 centre, uint32_t seed) {
    TriangleSoup soup;
    for (uint32_t i = 0; i < n; ++i) {
        const double t = 2 * std::numbers::pi * i / n;
        soup.points.push_back({centre[0] + radius * std::cos(t), centre[1] + radius * std::sin(t), centre[2]});
    }
    std::mt19937 rng(seed);
    std::vector<std::pair<uint32_t, uint32_t>> todo{{0, n - 1}};
    while (!todo.empty()) {
        const auto [i, j] = todo.back();
        todo.pop_back();
        if (j - i < 2) continue;
        const uint32_t k = i + 1 + static_cast<uint32_t>(rng() % (j - i - 1));
        soup.triangles.push_back({i, k, j});
        todo.push_back({i, k});
        todo.push_back({k, j});
    }
    return soup;
}

TriangleSoup make_grid_disk(uint32_t nx, uint32_t ny) {
    require(nx >= 1 && ny >= 1, "grid needs nx, ny >= 1");
    return make_grid_cells(nx, ny, 1.0, [](uint32_t, uint32_t) { return true; });
}

TriangleSoup make_annulus(uint32_t n_around, uint32_t n_radial) {
    require(n_around >= 3 && n_radial >= 1, "annulus needs n_around >= 3, n_radial >= 1");
    TriangleSoup s;
    auto id = [&](uint32_t ring, uint32_t i) { return ring * n_around + i % n_around; };
    for (uint32_t ring = 0; ring <= n_radial; ++ring) {
        const double r = 1.0 + static_cast<double>(ring) / n_radial;
        for (uint32_t i = 0; i < n_around; ++i) {
            const double a = 2 * kPi * i / n_around;
            s.points.push_back({r * std::cos(a), r * std::sin(a), 0});
        }
    }
    // radial x angular = +z, so (inner, outer, outer next) is CCW.
    add_quads(s, n_radial, n_around, id);
    return s;
}

TriangleSoup make_icosphere(uint32_t subdivisions) {
    require(subdivisions <= 10, "icosphere needs subdivisions <= 10");
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    TriangleSoup s;
    s.points = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    s.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2}, {3, 2, 6}, {3, 6, 8},  {3, 8, 9},   {4, 9, 5}, {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (uint32_t level = 0; level < subdivisions; ++level) {
        std::unordered_map<uint64_t, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const uint64_t key = a < b ? edge_key(a, b) : edge_key(b, a);
            auto [it, fresh] = mid.try_emplace(key, static_cast<uint32_t>(s.points.size()));
            if (fresh) {
                const Point3 p = s.points[a], q = s.points[b];
                s.points.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
            }
            return it->second;
        };
        std::vector<Triangle> next;
        next.reserve(s.triangles.size() * 4);
        for (const Triangle& f : s.triangles) {
            const uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            next.push_back({f[0], ab, ca});
            next.push_back({f[1], bc, ab});
            next.push_back({f[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        s.triangles = std::move(next);
    }
    for (Point3& p : s.points) {
        const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (double& c : p) c /= n;
    }
    return s;
}

TriangleSoup make_uv_sphere(uint32_t n_lon, uint32_t n_lat) {
    require(n_lon >= 3 && n_lat >= 2, "uv sphere needs n_lon >= 3, n_lat >= 2");
    TriangleSoup s;
    s.points.push_back({0, 0, 1});  // north pole
    for (uint32_t k = 1; k < n_lat; ++k) {
        const double th = kPi * k / n_lat;
        for (uint32_t j = 0; j < n_lon; ++j) {
            const double ph = 2 * kPi * j / n_lon;
            s.points.push_back({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
        }
    }
    const uint32_t south = static_cast<uint32_t>(s.points.size());
    s.points.push_back({0, 0, -1});
    auto id = [&](uint32_t ring, uint32_t j) { return 1 + (ring - 1) * n_lon + j % n_lon; };
    // south x east is outward: (v, its south neighbour, that one's east neighbour).
    for (uint32_t j = 0; j < n_lon; ++j) s.triangles.push_back({0, id(1, j), id(1, j + 1)});
    for (uint32_t k = 1; k + 1 < n_lat; ++k) {
        for (uint32_t j = 0; j < n_lon; ++j) {
            const uint32_t a = id(k, j), b = id(k + 1, j), c = id(k + 1, j + 1), d = id(k, j + 1);
            s.triangles.push_back({a, b, c});
            s.triangles.push_back({a, c, d});
        }
    }
    for (uint32_t j = 0; j < n_lon; ++j) s.triangles.push_back({id(n_lat - 1, j), south, id(n_lat - 1, j + 1)});
    return s;
}

TriangleSoup make_torus(uint32_t n_major, uint32_t n_minor) {
    require(n_major >= 3 && n_minor >= 3, "torus needs n_major, n_minor >= 3");
    const double big = 1.0, small = 0.35;
    TriangleSoup s;
    auto id = [&](uint32_t i, uint32_t j) { return (i % n_major) * n_minor + j % n_minor; };
    for (uint32_t i = 0; i < n_major; ++i) {
        const double u = 2 * kPi * i / n_major;
        for (uint32_t j = 0; j < n_minor; ++j) {
            const double v = 2 * kPi * j / n_minor;
            const double rr = big + small * std::cos(v);
            s.points.push_back({rr * std::cos(u), rr * std::sin(u), small * std::sin(v)});
        }
    }
    // d/du x d/dv points outward, so (i,j), (i+1,j), (i+1,j+1) is outward.
    add_quads(s, n_major, n_minor, id);
    return s;
}

TriangleSoup make_genus_with_holes(uint32_t g, uint32_t h, uint32_t resolution) {
    TriangleSoup s = make_genus_surface(g, resolution);
    remove_random_faces_as_holes(s, h, 0x5eedULL + 131ULL * g + h);
    return s;
}

TriangleSoup make_moebius_soup(uint32_t n) {
    require(n >= 3, "moebius band needs n >= 3");
    TriangleSoup s;
    // Column i: vertices 2i (one side) and 2i+1 (other side) at half-twist angle i*pi/n.
    for (uint32_t i = 0; i < n; ++i) {
        const double u = 2 * kPi * i / n, tw = kPi * i / n;
        for (int side = -1; side <= 1; side += 2) {
            const double w = 0.3 * side;
            const double rr = 1.0 + w * std::cos(tw);
            s.points.push_back({rr * std::cos(u), rr * std::sin(u), w * std::sin(tw)});
        }
    }
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t a = 2 * i, d = 2 * i + 1;
        uint32_t b = 2 * ((i + 1) % n), c = b + 1;
        if (i + 1 == n) std::swap(b, c);  // the half twist glues the sides crosswise
        s.triangles.push_back({a, b, c});
        s.triangles.push_back({a, c, d});
    }
    return s;
}

size_t random_edge_flips(TriangleSoup& soup, size_t count, uint64_t seed) {
    if (soup.triangles.empty() || count == 0) return 0;
    auto edges = directed_edges(soup);
    std::vector<uint32_t> degree(soup.points.size(), 0);
    for (const auto& [key, f] : edges) {
        const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
        if (a < b || edges.count(edge_key(b, a)) == 0) {  // count each undirected edge once
            ++degree[a];
            ++degree[b];
        }
    }
    Rng rng{seed};
    size_t done = 0;
    const size_t max_attempts = 10 * count + 100;
    const size_t nf = soup.triangles.size();
    for (size_t attempt = 0; attempt < max_attempts && done < count; ++attempt) {
        const uint32_t f = static_cast<uint32_t>(rng.below(nf));
        const int k = static_cast<int>(rng.below(3));
        const Triangle tf = soup.triangles[f];
        const uint32_t a = tf[k], b = tf[(k + 1) % 3], c = tf[(k + 2) % 3];
        const auto it = edges.find(edge_key(b, a));
        if (it == edges.end()) continue;  // boundary edge
        const uint32_t g = it->second;
        const Triangle tg = soup.triangles[g];
        uint32_t d = kUnused;
        for (int m = 0; m < 3; ++m)
            if (tg[m] == b && tg[(m + 1) % 3] == a) d = tg[(m + 2) % 3];
        if (d == kUnused) continue;  // cannot happen on an oriented manifold; stay safe
        if (c == d || degree[a] <= 3 || degree[b] <= 3) continue;
        if (edges.count(edge_key(c, d)) != 0 || edges.count(edge_key(d, c)) != 0) continue;
        // Quad a, d, b, c is CCW; the new diagonal c-d splits it into (a,d,c) and (d,b,c).
        soup.triangles[f] = {a, d, c};
        soup.triangles[g] = {d, b, c};
        edges.erase(edge_key(a, b));
        edges.erase(edge_key(b, a));
        edges[edge_key(a, d)] = f;
        edges[edge_key(d, c)] = f;
        edges[edge_key(c, a)] = f;
        edges[edge_key(d, b)] = g;
        edges[edge_key(b, c)] = g;
        edges[edge_key(c, d)] = g;
        --degree[a];
        --degree[b];
        ++degree[c];
        ++degree[d];
        ++done;
    }
    return done;
}

void remove_random_faces_as_holes(TriangleSoup& soup, size_t k, uint64_t seed) {
    if (k == 0) return;
    const auto edges = directed_edges(soup);
    // Vertices that must not be touched: on the boundary, or on an already removed face.
    std::vector<char> blocked(soup.points.size(), 0);
    for (const auto& [key, f] : edges) {
        const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
        if (edges.count(edge_key(b, a)) == 0) blocked[a] = blocked[b] = 1;
    }
    std::vector<uint32_t> order(soup.triangles.size());
    for (uint32_t f = 0; f < order.size(); ++f) order[f] = f;
    Rng rng{seed};
    for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
    std::vector<char> removed(soup.triangles.size(), 0);
    size_t taken = 0;
    for (uint32_t f : order) {
        if (taken == k) break;
        const Triangle& t = soup.triangles[f];
        if (blocked[t[0]] || blocked[t[1]] || blocked[t[2]]) continue;
        for (uint32_t v : t) blocked[v] = 1;
        removed[f] = 1;
        ++taken;
    }
    if (taken < k)
        throw RequestError("remove_random_faces_as_holes: only " + std::to_string(taken) + " isolated interior faces available, " +
                           std::to_string(k) + " requested");
    const bool has_sources = soup.source_polygon.size() == soup.triangles.size();
    size_t out = 0;
    for (size_t f = 0; f < soup.triangles.size(); ++f) {
        if (removed[f]) continue;
        soup.triangles[out] = soup.triangles[f];
        if (has_sources) soup.source_polygon[out] = soup.source_polygon[f];
        ++out;
    }
    soup.triangles.resize(out);
    if (has_sources) soup.source_polygon.resize(out);
}

std::vector<std::pair<uint32_t, uint32_t>> polyline_edges(const Polylines& lines) {
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    for (const auto& line : lines)
        for (size_t i = 0; i + 1 < line.size(); ++i) edges.push_back({line[i], line[i + 1]});
    return edges;
}

std::vector<ConstraintEdge> as_constraints(const std::vector<std::pair<uint32_t, uint32_t>>& pairs) {
    std::vector<ConstraintEdge> edges;
    edges.reserve(pairs.size());
    for (const auto& [a, b] : pairs) edges.push_back({a, b});
    return edges;
}

TriangleSoup make_hole_corridors(uint32_t holes, uint32_t length) {
    require(length >= 1, "hole corridors need length >= 1");
    return make_grid_cells(length + 2, 2 * holes + 1, 1.0,
                           [length](uint32_t i, uint32_t j) { return !(j % 2 == 1 && i >= 1 && i <= length); });
}

TriangleSoup make_slit_corridors(uint32_t slits, uint32_t length) {
    require(length >= 2, "slit corridors need length >= 2");
    const uint32_t nx = length + 2, ny = slits + 1, w = nx + 1;
    TriangleSoup s = make_grid_cells(nx, ny, 1.0, [](uint32_t, uint32_t) { return true; });
    // Grid vertex (x, y) is y*w + x (no cell dropped). Slit y = k has inner vertices x = 2..length.
    const uint32_t grid_vertices = static_cast<uint32_t>(s.points.size());
    auto copy_of = [&](uint32_t v) -> uint32_t {
        const uint32_t x = v % w, y = v / w;
        if (y < 1 || y > slits || x < 2 || x > length) return v;
        return grid_vertices + (y - 1) * (length - 1) + (x - 2);
    };
    for (uint32_t k = 1; k <= slits; ++k)
        for (uint32_t x = 2; x <= length; ++x) s.points.push_back(s.points[k * w + x]);
    // Cell row j's lower corners lie on line y = j: the cells above a slit take the copies.
    for (Triangle& t : s.triangles) {
        const uint32_t row = std::min({t[0], t[1], t[2]}) / w;
        for (uint32_t& v : t)
            if (v / w == row) v = copy_of(v);
    }
    return s;
}

WalledMesh make_slit_walls(uint32_t slits, uint32_t length) {
    require(length >= 1, "slit walls need length >= 1");
    WalledMesh m{make_grid_disk(length + 2, slits + 1), {}};
    const uint32_t w = length + 3;
    for (uint32_t k = 1; k <= slits; ++k) {
        std::vector<uint32_t> line;
        for (uint32_t x = 1; x <= length + 1; ++x) line.push_back(k * w + x);
        m.walls.push_back(std::move(line));
    }
    return m;
}

WalledMesh make_serpentine_walls(uint32_t walls, uint32_t length) {
    require(length >= 2, "serpentine walls need length >= 2");
    WalledMesh m{make_grid_disk(length, 2 * (walls + 1)), {}};
    const uint32_t w = length + 1;
    for (uint32_t k = 1; k <= walls; ++k) {
        const uint32_t first = k % 2 == 1 ? 0 : 1;  // alternate sides: the gaps zigzag
        std::vector<uint32_t> line;
        for (uint32_t x = first; x <= first + length - 1; ++x) line.push_back(2 * k * w + x);
        m.walls.push_back(std::move(line));
    }
    return m;
}

TriangleSoup make_disk_many_holes(uint32_t bx, uint32_t by) {
    require(bx >= 1 && by >= 1, "disk with many holes needs bx, by >= 1");
    const uint32_t n = 10 * bx;
    const TriangleSoup grid = make_grid_cells(n, 10 * by, 1.0, [](uint32_t, uint32_t) { return true; });
    // grid_cells emits cell (i, j)'s two faces at 2(j n + i) and 2(j n + i) + 1; for a cell with
    // i + j even the first is (a, b, c), a corner triangle.
    std::vector<char> removed(grid.triangles.size(), 0);
    auto remove_cell = [&](uint32_t i, uint32_t j, bool both) {
        const size_t f = 2 * (static_cast<size_t>(j) * n + i);
        removed[f] = 1;
        if (both) removed[f + 1] = 1;
    };
    for (uint32_t b = 0; b < by; ++b) {
        for (uint32_t a = 0; a < bx; ++a) {
            const uint32_t x = 10 * a + 5, y = 10 * b + 5;
            if (a % 3 == 0) remove_cell(x, y, false);
            if (a % 3 == 1) remove_cell(x, y, true);
            if (a % 3 == 2)
                for (uint32_t dy = 0; dy < 2; ++dy)
                    for (uint32_t dx = 0; dx < 2; ++dx) remove_cell(x - 1 + dx, y - 1 + dy, true);
        }
    }
    return drop_faces(grid, removed);
}

TriangleSoup make_sparse_holes(uint32_t n, uint32_t period) {
    require(n >= 1 && period >= 3, "sparse holes need n >= 1, period >= 3");
    TriangleSoup s;
    const uint32_t w = n + 1;
    for (uint32_t j = 0; j <= n; ++j)
        for (uint32_t i = 0; i <= n; ++i) s.points.push_back({static_cast<double>(i), static_cast<double>(j), 0.0});
    auto hole = [&](uint32_t i) { return i % period == period / 2 && i >= 1 && i + 1 < n; };
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            if (hole(i) && hole(j)) continue;
            const uint32_t a = j * w + i, b = a + 1, c = a + w + 1, d = a + w;  // CCW corners
            s.triangles.push_back({a, b, c});
            s.triangles.push_back({a, c, d});
        }
    return s;
}

TriangleSoup make_random_diagonal_holes(uint32_t n, uint32_t period, uint64_t seed) {
    require(n >= 1 && period >= 3, "random diagonal holes need n >= 1, period >= 3");
    TriangleSoup s;
    const uint32_t w = n + 1;
    for (uint32_t j = 0; j <= n; ++j)
        for (uint32_t i = 0; i <= n; ++i) s.points.push_back({static_cast<double>(i), static_cast<double>(j), 0.0});
    auto hole = [&](uint32_t i) { return i >= 1 && i + 1 < n && (n - 2 - i) % period == 0; };
    Rng rng{seed};
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            if (hole(i) && hole(j)) continue;
            const uint32_t a = j * w + i, b = a + 1, c = a + w + 1, d = a + w;  // CCW corners
            const bool ac = rng.next() & 1;
            s.triangles.push_back(ac ? Triangle{a, b, c} : Triangle{a, b, d});
            s.triangles.push_back(ac ? Triangle{a, c, d} : Triangle{b, c, d});
        }
    return s;
}

TriangleSoup make_eared_grid(uint32_t nx, uint32_t ny) {
    require(nx >= 1 && ny >= 1, "eared grid needs nx, ny >= 1");
    TriangleSoup s = make_grid_cells(nx, ny, 1.0, [](uint32_t, uint32_t) { return true; });
    const uint32_t w = nx + 1;
    auto add_point = [&](double x, double y) {
        s.points.push_back({x, y, 0.0});
        return static_cast<uint32_t>(s.points.size() - 1);
    };
    for (uint32_t x = 0; x < nx; ++x) {
        // Bottom edge a -> b belongs to the grid; T = (b, a, p) below it, ear (p, a, q) on a-p.
        const uint32_t a = x, b = x + 1;
        const uint32_t p = add_point(x + 0.5, -0.5), q = add_point(x - 0.3, -0.6);
        s.triangles.push_back({b, a, p});
        s.triangles.push_back({p, a, q});
    }
    for (uint32_t x = 0; x < nx; ++x) {
        // Top edge b -> a belongs to the grid; T = (a, b, p) above it, ear (a, p, q) on p-a.
        const uint32_t a = ny * w + x, b = a + 1;
        const uint32_t p = add_point(x + 0.5, ny + 0.5), q = add_point(x - 0.3, ny + 0.6);
        s.triangles.push_back({a, b, p});
        s.triangles.push_back({a, p, q});
    }
    return s;
}

TriangleSoup make_spiked_comb(uint32_t teeth, uint32_t height) {
    require(teeth >= 1 && height >= 1, "spiked comb needs teeth, height >= 1");
    TriangleSoup s;
    const uint32_t w = 2 * teeth + 1;  // base vertices per row
    for (uint32_t y = 0; y < 2; ++y)
        for (uint32_t x = 0; x < w; ++x) s.points.push_back({double(x), double(y), 0.0});
    auto cell = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t d) {  // a b c d counter-clockwise
        s.triangles.push_back({a, b, c});
        s.triangles.push_back({a, c, d});
    };
    for (uint32_t x = 0; x + 1 < w; ++x) cell(x, x + 1, w + x + 1, w + x);
    for (uint32_t t = 0; t < teeth; ++t) {
        const uint32_t x = 2 * t;
        uint32_t left = w + x, right = w + x + 1;  // the tooth's bottom edge, on the base's top
        for (uint32_t y = 2; y <= height + 1; ++y) {
            const auto l = static_cast<uint32_t>(s.points.size());
            s.points.push_back({double(x), double(y), 0.0});
            s.points.push_back({double(x + 1), double(y), 0.0});
            cell(left, right, l + 1, l);
            left = l, right = l + 1;
        }
        const auto tip = static_cast<uint32_t>(s.points.size());
        s.points.push_back({x + 0.5, height + 1.5, 0.0});
        s.triangles.push_back({left, right, tip});
    }
    return s;
}

TriangleSoup make_cone(uint32_t k, bool capped) {
    require(k >= 3, "cone needs k >= 3");
    TriangleSoup s;
    s.points.push_back({0, 0, 1});
    for (uint32_t i = 0; i < k; ++i) {
        const double a = 2 * kPi * i / k;
        s.points.push_back({std::cos(a), std::sin(a), 0});
    }
    for (uint32_t i = 0; i < k; ++i) s.triangles.push_back({0, 1 + i, 1 + (i + 1) % k});
    if (capped) add_ring_cap(s, 1, k);
    return s;
}

std::vector<uint32_t> shuffle_vertices(TriangleSoup& soup, uint64_t seed) {
    const size_t n = soup.points.size();
    std::vector<uint32_t> new_of_old(n);
    for (uint32_t v = 0; v < n; ++v) new_of_old[v] = v;
    Rng rng{seed};
    for (size_t i = n; i > 1; --i) std::swap(new_of_old[i - 1], new_of_old[rng.below(i)]);
    std::vector<Point3> points(n);
    for (size_t v = 0; v < n; ++v) points[new_of_old[v]] = soup.points[v];
    soup.points = std::move(points);
    for (Triangle& t : soup.triangles)
        for (uint32_t& v : t) v = new_of_old[v];
    return new_of_old;
}

void shuffle_faces(TriangleSoup& soup, uint64_t seed) {
    const size_t n = soup.triangles.size();
    const bool has_sources = soup.source_polygon.size() == n;
    Rng rng{seed};
    for (size_t i = n; i > 1; --i) {
        const size_t j = rng.below(i);
        std::swap(soup.triangles[i - 1], soup.triangles[j]);
        if (has_sources) std::swap(soup.source_polygon[i - 1], soup.source_polygon[j]);
    }
    for (Triangle& t : soup.triangles) std::rotate(t.begin(), t.begin() + static_cast<long>(rng.below(3)), t.end());
}

}  // namespace singlestrip
