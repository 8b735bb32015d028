// Fundamental cycles (paper §4) and tree–cotree generators: count 2g+h-1 (2g closed), closed
// chains, Z2 independence — each set checked by the independent verifier (verify.hpp) AND by a
// second Z2 rank check written here (intersection parity with relative cycles of H1(M, dM)).
// Every test that builds a strip runs on both engines (test names end in /matching or /growth).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cgal_data.hpp"
#include "cycle_check.hpp"
#include "fixtures.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/tree_cotree.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"
#include "strip_check.hpp"

using namespace singlestrip;
using singlestrip::testing::expect_closed_chains;

namespace {

// ---- second opinion: Z2 rank of face-chain cycles in H1(M; Z2), written from face arrays only.
// A closed face chain crosses a set of interior edges (a Z2 1-cycle of the dual). Its class in
// H1(M) is detected by intersection parity with relative cycles of H1(M, dM): for every interior
// edge e = (u, w) not in a spanning tree Tq of the graph in which all boundary vertices are one
// vertex, the relative cycle path(u) + e + path(w) (tree paths to the root). These span
// H1(M, dM), and the pairing is perfect (Lefschetz duality), so the rank of the parity matrix is
// the rank of the cycles in H1(M; Z2). The tree here is depth-first (the verifier's and the
// library's are breadth-first).
struct RankCheck {
    size_t rank = 0;
    bool chains_ok = true;
    std::string problem;
};

RankCheck z2_rank(const std::vector<Point3>& /*points*/, const std::vector<Triangle>& faces,
                  const std::vector<std::vector<uint32_t>>& cycles) {
    RankCheck rc;
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> by_edge;  // undirected edge -> faces
    uint32_t nv = 0;
    for (uint32_t f = 0; f < faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = faces[f][k], b = faces[f][(k + 1) % 3];
            by_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
            nv = std::max(nv, std::max(a, b) + 1);
        }
    std::vector<char> on_boundary(nv, 0);
    std::vector<std::pair<uint32_t, uint32_t>> edges;  // interior edges
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> edge_id;
    for (const auto& [e, fs] : by_edge) {
        if (fs.size() == 1) on_boundary[e.first] = on_boundary[e.second] = 1;
        if (fs.size() == 2) {
            edge_id[{std::min(fs[0], fs[1]), std::max(fs[0], fs[1])}] = static_cast<uint32_t>(edges.size());
            edges.push_back(e);
        }
    }
    const uint32_t super = nv;
    auto q = [&](uint32_t v) { return on_boundary[v] ? super : v; };
    std::vector<std::vector<std::pair<uint32_t, uint32_t>>> adj(nv + 1);  // (neighbour, edge)
    for (uint32_t e = 0; e < edges.size(); ++e) {
        const uint32_t a = q(edges[e].first), b = q(edges[e].second);
        if (a == b) continue;
        adj[a].push_back({b, e});
        adj[b].push_back({a, e});
    }
    bool any_boundary = std::find(on_boundary.begin(), on_boundary.end(), 1) != on_boundary.end();
    const uint32_t root = any_boundary ? super : faces[0][0];
    // Depth-first tree (explicit stack), parent edge per vertex, vertices in discovery order.
    std::vector<uint32_t> parent_edge(nv + 1, UINT32_MAX), parent(nv + 1, UINT32_MAX), disc;
    std::vector<char> seen(nv + 1, 0);
    std::vector<char> in_tree(edges.size(), 0);
    std::vector<std::pair<uint32_t, size_t>> stack{{root, 0}};
    seen[root] = 1;
    disc.push_back(root);
    while (!stack.empty()) {
        auto& [v, i] = stack.back();
        if (i == adj[v].size()) {
            stack.pop_back();
            continue;
        }
        const auto [w, e] = adj[v][i++];
        if (seen[w]) continue;
        seen[w] = 1;
        in_tree[e] = 1;
        parent[w] = v;
        parent_edge[w] = e;
        disc.push_back(w);
        stack.push_back({w, 0});
    }
    std::vector<uint32_t> non_tree;
    for (uint32_t e = 0; e < edges.size(); ++e)
        if (!in_tree[e]) non_tree.push_back(e);

    const size_t m = cycles.size();
    std::vector<std::vector<uint8_t>> rows(m, std::vector<uint8_t>(non_tree.size(), 0));
    for (size_t c = 0; c < m; ++c) {
        std::vector<uint8_t> crossed(edges.size(), 0);
        const auto& cyc = cycles[c];
        for (size_t i = 0; i < cyc.size(); ++i) {
            const uint32_t f = cyc[i], g = cyc[(i + 1) % cyc.size()];
            auto it = edge_id.find({std::min(f, g), std::max(f, g)});
            if (f >= faces.size() || g >= faces.size() || it == edge_id.end()) {
                rc.chains_ok = false;
                rc.problem = "cycle " + std::to_string(c) + ": faces " + std::to_string(f) + ", " + std::to_string(g) + " are not adjacent";
                return rc;
            }
            crossed[it->second] ^= 1;
        }
        // Parity of crossings along the tree path from each vertex to the root.
        std::vector<uint8_t> par(nv + 1, 0);
        for (uint32_t v : disc)
            if (v != root) par[v] = par[parent[v]] ^ crossed[parent_edge[v]];
        for (size_t j = 0; j < non_tree.size(); ++j) {
            const uint32_t e = non_tree[j];
            rows[c][j] = crossed[e] ^ par[q(edges[e].first)] ^ par[q(edges[e].second)];
        }
    }
    // Gaussian elimination over Z2.
    size_t rank = 0;
    for (size_t col = 0; col < non_tree.size() && rank < m; ++col) {
        size_t piv = rank;
        while (piv < m && !rows[piv][col]) ++piv;
        if (piv == m) continue;
        std::swap(rows[piv], rows[rank]);
        for (size_t r = 0; r < m; ++r)
            if (r != rank && rows[r][col])
                for (size_t k = col; k < non_tree.size(); ++k) rows[r][k] ^= rows[rank][k];
        ++rank;
    }
    rc.rank = rank;
    return rc;
}

long long expected_count(long long genus, long long loops) {
    return loops == 0 ? 2 * genus : 2 * genus + loops - 1;
}

double mean(const std::vector<double>& v) {
    return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

double mean_faces(const Cycles& c) {
    double s = 0;
    for (const auto& x : c.cycles) s += static_cast<double>(x.size());
    return c.cycles.empty() ? 0.0 : s / static_cast<double>(c.cycles.size());
}

struct Outcome {
    Cycles strip_cycles, tc_cycles;
};

/// Strip, cycles, tree-cotree; both sets checked by verify() and by z2_rank().
/// `degenerate_geometry`: random flips of planar regions make zero-area faces, which the verifier's
/// geometric checks may flag; only its cycle checks are then required to pass.
Outcome check_surface(const TriangleSoup& soup, long long genus, long long loops, const std::string& what, const StripOptions& opt,
                      bool degenerate_geometry = false) {
    Outcome o;
    Mesh mesh = Mesh::from_soup(soup);
    EXPECT_EQ(mesh.genus(), genus) << what;
    EXPECT_EQ(mesh.num_boundary_loops(), static_cast<uint32_t>(loops)) << what;
    const long long expected = expected_count(genus, loops);
    const StripResult r = build_strip(std::move(mesh), opt);
    const StripArrays a = strip_arrays(r);
    o.strip_cycles = compute_fundamental_cycles(r);
    o.tc_cycles = tree_cotree_cycles(r);
    EXPECT_EQ(static_cast<long long>(o.strip_cycles.cycles.size()), expected) << what << " (steepest ascent)";
    EXPECT_EQ(static_cast<long long>(o.tc_cycles.cycles.size()), expected) << what << " (tree-cotree)";
    expect_closed_chains(r, o.strip_cycles, what + " steepest ascent");
    expect_closed_chains(r, o.tc_cycles, what + " tree-cotree");

    for (const Cycles* c : {&o.strip_cycles, &o.tc_cycles}) {
        const std::string which = what + (c == &o.strip_cycles ? " steepest ascent" : " tree-cotree");
        VerifyInput in = verify_input(soup, a, encode_triangle_strip(a.faces));
        in.constraints = vertex_pairs(opt.constraint_edges);
        in.source = index_of(opt.source);
        in.target = index_of(opt.target);
        in.cycles = c->cycles;
        const VerifyReport rep = verify(in);
        if (!degenerate_geometry) {
            EXPECT_TRUE(rep.ok()) << which << ": " << rep.to_string();
        }
        for (const std::string& f : rep.failures) EXPECT_NE(f.rfind("cycles", 0), 0u) << which << ": " << f;
        EXPECT_EQ(rep.cycles_checked, static_cast<size_t>(expected)) << which;
        EXPECT_EQ(static_cast<long long>(rep.cycle_rank), expected) << which;
        const RankCheck rc = z2_rank(a.points, a.faces, c->cycles);
        EXPECT_TRUE(rc.chains_ok) << which << ": " << rc.problem;
        EXPECT_EQ(static_cast<long long>(rc.rank), expected) << which << " (second-opinion Z2 rank)";
    }
    return o;
}

TriangleSoup load_real(const std::string& name) {
    const std::string path = test::cgal_mesh_path(name);
    if (path.empty()) return {};
    return prepare_soup(read_mesh_file(path), PrepareOptions{}, path);
}

class StripCycles : public EngineTest {};
class StripCyclesReal : public EngineTest {};

}  // namespace

INSTANTIATE_TEST_SUITE_P(Engines, StripCycles, kBothEngines, engine_test_name);
INSTANTIATE_TEST_SUITE_P(Engines, StripCyclesReal, kBothEngines, engine_test_name);

// ---- procedural surfaces ----

TEST_P(StripCycles, TorusHasTwo) {
    for (uint32_t n : {3u, 4u, 8u, 16u}) check_surface(make_torus(2 * n, n), 1, 0, "torus " + std::to_string(n), opts());
}

TEST_P(StripCycles, DoubleTorusHasFour) {
    for (uint32_t r : {1u, 2u, 4u}) check_surface(make_genus_surface(2, r), 2, 0, "genus 2 r=" + std::to_string(r), opts());
}

TEST_P(StripCycles, GenusFiveHasTen) {
    for (uint32_t r : {1u, 3u}) check_surface(make_genus_surface(5, r), 5, 0, "genus 5 r=" + std::to_string(r), opts());
}

TEST_P(StripCycles, SphereAndDiskHaveNone) {
    check_surface(make_icosphere(2), 0, 0, "icosphere", opts());
    check_surface(make_grid_disk(6, 5), 0, 1, "grid disk", opts());
}

TEST_P(StripCycles, DiskWithHolesHasKMinusOne) {
    // k holes in a disk: b = k + 1 boundary loops, so 2g + b - 1 = k cycles.
    for (uint32_t k : {1u, 2u, 3u, 5u})
        for (uint32_t r : {1u, 2u, 3u})
            check_surface(make_disk_with_holes(k, r), 0, k + 1, "disk with " + std::to_string(k) + " holes r=" + std::to_string(r), opts());
}

// A strip that starts inside a large mesh with boundary (here from an interior seed face): its
// first face opens a hole, so the replay finds one fundamental triangle more than 2g+h-1, and
// from 2^19 faces the order is replayed from its first face on the boundary instead of computing
// homology classes (cycles.cpp, choose_nested_reordered). Still a verified basis of strip cycles.
TEST_P(StripCycles, LargeStripFromAnInteriorSeed) {
    TriangleSoup soup = make_annulus(1024, 264);
    remove_random_faces_as_holes(soup, 8, 7);
    Mesh mesh = Mesh::from_soup(soup);
    ASSERT_GE(mesh.num_faces(), 1u << 19);
    auto on_boundary = [&](const Mesh& m, FaceId f) {
        return m.is_boundary(Mesh::halfedge(f, 0)) || m.is_boundary(Mesh::halfedge(f, 1)) || m.is_boundary(Mesh::halfedge(f, 2));
    };
    FaceId seed(mesh.num_faces() / 2);
    while (on_boundary(mesh, seed)) seed = FaceId(seed.idx() + 1);
    StripOptions o = opts();
    o.seed_face = seed;
    const StripResult r = build_strip(std::move(mesh), o);
    ASSERT_FALSE(on_boundary(r.mesh, FaceId(r.order.front()))) << "the scenario: the strip starts inside";
    const Cycles c = compute_fundamental_cycles(r);
    ASSERT_EQ(c.cycles.size(), 9u);  // annulus (h = 2) with 8 more holes: 2g + h - 1
    for (const CycleSource s : c.sources) EXPECT_NE(s, CycleSource::TreeCotree);
    expect_closed_chains(r, c, "annulus with holes, interior seed");
    const StripArrays a = strip_arrays(r);
    VerifyInput in = verify_input(soup, a, encode_triangle_strip(a.faces));
    in.cycles = c.cycles;
    const VerifyReport rep = verify(in);
    EXPECT_TRUE(rep.ok()) << rep.to_string();
    EXPECT_EQ(rep.cycle_rank, 9u);
    EXPECT_EQ(z2_rank(a.points, a.faces, c.cycles).rank, 9u) << "second-opinion Z2 rank";
}

// Corridors one quad wide between long holes: each breadth-first search around a fundamental
// triangle covers most of the mesh, so past their budget the cycles are the tree–cotree
// generators (cycles.hpp), still a verified basis.
TEST_P(StripCycles, CorridorsBetweenLongHolesFallBackToTreeCotree) {
    const TriangleSoup soup = make_hole_corridors(24, 400);
    const long long holes = 24;
    const Outcome o = check_surface(soup, 0, holes + 1, "hole corridors", opts());
    for (const CycleSource s : o.strip_cycles.sources) EXPECT_EQ(s, CycleSource::TreeCotree);
}

TEST_P(StripCycles, GenusWithHolesRandomFlips) {
    uint64_t seed = 1;
    for (uint32_t g : {1u, 2u, 3u})
        for (uint32_t h : {1u, 2u, 4u}) {
            TriangleSoup s = make_genus_with_holes(g, h, 3);
            random_edge_flips(s, s.triangles.size() / 4, seed++);
            check_surface(s, g, h, "genus " + std::to_string(g) + " with " + std::to_string(h) + " holes (flipped)", opts(), true);
        }
}

TEST_P(StripCycles, RandomTorusAndAnnulusMeshes) {
    for (uint64_t seed = 1; seed <= 6; ++seed) {
        TriangleSoup t = make_torus(12, 7);
        random_edge_flips(t, 60, seed);
        check_surface(t, 1, 0, "flipped torus seed " + std::to_string(seed), opts(), true);
        TriangleSoup a = make_annulus(10, 3);
        random_edge_flips(a, 20, seed);
        check_surface(a, 0, 2, "flipped annulus seed " + std::to_string(seed), opts(), true);
    }
}

TEST_P(StripCycles, ClosedSurfaceAnySeedFace) {
    // On a closed surface every seed is "on the boundary" of nothing: count and independence hold.
    const TriangleSoup s = make_genus_surface(2, 2);
    for (uint32_t seed : {0u, 17u, 101u}) {
        StripOptions opt = opts();
        opt.seed_face = FaceId(seed);
        check_surface(s, 2, 0, "genus 2, seed face " + std::to_string(seed), opt);
    }
}

TEST_P(StripCycles, InteriorSeedStillClosedChains) {
    // Seed not on the boundary: closed chains, and still a basis (cycles.hpp, any seed).
    const TriangleSoup s = make_disk_with_holes(2, 3);
    Mesh mesh = Mesh::from_soup(s);
    // A face with no boundary edge.
    uint32_t interior = kNone;
    for (uint32_t f = 0; f < mesh.num_faces() && interior == kNone; ++f) {
        bool b = false;
        for (uint32_t k = 0; k < 3; ++k) b = b || mesh.is_boundary(Mesh::halfedge(FaceId(f), k));
        if (!b && f > 20) interior = f;
    }
    ASSERT_NE(interior, kNone);
    StripOptions opt = opts();
    opt.seed_face = FaceId(interior);
    const auto check = singlestrip::testing::strip_and_verify(s, opt);
    EXPECT_TRUE(check.report.ok()) << singlestrip::testing::describe(check);
    const StripResult& r = check.result;
    const Cycles c = compute_fundamental_cycles(r);
    // cycles.hpp: 2g + h - 1 cycles for any seed (here 0 + 3 - 1), tree-cotree filling in for
    // classes the growth builder's interior seed did not meet.
    EXPECT_EQ(c.cycles.size(), 2u);
    expect_closed_chains(r, c, "interior seed");
}

TEST(CycleTools, TreeCotreeOnInputMeshWithIdentityOrder) {
    const TriangleSoup s = make_genus_with_holes(2, 3, 2);
    const Mesh m = Mesh::from_soup(s);
    const auto gens = tree_cotree_generators(m);
    ASSERT_EQ(gens.size(), 2u * 2 + 3 - 1);
    const RankCheck rc = z2_rank(s.points, s.triangles, gens);
    EXPECT_TRUE(rc.chains_ok) << rc.problem;
    EXPECT_EQ(rc.rank, gens.size());
    EXPECT_THROW(tree_cotree_generators(m, {0, 1, 2}), RequestError);
}

TEST(CycleTools, SecondOpinionDetectsDependence) {
    // The rank check must not be vacuous: duplicate a cycle and the rank stays put; a cycle
    // around one interior vertex (its face star) is null-homologous.
    const TriangleSoup s = make_torus(9, 5);
    const Mesh m = Mesh::from_soup(s);
    auto gens = tree_cotree_generators(m);
    ASSERT_EQ(gens.size(), 2u);
    gens.push_back(gens[0]);
    EXPECT_EQ(z2_rank(s.points, s.triangles, gens).rank, 2u);
    // Star of vertex 0 in rotation order.
    std::vector<uint32_t> star;
    const uint32_t h0 = m.vertex_halfedge(VertexId(0)).idx();
    uint32_t h = h0;
    do {
        star.push_back(Mesh::face(HalfedgeId(h)).idx());
        h = m.twin(Mesh::prev(HalfedgeId(h))).idx();  // next outgoing half-edge around vertex 0
    } while (h != h0 && h != kNone);
    const RankCheck rc = z2_rank(s.points, s.triangles, {star});
    EXPECT_TRUE(rc.chains_ok) << rc.problem;
    EXPECT_EQ(rc.rank, 0u);
}

// ---- output files ----

TEST_P(StripCycles, WritesJsonAndObj) {
    const StripResult r = build_strip(Mesh::from_soup(make_torus(10, 6)), opts());
    const Cycles c = compute_fundamental_cycles(r);
    const StripArrays a = strip_arrays(r);
    // One file per engine: ctest may run both instances at once.
    const std::string json_path = ::testing::TempDir() + "ss_cycles_test_" + engine_name(GetParam()) + ".json";
    const std::string obj_path = ::testing::TempDir() + "ss_cycles_test_" + engine_name(GetParam()) + ".obj";
    write_cycles_json(json_path, c);
    write_cycles_obj(obj_path, cycle_polylines(a, c));

    // The verifier's own reader reads the JSON back identically.
    EXPECT_EQ(read_cycles_file(json_path), c.cycles);
    std::ifstream jf(json_path);
    const nlohmann::json j = nlohmann::json::parse(jf);
    ASSERT_EQ(j.at("lengths").size(), c.lengths.size());
    for (size_t i = 0; i < c.lengths.size(); ++i) EXPECT_DOUBLE_EQ(j["lengths"][i].get<double>(), c.lengths[i]);

    // OBJ: 2 points per face of each cycle; each `l` closes on its first vertex; polyline length
    // recomputed from the file equals the reported length.
    std::ifstream of(obj_path);
    std::vector<Point3> v;
    std::vector<std::vector<size_t>> lines;
    for (std::string line; std::getline(of, line);) {
        std::istringstream is(line);
        std::string tag;
        is >> tag;
        if (tag == "v") {
            Point3 p;
            is >> p[0] >> p[1] >> p[2];
            v.push_back(p);
        } else if (tag == "l") {
            lines.emplace_back();
            for (size_t k; is >> k;) lines.back().push_back(k);
        }
    }
    ASSERT_EQ(lines.size(), c.cycles.size());
    for (size_t i = 0; i < lines.size(); ++i) {
        EXPECT_EQ(lines[i].size(), 2 * c.cycles[i].size() + 1);
        EXPECT_EQ(lines[i].front(), lines[i].back());
        double len = 0;
        for (size_t k = 0; k + 1 < lines[i].size(); ++k) {
            const Point3& p = v.at(lines[i][k] - 1);
            const Point3& q = v.at(lines[i][k + 1] - 1);
            len += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
        }
        EXPECT_NEAR(len, c.lengths[i], 1e-9 * (1 + len));
    }
    std::remove(json_path.c_str());
    std::remove(obj_path.c_str());
}

TEST(CycleTools, WriteToMissingDirectoryThrowsOutputError) {
    const Cycles c;
    EXPECT_THROW(write_cycles_json("/nonexistent-dir-singlestrip/c.json", c), OutputError);
    EXPECT_THROW(write_cycles_obj("/nonexistent-dir-singlestrip/c.obj", cycle_polylines(StripArrays{}, c)), OutputError);
}

TEST(CycleTools, CycleLengthOfTwoUnitTriangles) {
    // Square [0,1]^2 split on the diagonal: the 2-chain goes centroid -> diagonal midpoint ->
    // centroid -> same midpoint -> back.
    StripArrays a;
    a.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    a.faces = {{0, 1, 2}, {0, 2, 3}};
    const double d = std::sqrt(2.0) / 6.0;  // centroid to diagonal midpoint
    EXPECT_NEAR(cycle_length(a, {0, 1}), 4 * d, 1e-12);
    EXPECT_EQ(cycle_length(a, {0}), 0.0);
}

// ---- real meshes (libcgal-demo) ----

namespace {
void check_real(const std::string& name, long long expected_genus, long long expected_loops, long long expected_cycles,
                const StripOptions& opt) {
    const TriangleSoup s = load_real(name);
    if (s.triangles.empty()) GTEST_SKIP() << name << " not available";
    const Mesh m = Mesh::from_soup(s);
    if (expected_genus >= 0) {
        EXPECT_EQ(m.genus(), expected_genus) << name;
    }
    if (expected_loops >= 0) {
        EXPECT_EQ(m.num_boundary_loops(), static_cast<uint32_t>(expected_loops)) << name;
    }
    const long long g = m.genus();
    const long long b = m.num_boundary_loops();
    if (expected_cycles >= 0) {
        EXPECT_EQ(expected_count(g, b), expected_cycles) << name;
    }
    const Outcome o = check_surface(s, g, b, name, opt);
    std::printf(
        "[cycles] %s %s: g=%lld h=%lld cycles=%zu | steepest ascent: mean %.4f (%.1f faces) | tree-cotree: mean %.4f (%.1f faces)\n",
        engine_name(opt.engine), name.c_str(), g, b, o.strip_cycles.cycles.size(), mean(o.strip_cycles.lengths), mean_faces(o.strip_cycles),
        mean(o.tc_cycles.lengths), mean_faces(o.tc_cycles));
    size_t by_source[6] = {0, 0, 0, 0, 0, 0};
    for (CycleSource src : o.strip_cycles.sources) ++by_source[static_cast<size_t>(src)];
    std::printf(
        "[cycles] %s %s sources: ascent %zu, descent %zu, strip segment %zu, shortest path %zu, tree-cotree fill %zu, parallel path %zu\n",
        engine_name(opt.engine), name.c_str(), by_source[0], by_source[1], by_source[2], by_source[3], by_source[4], by_source[5]);
    ::testing::Test::RecordProperty("steepest_ascent_mean_length", std::to_string(mean(o.strip_cycles.lengths)));
    ::testing::Test::RecordProperty("tree_cotree_mean_length", std::to_string(mean(o.tc_cycles.lengths)));
}
}  // namespace

TEST_P(StripCyclesReal, Eight) {
    check_real("eight.off", 2, 0, 4, opts());
}
TEST_P(StripCyclesReal, Head) {
    check_real("head.off", 0, 3, 2, opts());
}
TEST_P(StripCyclesReal, ElephantWithHoles) {
    check_real("elephant-with-holes.off", -1, -1, -1, opts());
}
TEST_P(StripCyclesReal, Turbine) {
    check_real("turbine.off", -1, -1, -1, opts());
}
TEST_P(StripCyclesReal, Cheese) {
    check_real("cheese.off", -1, -1, 266, opts());
}
