// One strip on every oriented manifold: procedural families and thousands of random meshes,
// every result checked by the independent verifier (verify.hpp). Every test runs on both engines
// (test names end in /matching or /growth).
#include <gtest/gtest.h>

#include <random>

#include "fixtures.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "strip_check.hpp"

using namespace singlestrip;
using singlestrip::testing::describe;
using singlestrip::testing::strip_and_verify;

namespace {

void expect_one_strip(const TriangleSoup& soup, const std::string& name, const StripOptions& options) {
    const auto c = strip_and_verify(soup, options);
    EXPECT_TRUE(c.report.ok()) << name << " (" << engine_name(options.engine) << "): " << describe(c);
    EXPECT_EQ(c.arrays.faces.size(), soup.triangles.size() + 2 * c.result.stats.splits) << name;
    // strip.hpp: splits are bounded by the input faces, either engine; the growth builder's own
    // bound (docs/algorithm.md, n - 1 split splices) is strict.
    EXPECT_LE(c.result.stats.splits, soup.triangles.size()) << name;
    if (options.engine == StripEngine::Growth) {
        EXPECT_LT(c.result.stats.splits, std::max<size_t>(1, soup.triangles.size())) << name;
    }
}

// Random flips on flat grids can create collinear (zero-area) faces, which no geometric check
// can place; a small random displacement makes every face non-degenerate first.
void jitter(TriangleSoup& soup, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> d(-0.05, 0.05);
    for (auto& p : soup.points)
        for (double& x : p) x += d(rng) * 0.1;
}

struct Family {
    std::string name;
    TriangleSoup soup;
};

std::vector<Family> families() {
    std::vector<Family> f;
    f.push_back({"single triangle", make_single_triangle()});
    f.push_back({"two triangles", make_two_triangles()});
    for (uint32_t k : {1u, 2u, 3u, 7u, 30u}) f.push_back({"fan " + std::to_string(k), make_fan(k)});
    for (uint32_t k : {1u, 2u, 5u, 40u}) f.push_back({"corridor " + std::to_string(k), make_corridor(k)});
    for (uint32_t n : {1u, 2u, 3u, 5u, 12u}) f.push_back({"grid disk " + std::to_string(n), make_grid_disk(n, n)});
    f.push_back({"grid disk 17x3", make_grid_disk(17, 3)});
    for (uint32_t n : {3u, 8u}) f.push_back({"annulus " + std::to_string(n), make_annulus(4 * n, n)});
    for (uint32_t k : {1u, 2u, 5u}) f.push_back({"disk with holes " + std::to_string(k), make_disk_with_holes(k, 3)});
    for (uint32_t s : {0u, 1u, 3u}) f.push_back({"icosphere " + std::to_string(s), make_icosphere(s)});
    f.push_back({"uv sphere", make_uv_sphere(16, 9)});
    for (uint32_t n : {3u, 6u, 20u}) f.push_back({"torus " + std::to_string(n), make_torus(2 * n, n)});
    for (uint32_t g = 2; g <= 6; ++g) f.push_back({"genus " + std::to_string(g), make_genus_surface(g, 2)});
    f.push_back({"genus 2 with 3 holes", make_genus_with_holes(2, 3, 3)});
    f.push_back({"builtin", make_builtin_model()});
    return f;
}

class Strip : public EngineTest {};

}  // namespace

INSTANTIATE_TEST_SUITE_P(Engines, Strip, kBothEngines, engine_test_name);

TEST_P(Strip, ProceduralFamilies) {
    for (const auto& fam : families()) {
        SCOPED_TRACE(fam.name);
        expect_one_strip(fam.soup, fam.name, opts());
        StripOptions paper = opts();
        paper.greedy = false;
        expect_one_strip(fam.soup, fam.name + " (no greedy)", paper);
    }
}

TEST_P(Strip, ProceduralFamiliesWithEdgeFlips) {
    for (auto fam : families()) {
        if (fam.soup.triangles.size() < 8) continue;
        jitter(fam.soup, 11);
        random_edge_flips(fam.soup, fam.soup.triangles.size() / 3, 7);
        expect_one_strip(fam.soup, fam.name + " flipped", opts());
    }
}

TEST_P(Strip, EverySeedFaceOfSmallMeshes) {
    for (const auto& fam : {make_grid_disk(5, 5), make_torus(6, 4), make_disk_with_holes(2, 2), make_genus_surface(2, 1)}) {
        for (uint32_t f = 0; f < fam.triangles.size(); ++f) {
            StripOptions o = opts();
            o.seed_face = FaceId(f);
            o.validate_each_split = true;
            expect_one_strip(fam, "seed " + std::to_string(f), o);
        }
    }
}

