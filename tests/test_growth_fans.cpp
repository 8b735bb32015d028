// singlestrip — high-valence vertices and the growth builder's O(1) cavity test (issue 17).
// Large sizes (10^5, 10^6 faces) are in test_slow_scaling.cpp (label `slow`).
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "fixtures.hpp"
#include "many_centres.hpp"
#include "singlestrip/strip.hpp"
#include "strip_check.hpp"

namespace {

using namespace singlestrip;
using singlestrip::testing::make_many_centres;
using singlestrip::testing::strip_and_verify;

void expect_verified(const TriangleSoup& soup, const StripOptions& o, const std::string& what) {
    try {
        const auto c = strip_and_verify(soup, o);
        EXPECT_TRUE(c.report.ok()) << what << "\n" << singlestrip::testing::describe(c);
        EXPECT_EQ(c.result.stats.engine, o.engine) << what;
    } catch (const std::exception& e) {
        ADD_FAILURE() << what << " threw: " << e.what();
    }
}

class BothEngines : public ::testing::TestWithParam<StripEngine> {};

// Several centres of high valence, open and closed, from the default seed and around a centre.
TEST_P(BothEngines, SeveralHighValenceCentres) {
    for (const bool closed : {false, true})
        for (const uint32_t centres : {3u, 8u}) {
            const TriangleSoup s = make_many_centres(20000, centres, closed);
            const std::string what = "make_many_centres(20000, " + std::to_string(centres) + (closed ? ", closed)" : ", open)");
            StripOptions o;
            o.engine = GetParam();
            expect_verified(s, o, what);
            o.source = VertexId(static_cast<uint32_t>(s.points.size() - 2));  // a centre
            o.target = o.source;
            expect_verified(s, o, what + " source = target = a centre");
        }
}

// Valence 4097-4100: the old 4096-step fan walk answered "not connected" there.
TEST_P(BothEngines, ValenceJustAboveTheOldWalkCap) {
    for (const uint32_t k : {4097u, 4099u, 4100u})
        for (const bool capped : {false, true}) {
            StripOptions o;
            o.engine = GetParam();
            expect_verified(make_cone(k, capped), o, "make_cone(" + std::to_string(k) + (capped ? ", true)" : ", false)"));
        }
}

INSTANTIATE_TEST_SUITE_P(Engines, BothEngines, ::testing::Values(StripEngine::Matching, StripEngine::Growth),
                         [](const ::testing::TestParamInfo<StripEngine>& i) { return std::string(engine_name(i.param)); });

// validate_each_split also checks the O(1) cavity test (striped faces and rim per vertex)
// against a walk around the vertex at every test, and the mesh after every split.
TEST(GrowthCavityTest, AgreesWithTheWalkAroundTheVertex) {
    std::vector<std::pair<std::string, WalledMesh>> cases;
    cases.emplace_back("make_cone(2000, true)", WalledMesh{make_cone(2000, true), {}});
    cases.emplace_back("make_cone(2000, false)", WalledMesh{make_cone(2000, false), {}});
    cases.emplace_back("make_fan(2000)", WalledMesh{make_fan(2000), {}});
    cases.emplace_back("make_many_centres(4000, 8, closed)", WalledMesh{make_many_centres(4000, 8, true), {}});
    for (AwkwardFamily family : kAwkwardFamilies)
        cases.emplace_back(std::string(awkward_family_name(family)) + " at 600", make_awkward(family, 600));
    for (const auto& [name, m] : cases) {
        StripOptions o;
        o.engine = StripEngine::Growth;
        o.validate_each_split = true;
        o.constraint_edges = as_constraints(polyline_edges(m.walls));
        expect_verified(m.soup, o, name);
        TriangleSoup shuffled = m.soup;
        shuffle_faces(shuffled, 5);
        expect_verified(shuffled, o, name + " + shuffle_faces(5)");
    }
}

// The rim walks beside the bidirectional search (growth_classify.cpp) prove a face safe when the
// rim loops at its two ends differ; validate_each_split checks each such answer by a full search.
// Shapes whose regions keep many loops far apart: rows of holes, holes everywhere, genus, walls.
TEST(GrowthCavityTest, RimWalksAgreeWithTheFullSearch) {
    std::vector<std::pair<std::string, WalledMesh>> cases;
    cases.emplace_back("make_disk_with_holes(1000, 1)", WalledMesh{make_disk_with_holes(1000, 1), {}});
    cases.emplace_back("make_disk_with_holes(40, 3)", WalledMesh{make_disk_with_holes(40, 3), {}});
    cases.emplace_back("make_genus_surface(12, 3)", WalledMesh{make_genus_surface(12, 3), {}});
    for (AwkwardFamily family : {AwkwardFamily::ManyHoles, AwkwardFamily::HoleCorridors, AwkwardFamily::SerpentineWalls})
        cases.emplace_back(std::string(awkward_family_name(family)) + " at 6000", make_awkward(family, 6000));
    for (const auto& [name, m] : cases) {
        StripOptions o;
        o.engine = StripEngine::Growth;
        o.validate_each_split = true;
        o.constraint_edges = as_constraints(polyline_edges(m.walls));
        expect_verified(m.soup, o, name);
        const auto nv = static_cast<uint32_t>(m.soup.points.size());
        o.source = VertexId(nv / 3);
        o.target = VertexId(2 * nv / 3);
        expect_verified(m.soup, o, name + " source " + std::to_string(nv / 3) + " target " + std::to_string(2 * nv / 3));
    }
}

}  // namespace
