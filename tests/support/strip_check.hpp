// Test support: build a strip from a soup and check it with the independent verifier.
#pragma once

#include <string>

#include "singlestrip/soup.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/verify.hpp"

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
