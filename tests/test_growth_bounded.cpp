// singlestrip — the bounded growth builder, the matching engine's candidate after parity splits
// (growth::build_strip_growth_bounded, docs/algorithm.md step 9).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "algo/growth_builder.hpp"
#include "fixtures.hpp"
#include "singlestrip/strip.hpp"

namespace {

using namespace singlestrip;

// The bounded growth builder (the matching engine's candidate after parity splits): the same
// strip as the plain one while its deferred islands stay within the bound, an empty result once
// they pass it.
TEST(GrowthBounded, SameStripWithinTheBoundNoneBeyond) {
    for (AwkwardFamily family : {AwkwardFamily::ManyHoles, AwkwardFamily::SpikedComb, AwkwardFamily::SparseHoles}) {
        const WalledMesh m = make_awkward(family, 3000);
        const std::string what = awkward_family_name(family);
        StripOptions o;
        o.engine = StripEngine::Growth;
        const StripResult plain = build_strip_growth(Mesh::from_soup(m.soup), o);
        const uint32_t deferred = plain.stats.deferred_regions;
        ASSERT_GT(deferred, 0u) << what;
        const StripResult within = growth::build_strip_growth_bounded(Mesh::from_soup(m.soup), o, deferred);
        EXPECT_EQ(within.order, plain.order) << what;
        EXPECT_EQ(within.stats.splits, plain.stats.splits) << what;
        const StripResult beyond = growth::build_strip_growth_bounded(Mesh::from_soup(m.soup), o, deferred - 1);
        EXPECT_TRUE(beyond.order.empty()) << what;
    }
}

}  // namespace
