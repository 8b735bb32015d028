// Test support: build a strip from a soup and check it with the independent verifier; suites
// run once per engine.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "singlestrip/soup.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/verify.hpp"

namespace singlestrip {

/// Suites over both engines: `class S : public EngineTest {};` then
/// INSTANTIATE_TEST_SUITE_P(Engines, S, kBothEngines, engine_test_name); opts() gives default
/// options on the engine under test.
class EngineTest : public ::testing::TestWithParam<StripEngine> {
protected:
    StripOptions opts() const {
        StripOptions o;
        o.engine = GetParam();
        return o;
    }
};

inline const auto kBothEngines = ::testing::Values(StripEngine::Matching, StripEngine::Growth);

/// "matching" or "growth": the suffix of each parameterised test's name.
std::string engine_test_name(const ::testing::TestParamInfo<StripEngine>& info);

}  // namespace singlestrip

namespace singlestrip::testing {

struct StripCheck {
    StripResult result;
    StripArrays arrays;
    std::vector<uint32_t> indices;
    VerifyReport report;
};

/// stripify() (pipeline.hpp, with its self checks) on `soup` with `options`, then verify() with
/// the indices, the options' constraints and source/target. Exceptions propagate.
StripCheck strip_and_verify(const TriangleSoup& soup, const StripOptions& options = {});

/// One-line description of a result, for failure messages.
std::string describe(const StripCheck& check);

}  // namespace singlestrip::testing
