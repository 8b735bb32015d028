// Generators: every mesh is checked by an independent edge-map topology checker (below) and by
// Mesh::from_soup + validate(); counts and topology must match fixtures.hpp and singlestrip/models.hpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "../src/algo/union_find.hpp"
#include "fixtures.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"

using namespace singlestrip;

namespace {

uint64_t key(uint32_t a, uint32_t b) {
    return (uint64_t{a} << 32) | b;
}

/// Independent topology of a soup (no use of Mesh).
struct Topology {
    std::string problem;  // empty when the soup is an edge-connected oriented manifold
    long long V = 0, E = 0, F = 0, chi = 0, loops = 0, genus = 0;
    size_t components = 0;
    bool unreferenced = false;
};

Topology analyze(const TriangleSoup& s) {
    Topology r;
    r.F = static_cast<long long>(s.triangles.size());
    std::unordered_map<uint64_t, int> directed;
    std::vector<char> used(s.points.size(), 0);
    for (const Triangle& t : s.triangles) {
        for (int k = 0; k < 3; ++k) {
            if (t[k] >= s.points.size()) return r.problem = "index out of range", r;
            used[t[k]] = 1;
        }
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return r.problem = "degenerate face", r;
        for (int k = 0; k < 3; ++k)
            if (++directed[key(t[k], t[(k + 1) % 3])] > 1) r.problem = "edge used twice in one direction";
    }
    if (!r.problem.empty()) return r;
    for (char u : used) r.V += u;
    r.unreferenced = r.V != static_cast<long long>(s.points.size());
    for (const auto& [k, c] : directed) {
        const uint32_t a = static_cast<uint32_t>(k >> 32), b = static_cast<uint32_t>(k);
        if (a < b || directed.count(key(b, a)) == 0) ++r.E;
    }
    // Vertex manifoldness: the link of every vertex (opposite edges) is one path or one cycle.
    std::vector<std::vector<std::pair<uint32_t, uint32_t>>> link(s.points.size());
    for (const Triangle& t : s.triangles)
        for (int k = 0; k < 3; ++k) link[t[k]].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
    for (uint32_t v = 0; v < link.size(); ++v) {
        if (link[v].empty()) continue;
        std::map<uint32_t, uint32_t> id;
        for (auto [a, b] : link[v]) {
            id.try_emplace(a, static_cast<uint32_t>(id.size()));
            id.try_emplace(b, static_cast<uint32_t>(id.size()));
        }
        UnionFind d(id.size());
        size_t comps = id.size();
        for (auto [a, b] : link[v]) comps -= d.unite(id[a], id[b]) ? 1 : 0;
        if (comps != 1) return r.problem = "non-manifold vertex " + std::to_string(v), r;
    }
    // Edge-connected components.
    UnionFind faces(s.triangles.size());
    std::unordered_map<uint64_t, uint32_t> face_of;
    for (uint32_t f = 0; f < s.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) face_of[key(s.triangles[f][k], s.triangles[f][(k + 1) % 3])] = f;
    r.components = s.triangles.size();
    for (const auto& [k, f] : face_of) {
        auto it = face_of.find(key(static_cast<uint32_t>(k), static_cast<uint32_t>(k >> 32)));
        if (it != face_of.end() && faces.unite(f, it->second)) --r.components;
    }
    // Boundary loops: follow boundary half-edges a->b (no b->a); one outgoing per boundary vertex.
    std::unordered_map<uint32_t, uint32_t> next;
    for (const auto& [k, c] : directed) {
        const uint32_t a = static_cast<uint32_t>(k >> 32), b = static_cast<uint32_t>(k);
        if (directed.count(key(b, a)) == 0) {
            if (!next.emplace(a, b).second) return r.problem = "two boundary edges leave a vertex", r;
        }
    }
    std::unordered_map<uint32_t, char> seen;
    for (const auto& [a, b] : next) {
        if (seen[a]) continue;
        ++r.loops;
        uint32_t v = a;
        while (!seen[v]) {
            seen[v] = 1;
            v = next.at(v);
        }
    }
    r.chi = r.V - r.E + r.F;
    r.genus = (2 - r.chi - r.loops) / 2;
    if ((2 - r.chi - r.loops) % 2 != 0) r.problem = "odd 2 - chi - b";
    if (r.components != 1) r.problem = "not edge-connected";
    return r;
}

/// 6 x signed volume (closed meshes: > 0 when outward).
double signed_volume6(const TriangleSoup& s) {
    double vol = 0;
    for (const Triangle& t : s.triangles) {
        const Point3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
        vol += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return vol;
}

/// Minimum of 2 x signed area in the xy plane over faces (planar meshes: > 0 when CCW up).
double min_signed_area2(const TriangleSoup& s) {
    double m = 1e300;
    for (const Triangle& t : s.triangles) {
        const Point3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
        m = std::min(m, (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    }
    return m;
}

struct Expect {
    long long V, F, chi, loops, genus;
};

void check_topology(const TriangleSoup& s, const Expect& e, const std::string& what) {
    SCOPED_TRACE(what);
    const Topology t = analyze(s);
    ASSERT_EQ(t.problem, "");
    EXPECT_FALSE(t.unreferenced);
    EXPECT_EQ(t.V, e.V);
    EXPECT_EQ(t.F, e.F);
    EXPECT_EQ(t.chi, e.chi);
    EXPECT_EQ(t.loops, e.loops);
    EXPECT_EQ(t.genus, e.genus);
    EXPECT_TRUE(s.source_polygon.empty() || s.source_polygon.size() == s.triangles.size());
    // The library's own mesh core must agree.
    const Mesh m = Mesh::from_soup(s);
    EXPECT_NO_THROW(m.validate());
    EXPECT_EQ(m.num_components(), 1u);
    EXPECT_EQ(m.euler_characteristic(), e.chi);
    EXPECT_EQ(m.num_boundary_loops(), static_cast<uint32_t>(e.loops));
    EXPECT_EQ(m.genus(), e.genus);
    EXPECT_EQ(m.num_faces(), static_cast<uint32_t>(e.F));
    EXPECT_EQ(m.num_referenced_vertices(), static_cast<uint32_t>(e.V));
}

long long pow4(uint32_t s) {
    return 1LL << (2 * s);
}

struct HolesCounts {
    long long V, F, boundary_edges;
};
HolesCounts disk_with_holes_counts(long long k, long long r) {
    const long long nx = (2 * k + 1) * r, ny = 3 * r;
    return {(nx + 1) * (ny + 1) - k * (r - 1) * (r - 1), 2 * (nx * ny - k * r * r), 2 * (nx + ny) + 4 * k * r};
}

}  // namespace

TEST(Generators, SmallPlanar) {
    check_topology(make_single_triangle(), {3, 1, 1, 1, 0}, "single");
    check_topology(make_two_triangles(), {4, 2, 1, 1, 0}, "two");
    for (uint32_t k : {1u, 2u, 3u, 5u, 12u, 40u}) {
        const TriangleSoup fan = make_fan(k);
        check_topology(fan, {k + 2, k, 1, 1, 0}, "fan " + std::to_string(k));
        EXPECT_GT(min_signed_area2(fan), 0);
        const TriangleSoup cor = make_corridor(k);
        check_topology(cor, {k + 2, k, 1, 1, 0}, "corridor " + std::to_string(k));
        EXPECT_GT(min_signed_area2(cor), 0);
    }
    EXPECT_GT(min_signed_area2(make_single_triangle()), 0);
    EXPECT_GT(min_signed_area2(make_two_triangles()), 0);
}

TEST(Generators, GridAnnulusHoles) {
    for (uint32_t nx : {1u, 2u, 5u})
        for (uint32_t ny : {1u, 3u, 4u}) {
            const TriangleSoup s = make_grid_disk(nx, ny);
            check_topology(s, {(nx + 1LL) * (ny + 1), 2LL * nx * ny, 1, 1, 0}, "grid");
            EXPECT_GT(min_signed_area2(s), 0);
        }
    for (uint32_t na : {3u, 4u, 9u})
        for (uint32_t nr : {1u, 2u, 5u}) {
            const TriangleSoup s = make_annulus(na, nr);
            check_topology(s, {na * (nr + 1LL), 2LL * na * nr, 0, 2, 0}, "annulus");
            EXPECT_GT(min_signed_area2(s), 0);
        }
    for (uint32_t k : {0u, 1u, 2u, 5u})
        for (uint32_t r : {1u, 2u, 3u}) {
            const TriangleSoup s = make_disk_with_holes(k, r);
            const HolesCounts c = disk_with_holes_counts(k, r);
            check_topology(s, {c.V, c.F, 1 - static_cast<long long>(k), k + 1LL, 0},
                           "holes " + std::to_string(k) + " r" + std::to_string(r));
            EXPECT_GT(min_signed_area2(s), 0);
        }
}

TEST(Generators, ClosedSurfaces) {
    for (uint32_t sub : {0u, 1u, 2u, 3u}) {
        const TriangleSoup s = make_icosphere(sub);
        check_topology(s, {10 * pow4(sub) + 2, 20 * pow4(sub), 2, 0, 0}, "icosphere");
        EXPECT_GT(signed_volume6(s), 0);
        for (const Point3& p : s.points) EXPECT_NEAR(std::hypot(p[0], p[1], p[2]), 1.0, 1e-12);
    }
    for (uint32_t lon : {3u, 8u})
        for (uint32_t lat : {2u, 3u, 7u}) {
            const TriangleSoup s = make_uv_sphere(lon, lat);
            check_topology(s, {lon * (lat - 1LL) + 2, 2LL * lon * (lat - 1), 2, 0, 0}, "uv sphere");
            EXPECT_GT(signed_volume6(s), 0);
        }
    for (uint32_t a : {3u, 4u, 16u})
        for (uint32_t b : {3u, 7u}) {
            const TriangleSoup s = make_torus(a, b);
            check_topology(s, {1LL * a * b, 2LL * a * b, 0, 0, 1}, "torus");
            EXPECT_GT(signed_volume6(s), 0);
        }
}

TEST(Generators, GenusSurfaces) {
    for (uint32_t g : {0u, 1u, 2u, 3u, 6u})
        for (uint32_t r : {1u, 2u, 4u}) {
            const TriangleSoup s = make_genus_surface(g, r);
            const HolesCounts c = disk_with_holes_counts(g, r);
            check_topology(s, {2 * c.V, 2 * c.F + 2 * c.boundary_edges, 2 - 2LL * g, 0, g},
                           "genus " + std::to_string(g) + " r" + std::to_string(r));
            EXPECT_GT(signed_volume6(s), 0);
        }
    for (uint32_t g : {0u, 1u, 2u, 4u})
        for (uint32_t h : {0u, 1u, 3u, 7u}) {
            const uint32_t r = 3;
            const TriangleSoup s = make_genus_with_holes(g, h, r);
            const HolesCounts c = disk_with_holes_counts(g, r);
            check_topology(s, {2 * c.V, 2 * c.F + 2 * c.boundary_edges - h, 2 - 2LL * g - h, h, g},
                           "genus " + std::to_string(g) + " holes " + std::to_string(h));
        }
    EXPECT_THROW(make_genus_with_holes(0, 1000, 1), RequestError);
}

TEST(Generators, BuiltinModel) {
    const TriangleSoup s = make_builtin_model();
    check_topology(s, {1854, 3712, -2, 0, 2}, "builtin");
    EXPECT_GT(signed_volume6(s), 0);
}

TEST(Generators, MoebiusIsRejected) {
    for (uint32_t n : {3u, 4u, 10u}) {
        const TriangleSoup s = make_moebius_soup(n);
        EXPECT_EQ(s.triangles.size(), 2u * n);
        EXPECT_EQ(s.points.size(), 2u * n);
        EXPECT_EQ(analyze(s).problem, "edge used twice in one direction");
        EXPECT_THROW(Mesh::from_soup(s), InputError);
    }
}

TEST(Generators, CheckerCatchesBrokenSoups) {
    // The checker itself must see the defects the generators are claimed not to have.
    TriangleSoup bowtie;
    bowtie.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    bowtie.triangles = {{0, 1, 2}, {0, 3, 4}};
    EXPECT_EQ(analyze(bowtie).problem, "non-manifold vertex 0");
    TriangleSoup flipped = make_grid_disk(2, 2);
    std::swap(flipped.triangles[3][0], flipped.triangles[3][1]);
    EXPECT_EQ(analyze(flipped).problem, "edge used twice in one direction");
    TriangleSoup two = make_grid_disk(1, 1);
    TriangleSoup apart = two;
    for (Triangle t : two.triangles) apart.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
    apart.points.insert(apart.points.end(), two.points.begin(), two.points.end());
    EXPECT_EQ(analyze(apart).problem, "not edge-connected");
}

TEST(Generators, BadParametersThrow) {
    EXPECT_THROW(make_fan(0), RequestError);
    EXPECT_THROW(make_corridor(0), RequestError);
    EXPECT_THROW(make_grid_disk(0, 3), RequestError);
    EXPECT_THROW(make_annulus(2, 1), RequestError);
    EXPECT_THROW(make_disk_with_holes(1, 0), RequestError);
    EXPECT_THROW(make_icosphere(11), RequestError);
    EXPECT_THROW(make_uv_sphere(2, 5), RequestError);
    EXPECT_THROW(make_torus(3, 2), RequestError);
    EXPECT_THROW(make_moebius_soup(2), RequestError);
}

TEST(Generators, RandomFlipsKeepTopology) {
    struct Base {
        std::string name;
        std::function<TriangleSoup()> make;
    };
    const std::vector<Base> bases = {
        {"grid", [] { return make_grid_disk(6, 5); }},
        {"annulus", [] { return make_annulus(9, 3); }},
        {"holes", [] { return make_disk_with_holes(2, 2); }},
        {"icosphere", [] { return make_icosphere(1); }},
        {"torus", [] { return make_torus(8, 5); }},
        {"genus3", [] { return make_genus_surface(3, 1); }},
        {"genus2holes", [] { return make_genus_with_holes(2, 3, 2); }},
    };
    size_t total_flips = 0;
    for (const Base& base : bases) {
        const TriangleSoup original = base.make();
        const Topology before = analyze(original);
        ASSERT_EQ(before.problem, "");
        for (uint64_t seed = 0; seed < 60; ++seed) {
            TriangleSoup s = original;
            const size_t count = 1 + seed * 3;
            const size_t done = random_edge_flips(s, count, seed);
            EXPECT_LE(done, count);
            total_flips += done;
            check_topology(s, {before.V, before.F, before.chi, before.loops, before.genus},
                           base.name + " flips seed " + std::to_string(seed));
            TriangleSoup again = original;
            random_edge_flips(again, count, seed);
            EXPECT_EQ(again.triangles, s.triangles) << "deterministic for a seed";
        }
    }
    EXPECT_GT(total_flips, 1000u);  // the flips actually happen
}

TEST(Generators, RandomHolesKeepTopology) {
    for (uint64_t seed = 0; seed < 200; ++seed) {
        const uint32_t g = static_cast<uint32_t>(seed % 4);
        TriangleSoup s = make_genus_surface(g, 2);
        random_edge_flips(s, 50, seed * 7 + 1);
        const Topology before = analyze(s);
        ASSERT_EQ(before.problem, "");
        const size_t k = 1 + seed % 6;
        remove_random_faces_as_holes(s, k, seed);
        const long long kk = static_cast<long long>(k);
        check_topology(s, {before.V, before.F - kk, before.chi - kk, before.loops + kk, before.genus},
                       "holes seed " + std::to_string(seed));
        // Holes in a mesh that already has boundaries.
        TriangleSoup d = make_disk_with_holes(1, 4);
        const Topology bd = analyze(d);
        remove_random_faces_as_holes(d, 2, seed);
        check_topology(d, {bd.V, bd.F - 2, bd.chi - 2, bd.loops + 2, 0}, "disk holes seed " + std::to_string(seed));
    }
    TriangleSoup tiny = make_two_triangles();
    EXPECT_THROW(remove_random_faces_as_holes(tiny, 1, 1), RequestError);
}

// ---- awkward families (issue 15) ----

namespace {

std::map<std::pair<uint32_t, uint32_t>, int> undirected_edge_faces(const TriangleSoup& s) {
    std::map<std::pair<uint32_t, uint32_t>, int> count;
    for (const Triangle& t : s.triangles)
        for (int k = 0; k < 3; ++k) ++count[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    return count;
}

long long boundary_edge_count(const TriangleSoup& s) {
    long long n = 0;
    for (const auto& [e, c] : undirected_edge_faces(s)) n += c == 1;
    return n;
}

/// Walls must run along interior edges and leave the faces edge-connected.
void check_walls(const TriangleSoup& s, const Polylines& walls, const std::string& what) {
    SCOPED_TRACE(what);
    const auto edges = undirected_edge_faces(s);
    std::set<std::pair<uint32_t, uint32_t>> cut;
    for (auto [a, b] : polyline_edges(walls)) {
        const auto e = std::make_pair(std::min(a, b), std::max(a, b));
        ASSERT_TRUE(edges.count(e)) << a << "-" << b << " is not an edge";
        cut.insert(e);
    }
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> first_face;
    UnionFind d(s.triangles.size());
    size_t pieces = s.triangles.size();
    for (uint32_t f = 0; f < s.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const Triangle& t = s.triangles[f];
            const auto e = std::make_pair(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
            if (cut.count(e)) continue;
            auto [it, fresh] = first_face.emplace(e, f);
            if (!fresh && d.unite(it->second, f)) --pieces;
        }
    EXPECT_EQ(pieces, 1u) << "walls cut the surface apart";
}

/// Faces with one passable (interior) edge whose neighbour across it has exactly two.
size_t ears_next_to_two_edge_faces(const TriangleSoup& s) {
    const auto edges = undirected_edge_faces(s);
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> faces_of;
    std::vector<int> passable(s.triangles.size(), 0);
    for (uint32_t f = 0; f < s.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const Triangle& t = s.triangles[f];
            const auto e = std::make_pair(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
            faces_of[e].push_back(f);
            passable[f] += edges.at(e) == 2;
        }
    size_t n = 0;
    for (const auto& [e, fs] : faces_of)
        if (fs.size() == 2)
            for (int i = 0; i < 2; ++i) n += passable[fs[i]] == 1 && passable[fs[1 - i]] == 2;
    return n;
}

std::vector<size_t> valences(const TriangleSoup& s) {
    std::vector<size_t> v(s.points.size(), 0);
    for (const auto& [e, c] : undirected_edge_faces(s)) ++v[e.first], ++v[e.second];
    return v;
}

}  // namespace

TEST(AwkwardGenerators, HoleCorridors) {
    for (uint32_t holes : {0u, 1u, 2u, 7u})
        for (uint32_t len : {1u, 2u, 9u}) {
            const TriangleSoup s = make_hole_corridors(holes, len);
            const long long h = holes, nx = len + 2, ny = 2 * h + 1;
            check_topology(s, {(nx + 1) * (ny + 1), 2 * (nx * ny - h * len), 1 - h, h + 1, 0},
                           "hole corridors " + std::to_string(holes) + " x " + std::to_string(len));
            EXPECT_GT(min_signed_area2(s), 0);
        }
}

TEST(AwkwardGenerators, SlitCorridorsAreCuts) {
    for (uint32_t slits : {0u, 1u, 2u, 6u})
        for (uint32_t len : {2u, 3u, 10u}) {
            const TriangleSoup s = make_slit_corridors(slits, len);
            const long long k = slits, nx = len + 2, ny = k + 1;
            const std::string what = "slit corridors " + std::to_string(slits) + " x " + std::to_string(len);
            check_topology(s, {(nx + 1) * (ny + 1) + k * (len - 1LL), 2 * nx * ny, 1 - k, k + 1, 0}, what);
            EXPECT_GT(min_signed_area2(s), 0);
            // Each cut edge is boundary on both sides: the border plus two copies per slit edge.
            EXPECT_EQ(boundary_edge_count(s), 2 * (nx + ny) + 2 * k * len) << what;
        }
}

TEST(AwkwardGenerators, SlitAndSerpentineWalls) {
    for (uint32_t n : {0u, 1u, 2u, 5u})
        for (uint32_t len : {2u, 3u, 8u}) {
            const std::string tag = std::to_string(n) + " x " + std::to_string(len);
            const WalledMesh slit = make_slit_walls(n, len);
            const long long nx = len + 2, ny = n + 1;
            check_topology(slit.soup, {(nx + 1) * (ny + 1), 2 * nx * ny, 1, 1, 0}, "slit walls " + tag);
            ASSERT_EQ(slit.walls.size(), n);
            for (const auto& w : slit.walls) EXPECT_EQ(w.size(), len + 1u);
            check_walls(slit.soup, slit.walls, "slit walls " + tag);
            const WalledMesh serp = make_serpentine_walls(n, len);
            check_topology(serp.soup, {(len + 1LL) * (2 * n + 3), 4LL * len * (n + 1), 1, 1, 0}, "serpentine " + tag);
            ASSERT_EQ(serp.walls.size(), n);
            for (const auto& w : serp.walls) EXPECT_EQ(w.size(), len);
            check_walls(serp.soup, serp.walls, "serpentine " + tag);
        }
    EXPECT_EQ(polyline_edges({{4, 5, 6}, {1}, {7, 8}}), (std::vector<std::pair<uint32_t, uint32_t>>{{4, 5}, {5, 6}, {7, 8}}));
}

TEST(AwkwardGenerators, SerpentineWallsLeaveOnePath) {
    // Walls attached to alternate borders: cutting the gap column too splits the surface, so the
    // corridors really are joined only through their one-cell gaps.
    const WalledMesh m = make_serpentine_walls(3, 6);
    const uint32_t w = 7;
    Polylines closed = m.walls;
    closed[0].push_back(2 * w + 6);  // close wall 1's gap at the right border
    const auto edges = polyline_edges(closed);
    std::set<std::pair<uint32_t, uint32_t>> cut;
    for (auto [a, b] : edges) cut.insert({std::min(a, b), std::max(a, b)});
    UnionFind d(m.soup.triangles.size());
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> first;
    size_t pieces = m.soup.triangles.size();
    for (uint32_t f = 0; f < m.soup.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const Triangle& t = m.soup.triangles[f];
            const auto e = std::make_pair(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
            if (cut.count(e)) continue;
            auto [it, fresh] = first.emplace(e, f);
            if (!fresh && d.unite(it->second, f)) --pieces;
        }
    EXPECT_EQ(pieces, 2u);
}

TEST(AwkwardGenerators, DiskWithManyHoles) {
    for (uint32_t bx : {1u, 2u, 3u, 7u})
        for (uint32_t by : {1u, 4u}) {
            const TriangleSoup s = make_disk_many_holes(bx, by);
            long long h[3] = {0, 0, 0};
            for (uint32_t a = 0; a < bx; ++a) h[a % 3] += by;
            const long long nx = 10LL * bx, ny = 10LL * by, holes = 1LL * bx * by;
            check_topology(s, {(nx + 1) * (ny + 1) - h[2], 2 * nx * ny - h[0] - 2 * h[1] - 8 * h[2], 1 - holes, 1 + holes, 0},
                           "many holes " + std::to_string(bx) + " x " + std::to_string(by));
            EXPECT_GT(min_signed_area2(s), 0);
            const double per_hole = static_cast<double>(s.triangles.size()) / static_cast<double>(holes);
            EXPECT_GT(per_hole, 190.0);
            EXPECT_LE(per_hole, 200.0);
        }
}

TEST(AwkwardGenerators, EaredGrid) {
    for (uint32_t nx : {1u, 2u, 5u, 30u})
        for (uint32_t ny : {1u, 4u}) {
            const TriangleSoup s = make_eared_grid(nx, ny);
            const std::string what = "eared grid " + std::to_string(nx) + " x " + std::to_string(ny);
            check_topology(s, {(nx + 1LL) * (ny + 1) + 4 * nx, 2LL * nx * ny + 4 * nx, 1, 1, 0}, what);
            EXPECT_GT(min_signed_area2(s), 0);
            EXPECT_EQ(ears_next_to_two_edge_faces(s), 2u * nx) << what;
        }
}

TEST(AwkwardGenerators, SpikedComb) {
    for (uint32_t teeth : {1u, 2u, 7u, 40u})
        for (uint32_t height : {1u, 5u}) {
            const TriangleSoup s = make_spiked_comb(teeth, height);
            const std::string what = "spiked comb " + std::to_string(teeth) + " x " + std::to_string(height);
            check_topology(s, {2 * (2LL * teeth + 1) + teeth * (2LL * height + 1), teeth * (2LL * height + 5), 1, 1, 0}, what);
            EXPECT_GT(min_signed_area2(s), 0) << what;
            EXPECT_EQ(ears_next_to_two_edge_faces(s), teeth + 1) << what;  // and the base's last cell
        }
}

TEST(AwkwardGenerators, Cones) {
    for (uint32_t k : {3u, 4u, 5u, 17u, 1000u, 10000u}) {
        const std::string what = "cone " + std::to_string(k);
        const TriangleSoup open = make_cone(k, false);
        check_topology(open, {k + 1LL, k, 1, 1, 0}, what + " open");
        EXPECT_EQ(valences(open)[0], k);
        long long c = 0;  // cap vertices: rings of halving size down to 3
        for (long long n = k; n > 3;) c += n = std::max(3LL, (n + 1) / 2);
        const TriangleSoup closed = make_cone(k, true);
        check_topology(closed, {k + 1 + c, 2 * (k + c) - 2, 2, 0, 0}, what + " capped");
        EXPECT_GT(signed_volume6(closed), 0);
        const auto val = valences(closed);
        EXPECT_EQ(val[0], k);
        // Only the apex has a high valence.
        const size_t others = *std::max_element(val.begin() + 1, val.end());
        EXPECT_LE(others, 9u) << what;
        // The cap is flat, faces down, and has no sliver: twice the area of each face is at
        // least a fixed fraction of its longest edge squared.
        for (size_t f = k; f < closed.triangles.size(); ++f) {
            const Triangle& t = closed.triangles[f];
            const Point3 &a = closed.points[t[0]], &b = closed.points[t[1]], &d = closed.points[t[2]];
            const double area2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
            const double e = std::max(
                {std::hypot(b[0] - a[0], b[1] - a[1]), std::hypot(d[0] - b[0], d[1] - b[1]), std::hypot(a[0] - d[0], a[1] - d[1])});
            ASSERT_LT(area2, -0.05 * e * e) << what << " cap face " << f;
        }
    }
}

TEST(AwkwardGenerators, MakeAwkwardHitsTheRequestedSize) {
    for (AwkwardFamily fam : kAwkwardFamilies) {
        for (uint32_t target : {0u, 1u, 50u, 700u}) {
            const WalledMesh m = make_awkward(fam, target);
            const std::string what = std::string(awkward_family_name(fam)) + " " + std::to_string(target);
            const Topology t = analyze(m.soup);
            EXPECT_EQ(t.problem, "") << what;
            EXPECT_FALSE(t.unreferenced) << what;
            check_walls(m.soup, m.walls, what);
        }
        for (uint32_t target : {10000u, 31234u}) {
            const WalledMesh m = make_awkward(fam, target);
            const std::string what = std::string(awkward_family_name(fam)) + " " + std::to_string(target);
            const double ratio = static_cast<double>(m.soup.triangles.size()) / target;
            EXPECT_GT(ratio, 0.9) << what;
            EXPECT_LT(ratio, 1.1) << what;
            const Topology t = analyze(m.soup);
            EXPECT_EQ(t.problem, "") << what;
            EXPECT_NO_THROW(Mesh::from_soup(m.soup).validate()) << what;
            const bool walled = fam == AwkwardFamily::SlitWalls || fam == AwkwardFamily::SerpentineWalls;
            EXPECT_EQ(m.walls.empty(), !walled) << what;
            check_walls(m.soup, m.walls, what);
        }
    }
    EXPECT_STREQ(awkward_family_name(AwkwardFamily::SerpentineWalls), "serpentine_walls");
}

TEST(AwkwardGenerators, BadParametersThrow) {
    EXPECT_THROW(make_hole_corridors(2, 0), RequestError);
    EXPECT_THROW(make_slit_corridors(2, 1), RequestError);
    EXPECT_THROW(make_slit_walls(2, 0), RequestError);
    EXPECT_THROW(make_serpentine_walls(2, 1), RequestError);
    EXPECT_THROW(make_disk_many_holes(0, 3), RequestError);
    EXPECT_THROW(make_eared_grid(3, 0), RequestError);
    EXPECT_THROW(make_cone(2, true), RequestError);
}

TEST(Generators, ShufflesKeepTheSurface) {
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        TriangleSoup s = make_genus_with_holes(2, 3, 2);
        const Topology before = analyze(s);
        const TriangleSoup original = s;
        const std::vector<uint32_t> perm = shuffle_vertices(s, seed);
        shuffle_faces(s, seed + 100);
        check_topology(s, {before.V, before.F, before.chi, before.loops, before.genus}, "shuffled " + std::to_string(seed));
        EXPECT_GT(signed_volume6(s), 0);  // orientation kept
        std::vector<uint32_t> sorted = perm;
        std::sort(sorted.begin(), sorted.end());
        for (uint32_t v = 0; v < sorted.size(); ++v) ASSERT_EQ(sorted[v], v);
        for (uint32_t v = 0; v < perm.size(); ++v) EXPECT_EQ(s.points[perm[v]], original.points[v]);
        // The same faces, renamed: every original face is there as a rotation of itself.
        std::set<Triangle> faces;
        for (Triangle t : s.triangles) {
            std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
            faces.insert(t);
        }
        for (Triangle t : original.triangles) {
            for (uint32_t& v : t) v = perm[v];
            std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
            EXPECT_TRUE(faces.count(t));
        }
        TriangleSoup again = original;
        shuffle_vertices(again, seed);
        shuffle_faces(again, seed + 100);
        EXPECT_EQ(again.triangles, s.triangles) << "deterministic for a seed";
    }
}
