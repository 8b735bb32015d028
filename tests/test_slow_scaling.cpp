// singlestrip — large inputs (10^5 and 10^6 faces), label `slow`: built and registered only with
// -DSINGLESTRIP_SLOW_TESTS=ON, run with `ctest -L slow` (a few minutes on two cores). Issue 17:
// one vertex of valence up to 10^6, several high-valence centres, and every awkward family, both
// engines, each strip verified. Times per triangle are printed, not asserted (scripts/bench
// measures them).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "fixtures.hpp"
#include "many_centres.hpp"
#include "singlestrip/strip.hpp"
#include "strip_check.hpp"

namespace {

using namespace singlestrip;
using singlestrip::testing::make_many_centres;

void expect_verified(const TriangleSoup& soup, StripOptions o, const std::string& what) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
        const auto c = singlestrip::testing::strip_and_verify(soup, o);
        EXPECT_TRUE(c.report.ok()) << what << "\n" << singlestrip::testing::describe(c);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("[%s] %s: %zu faces, +%u splits, %.0f ns/face (strip and verify)\n", engine_name(o.engine), what.c_str(),
                    soup.triangles.size(), c.result.stats.splits, s / static_cast<double>(soup.triangles.size()) * 1e9);
    } catch (const std::exception& e) {
        ADD_FAILURE() << what << " threw: " << e.what();
    }
}

class Slow : public ::testing::TestWithParam<StripEngine> {
protected:
    StripOptions opts() const {
        StripOptions o;
        o.engine = GetParam();
        return o;
    }
};

// One vertex of valence 10^4 .. 10^6: open cone, closed cone (about 4k faces), open fan.
TEST_P(Slow, OneVertexOfValenceUpToAMillion) {
    for (const uint32_t k : {10000u, 100000u, 1000000u}) {
        expect_verified(make_cone(k, false), opts(), "make_cone(" + std::to_string(k) + ", false)");
        expect_verified(make_fan(k), opts(), "make_fan(" + std::to_string(k) + ")");
        expect_verified(make_cone(k / 4, true), opts(), "make_cone(" + std::to_string(k / 4) + ", true)");
    }
    StripOptions o = opts();
    o.source = VertexId(0);  // the apex
    o.target = VertexId(0);
    expect_verified(make_cone(250000, true), o, "make_cone(250000, true) source = target = apex");
}

TEST_P(Slow, SeveralHighValenceCentres) {
    for (const uint32_t n : {100000u, 1000000u})
        for (const bool closed : {false, true})
            expect_verified(make_many_centres(n, 8, closed), opts(),
                            "make_many_centres(" + std::to_string(n) + ", 8" + (closed ? ", closed)" : ", open)"));
}

TEST_P(Slow, AwkwardFamilies) {
    for (AwkwardFamily family : kAwkwardFamilies)
        for (const uint32_t n : {100000u, 1000000u}) {
            const WalledMesh m = make_awkward(family, n);
            StripOptions o = opts();
            o.constraint_edges = as_constraints(polyline_edges(m.walls));
            expect_verified(m.soup, o, std::string(awkward_family_name(family)) + " at " + std::to_string(n));
        }
}

INSTANTIATE_TEST_SUITE_P(Engines, Slow, ::testing::Values(StripEngine::Matching, StripEngine::Growth),
                         [](const ::testing::TestParamInfo<StripEngine>& i) { return std::string(engine_name(i.param)); });

}  // namespace
