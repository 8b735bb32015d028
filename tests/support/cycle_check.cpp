#include "cycle_check.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace singlestrip::testing {

void expect_closed_chains(const StripResult& r, const Cycles& c, const std::string& what) {
    ASSERT_EQ(c.cycles.size(), c.lengths.size()) << what;
    for (size_t i = 0; i < c.cycles.size(); ++i) {
        const auto& cyc = c.cycles[i];
        ASSERT_GE(cyc.size(), 2u) << what << " cycle " << i;
        std::vector<uint32_t> sorted = cyc;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << what << " cycle " << i << " repeats a face";
        for (size_t k = 0; k < cyc.size(); ++k) {
            ASSERT_LT(cyc[k], r.order.size()) << what;
            const uint32_t f = r.order[cyc[k]], g = r.order[cyc[(k + 1) % cyc.size()]];
            EXPECT_NE(r.mesh.shared_halfedge(FaceId(f), FaceId(g)).idx(), kNone) << what << " cycle " << i << " step " << k;
        }
        EXPECT_GT(c.lengths[i], 0.0) << what;
        EXPECT_TRUE(std::isfinite(c.lengths[i])) << what;
    }
}

}  // namespace singlestrip::testing
