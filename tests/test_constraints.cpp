// Controllable strips (issue 4): constraint edges (§5.1) and source/target vertices (§5.2),
// alone and together, every strip checked by the independent verifier. Every test runs on both
// engines (test names end in /matching or /growth).
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include "cgal_data.hpp"
#include "fixtures.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/validate.hpp"
#include "strip_check.hpp"

using namespace singlestrip;
using singlestrip::testing::describe;
using singlestrip::testing::strip_and_verify;
using EdgeList = std::vector<std::pair<uint32_t, uint32_t>>;

namespace {

void jitter(TriangleSoup& soup, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> d(-0.005, 0.005);
    for (auto& p : soup.points)
        for (double& x : p) x += d(rng);
}

// Independent of the builder: are the faces connected through edges that are not constraints?
size_t pieces_after_cutting(const TriangleSoup& soup, const EdgeList& cuts) {
    std::set<std::pair<uint32_t, uint32_t>> cut;
    for (auto [u, v] : cuts) cut.insert({std::min(u, v), std::max(u, v)});
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> faces_of_edge;
    for (uint32_t f = 0; f < soup.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = soup.triangles[f][k], b = soup.triangles[f][(k + 1) % 3];
            faces_of_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
        }
    std::vector<uint32_t> parent(soup.triangles.size());
    std::iota(parent.begin(), parent.end(), 0u);
    std::function<uint32_t(uint32_t)> find = [&](uint32_t x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
    size_t pieces = soup.triangles.size();
    for (const auto& [e, fs] : faces_of_edge)
        if (fs.size() == 2 && !cut.count(e)) {
            const uint32_t a = find(fs[0]), b = find(fs[1]);
            if (a != b) {
                parent[a] = b;
                --pieces;
            }
        }
    return pieces;
}

// Self-avoiding random walks along mesh edges.
EdgeList random_polylines(const TriangleSoup& soup, std::mt19937_64& rng, int count, int max_len) {
    std::vector<std::vector<uint32_t>> adj(soup.points.size());
    for (const auto& t : soup.triangles)
        for (int k = 0; k < 3; ++k) adj[t[k]].push_back(t[(k + 1) % 3]);
    EdgeList edges;
    for (int p = 0; p < count; ++p) {
        uint32_t v = static_cast<uint32_t>(rng() % soup.points.size());
        std::set<uint32_t> seen{v};
        const int len = 1 + static_cast<int>(rng() % max_len);
        for (int s = 0; s < len && !adj[v].empty(); ++s) {
            const uint32_t w = adj[v][rng() % adj[v].size()];
            if (seen.count(w)) break;
            seen.insert(w);
            edges.push_back({v, w});
            v = w;
        }
    }
    return edges;
}

TriangleSoup random_mesh(std::mt19937_64& rng, std::string& name) {
    TriangleSoup soup;
    switch (rng() % 5) {
        case 0:
            soup = make_grid_disk(3 + rng() % 10, 3 + rng() % 10);
            name = "grid";
            break;
        case 1:
            soup = make_disk_with_holes(1 + rng() % 3, 2 + rng() % 2);
            name = "disk with holes";
            break;
        case 2:
            soup = make_torus(6 + rng() % 10, 4 + rng() % 6);
            name = "torus";
            break;
        case 3:
            soup = make_genus_surface(rng() % 4, 1 + rng() % 2);
            name = "genus surface";
            break;
        default:
            soup = make_icosphere(1 + rng() % 2);
            name = "icosphere";
            break;
    }
    if (rng() % 2) {
        jitter(soup, rng());
        random_edge_flips(soup, soup.triangles.size() / 4, rng());
        name += " flipped";
    }
    return soup;
}

class Constraints : public EngineTest {};
class Endpoints : public EngineTest {};
class ConstraintsReal : public EngineTest {};

}  // namespace

INSTANTIATE_TEST_SUITE_P(Engines, Constraints, kBothEngines, engine_test_name);
INSTANTIATE_TEST_SUITE_P(Engines, Endpoints, kBothEngines, engine_test_name);
INSTANTIATE_TEST_SUITE_P(Engines, ConstraintsReal, kBothEngines, engine_test_name);

TEST_P(Constraints, ThousandRandomCasesWithEndpoints) {
    std::mt19937_64 rng(4242);
    int verified = 0, separating = 0;
    for (int i = 0; i < 1000; ++i) {
        std::string name;
        const TriangleSoup soup = random_mesh(rng, name);
        StripOptions o = opts();
        const int mode = i % 4;  // constraints, endpoints, both, both with source == target
        if (mode != 1) o.constraint_edges = as_constraints(random_polylines(soup, rng, 1 + rng() % 4, 12));
        if (mode != 0) {
            o.source = VertexId(soup.triangles[rng() % soup.triangles.size()][rng() % 3]);
            o.target = VertexId(mode == 3 ? o.source->idx() : soup.triangles[rng() % soup.triangles.size()][rng() % 3]);
        }
        SCOPED_TRACE(name + " case " + std::to_string(i));
        const size_t pieces = pieces_after_cutting(soup, vertex_pairs(o.constraint_edges));
        try {
            const auto c = strip_and_verify(soup, o);
            EXPECT_EQ(pieces, 1u) << "a separating constraint set was accepted";
            EXPECT_TRUE(c.report.ok()) << describe(c);
            ++verified;
        } catch (const RequestError& e) {
            const std::string msg = e.what();
            if (pieces > 1) {
                EXPECT_NE(msg.find(std::to_string(pieces) + " pieces"), std::string::npos) << msg;
                ++separating;
            } else {
                ADD_FAILURE() << "unexpected request error: " << msg;
            }
        }
        if (::testing::Test::HasFailure()) break;
    }
    std::printf("verified %d strips, %d separating constraint sets rejected\n", verified, separating);
    EXPECT_GT(verified, 700);
}

// Edge flips on a grid without jitter leave input edges through input vertices (zero-area
// faces). A constraint along such an edge has other vertices on its line: the verifier judges
// the constraint by the mesh's edges, not by that geometry.
TEST_P(Constraints, DegenerateInputWithVerticesOnConstraintLines) {
    std::mt19937_64 rng(99);
    int verified = 0;
    for (int i = 0; i < 60; ++i) {
        TriangleSoup soup = make_genus_with_holes(1 + i % 3, 1 + i % 5, 6 + i % 8);
        random_edge_flips(soup, soup.triangles.size() / 5, 100 + i);
        StripOptions o = opts();
        o.constraint_edges = as_constraints(random_polylines(soup, rng, 2 + i % 4, 16));
        if (pieces_after_cutting(soup, vertex_pairs(o.constraint_edges)) != 1) continue;
        SCOPED_TRACE("case " + std::to_string(i));
        const auto c = strip_and_verify(soup, o);
        EXPECT_TRUE(c.report.ok()) << describe(c);
        ++verified;
        if (::testing::Test::HasFailure()) break;
    }
    EXPECT_GT(verified, 30);
}

TEST_P(Constraints, LoopsAroundTorusHandles) {
    const uint32_t nm = 12, nn = 8;
    const TriangleSoup torus = make_torus(nm, nn);
    auto id = [&](uint32_t i, uint32_t j) { return (i % nm) * nn + j % nn; };
    EdgeList meridian, longitude, second_meridian;
    for (uint32_t j = 0; j < nn; ++j) meridian.push_back({id(0, j), id(0, j + 1)});
    for (uint32_t j = 0; j < nn; ++j) second_meridian.push_back({id(5, j), id(5, j + 1)});
    for (uint32_t i = 0; i < nm; ++i) longitude.push_back({id(i, 0), id(i + 1, 0)});
    for (const EdgeList& loops : {meridian, longitude, [&] {
                                      EdgeList both = meridian;
                                      both.insert(both.end(), longitude.begin(), longitude.end());
                                      return both;
                                  }()}) {
        StripOptions o = opts();
        o.constraint_edges = as_constraints(loops);
        o.source = VertexId(id(3, 3));
        o.target = VertexId(id(8, 5));
        const auto c = strip_and_verify(torus, o);
        EXPECT_TRUE(c.report.ok()) << describe(c);
    }
    StripOptions cut = opts();
    EdgeList both_meridians = meridian;
    both_meridians.insert(both_meridians.end(), second_meridian.begin(), second_meridian.end());
    cut.constraint_edges = as_constraints(both_meridians);
    try {
        build_strip(Mesh::from_soup(torus), cut);
        FAIL() << "two meridians cut the torus in two";
    } catch (const RequestError& e) {
        EXPECT_NE(std::string(e.what()).find("2 pieces"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("112, 80"), std::string::npos) << e.what();
    }
}

TEST_P(Constraints, BoundaryConstraintEdgesChangeNothing) {
    const TriangleSoup disk = make_grid_disk(4, 4);
    StripOptions o = opts();
    o.constraint_edges = {{0, 1}, {1, 2}, {2, 3}};  // along the grid's first row: the boundary
    const auto with = strip_and_verify(disk, o);
    const auto without = strip_and_verify(disk, opts());
    EXPECT_TRUE(with.report.ok()) << describe(with);
    EXPECT_EQ(with.arrays.faces, without.arrays.faces);
}

TEST_P(Constraints, PairThatIsNotAnEdgeIsARequestError) {
    StripOptions o = opts();
    o.constraint_edges = {{0, 1}, {0, 24}};
    try {
        build_strip(Mesh::from_soup(make_grid_disk(4, 4)), o);
        FAIL();
    } catch (const RequestError& e) {
        EXPECT_NE(std::string(e.what()).find("(0, 24) is not an edge"), std::string::npos) << e.what();
    }
}

TEST_P(Endpoints, BadVerticesAreRequestErrors) {
    TriangleSoup s = make_grid_disk(2, 2);
    s.points.push_back({5, 5, 5});  // unreferenced vertex
    StripOptions o = opts();
    o.source = VertexId(1000);
    EXPECT_THROW(build_strip(Mesh::from_soup(s), o), RequestError);
    o.source = VertexId(static_cast<uint32_t>(s.points.size() - 1));
    EXPECT_THROW(build_strip(Mesh::from_soup(s), o), RequestError);
    StripOptions t = opts();
    t.target = VertexId(static_cast<uint32_t>(s.points.size() - 1));
    EXPECT_THROW(build_strip(Mesh::from_soup(s), t), RequestError);
}

TEST_P(Endpoints, EveryVertexPairOfASmallMesh) {
    const TriangleSoup soup = make_disk_with_holes(1, 2);
    for (uint32_t s = 0; s < soup.points.size(); s += 3)
        for (uint32_t t = 0; t < soup.points.size(); t += 2) {
            StripOptions o = opts();
            o.source = VertexId(s);
            o.target = VertexId(t);
            o.validate_each_split = true;
            const auto c = strip_and_verify(soup, o);
            EXPECT_TRUE(c.report.ok()) << s << " -> " << t << ": " << describe(c);
        }
}

TEST_P(ConstraintsReal, RandomConstraintsAndEndpointsOnRealMeshes) {
    std::mt19937_64 rng(99);
    for (const char* name : {"fandisk.off", "head.off", "eight.off", "mushroom.off"}) {
        const std::string path = singlestrip::test::cgal_mesh_path(name);
        if (path.empty()) GTEST_SKIP() << "libcgal-demo data not available";
        const TriangleSoup soup = prepare_soup(read_mesh_file(path), {}, path);
        for (int i = 0; i < 8; ++i) {
            StripOptions o = opts();
            o.constraint_edges = as_constraints(random_polylines(soup, rng, 1 + rng() % 6, 40));
            o.source = VertexId(soup.triangles[rng() % soup.triangles.size()][0]);
            o.target = VertexId(soup.triangles[rng() % soup.triangles.size()][1]);
            const size_t pieces = pieces_after_cutting(soup, vertex_pairs(o.constraint_edges));
            if (pieces > 1) {
                EXPECT_THROW(build_strip(Mesh::from_soup(soup), o), RequestError);
                continue;
            }
            const auto c = strip_and_verify(soup, o);
            EXPECT_TRUE(c.report.ok()) << name << " case " << i << ": " << describe(c);
        }
    }
}

TEST_P(Endpoints, TargetWhoseOnlyFaceIsTheFirstFace) {
    // A corner of a single-row corridor has one face: start and end there (source == target).
    const TriangleSoup soup = make_grid_disk(3, 3);
    for (uint32_t v = 0; v < soup.points.size(); ++v) {
        StripOptions o = opts();
        o.source = VertexId(v);
        o.target = VertexId(v);
        const auto c = strip_and_verify(soup, o);
        EXPECT_TRUE(c.report.ok()) << v << ": " << describe(c);
    }
}

// Issue 5 point 3: with constraints and endpoints the cycles are still the surface's
// (2g+h-1 of them, independent), whatever the constraints did to the fundamental triangles.
TEST_P(Constraints, CyclesAreTheSurfacesWithConstraintsAndEndpoints) {
    const uint32_t nm = 12, nn = 8;
    const TriangleSoup torus = make_torus(nm, nn);
    auto id = [&](uint32_t i, uint32_t j) { return (i % nm) * nn + j % nn; };
    std::mt19937_64 rng(5);
    for (int variant = 0; variant < 4; ++variant) {
        StripOptions o = opts();
        if (variant & 1)
            for (uint32_t j = 0; j < nn; ++j) o.constraint_edges.push_back({id(0, j), id(0, j + 1)});
        if (variant & 2) {
            o.source = VertexId(id(3, 3));
            o.target = VertexId(id(9, 2));
        }
        auto c = strip_and_verify(torus, o);
        ASSERT_TRUE(c.report.ok()) << describe(c);
        const Cycles cycles = compute_fundamental_cycles(c.result);
        VerifyInput vi = verify_input(torus, c.arrays, c.indices);
        vi.cycles = cycles.cycles;
        const VerifyReport rep = verify(vi);
        EXPECT_TRUE(rep.ok()) << "variant " << variant << ": " << rep.to_string();
        EXPECT_EQ(cycles.cycles.size(), 2u) << "variant " << variant;
    }
}

// Either endpoint may be given alone (strip.hpp: first face on `source`, last on `target`).
TEST_P(Endpoints, SourceAloneOrTargetAlone) {
    for (const auto& [name, soup] : {std::pair{"grid 3x3", make_grid_disk(3, 3)}, std::pair{"torus 6x4", make_torus(6, 4)},
                                     std::pair{"disk with holes", make_disk_with_holes(1, 2)}}) {
        for (uint32_t v = 0; v < soup.points.size(); ++v) {
            StripOptions s = opts();
            s.source = VertexId(v);
            const auto from = strip_and_verify(soup, s);
            EXPECT_TRUE(from.report.ok()) << name << " source " << v << ": " << describe(from);
            StripOptions t = opts();
            t.target = VertexId(v);
            const auto to = strip_and_verify(soup, t);
            EXPECT_TRUE(to.report.ok()) << name << " target " << v << ": " << describe(to);
        }
    }
}