// 2000 random meshes: random family, size, genus 0-5, holes, edge flips and seed face.
TEST_P(Strip, ThousandsOfRandomMeshes) {
    std::mt19937_64 rng(20261122);
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const uint32_t kind = static_cast<uint32_t>(rng() % 6);
        TriangleSoup soup;
        std::string name;
        switch (kind) {
            case 0: {
                const uint32_t nx = 1 + rng() % 14, ny = 1 + rng() % 14;
                soup = make_grid_disk(nx, ny);
                name = "grid " + std::to_string(nx) + "x" + std::to_string(ny);
                break;
            }
            case 1: {
                const uint32_t k = 1 + rng() % 4, r = 1 + rng() % 3;
                soup = make_disk_with_holes(k, r);
                name = "disk holes " + std::to_string(k) + " r" + std::to_string(r);
                break;
            }
            case 2: {
                const uint32_t s = rng() % 3;
                soup = make_icosphere(s);
                name = "icosphere " + std::to_string(s);
                break;
            }
            case 3: {
                const uint32_t a = 3 + rng() % 12, b = 3 + rng() % 8;
                soup = make_torus(a, b);
                name = "torus " + std::to_string(a) + "x" + std::to_string(b);
                break;
            }
            default: {
                const uint32_t g = rng() % 6, r = 1 + rng() % 2;
                soup = make_genus_surface(g, r);
                name = "genus " + std::to_string(g) + " r" + std::to_string(r);
                break;
            }
        }
        const uint64_t seed = rng();
        if (rng() % 2) {
            jitter(soup, seed);
            const size_t flips = random_edge_flips(soup, soup.triangles.size() / 2, seed);
            name += " flips " + std::to_string(flips);
        }
        if (kind >= 2 && rng() % 3 == 0) {
            const size_t holes = 1 + rng() % 4;
            try {
                remove_random_faces_as_holes(soup, holes, seed);
                name += " holes " + std::to_string(holes);
            } catch (const RequestError&) {
            }
        }
        StripOptions o = opts();
        if (rng() % 2) o.seed_face = FaceId(static_cast<uint32_t>(rng() % soup.triangles.size()));
        o.greedy = rng() % 5 != 0;
        o.validate_each_split = i % 2 == 0;  // also checks the matching engine's matching
        SCOPED_TRACE(name + " case " + std::to_string(i));
        expect_one_strip(soup, name, o);
        ++checked;
        if (::testing::Test::HasFailure()) break;
    }
    EXPECT_EQ(checked, 2000);
}

TEST_P(Strip, SplitsStayBelowThePapersOnSyntheticDisks) {
    // A measured bound, not a timing: on a 40x40 grid disk the strip adds less than the paper's
    // +28.5% (fandisk) extra triangles.
    const auto c = strip_and_verify(make_grid_disk(40, 40), opts());
    ASSERT_TRUE(c.report.ok()) << describe(c);
    EXPECT_LT(c.arrays.faces.size(), 1.285 * 3200);
}

TEST_P(Strip, SeveralComponentsAreARequestError) {
    TriangleSoup soup;
    soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
    soup.triangles = {{0, 1, 2}, {3, 4, 5}};
    try {
        build_strip(Mesh::from_soup(soup), opts());
        FAIL() << "two components were stripped as one";
    } catch (const RequestError& e) {
        EXPECT_NE(std::string(e.what()).find("2 edge-connected components"), std::string::npos) << e.what();
    }
}

TEST_P(Strip, BadSeedFaceIsARequestError) {
    StripOptions o = opts();
    o.seed_face = FaceId(99);
    EXPECT_THROW(build_strip(Mesh::from_soup(make_two_triangles()), o), RequestError);
}

TEST_P(Strip, FundamentalTrianglesMatchTopology) {
    // Seed on the boundary (default): the growth builder records 2g + b - 1 fundamental triangles
    // (closed: 2g). Any engine's strip order gives them by replay (cycles.hpp): beta1 falls from
    // 2g + b - 1 to 0, so at least that many. Either way, exactly that many independent cycles.
    struct Case {
        TriangleSoup soup;
        uint32_t expected;
    };
    std::vector<Case> cases;
    cases.push_back({make_torus(12, 6), 2});
    cases.push_back({make_genus_surface(3, 2), 6});
    cases.push_back({make_disk_with_holes(4, 2), 4});
    cases.push_back({make_genus_with_holes(2, 3, 3), 6});
    for (const auto& c : cases) {
        const auto check = strip_and_verify(c.soup, opts());
        EXPECT_TRUE(check.report.ok()) << describe(check);
        EXPECT_EQ(check.result.stats.engine, GetParam());
        if (GetParam() == StripEngine::Growth) {
            EXPECT_EQ(check.result.stats.fundamental_triangles, c.expected);
            EXPECT_EQ(check.result.fundamental_positions.size(), c.expected);
        }
        EXPECT_GE(replay_fundamental_positions(check.result.mesh, check.result.order).size(), c.expected);
        const Cycles cycles = compute_fundamental_cycles(check.result);
        VerifyInput in = verify_input(c.soup, check.arrays, check.indices);
        in.cycles = cycles.cycles;
        const VerifyReport rep = verify(in);
        EXPECT_TRUE(rep.ok()) << rep.to_string();
        EXPECT_EQ(rep.cycle_rank, c.expected);
    }
}

// The moving strip_arrays() gives what the copying one gives, and leaves only the stats.
TEST_P(Strip, MovedArraysEqualCopiedOnes) {
    for (const auto& fam : families()) {
        SCOPED_TRACE(fam.name);
        StripResult r = build_strip(Mesh::from_soup(fam.soup), opts());
        const StripArrays copied = strip_arrays(r);
        const StripStats stats = r.stats;
        const StripArrays moved = strip_arrays(std::move(r));
        EXPECT_EQ(moved.points, copied.points);
        EXPECT_EQ(moved.faces, copied.faces);
        EXPECT_EQ(moved.parent, copied.parent);
        EXPECT_EQ(r.stats.output_triangles, stats.output_triangles);  // NOLINT(bugprone-use-after-move): documented
        EXPECT_EQ(r.stats.splits, stats.splits);
        EXPECT_TRUE(r.order.empty());
        EXPECT_EQ(r.mesh.num_faces(), 0u);
    }
}
