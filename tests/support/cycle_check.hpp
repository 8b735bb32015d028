// Test support: the shape every set of cycles must have, whichever way it was computed.
#pragma once

#include <string>

#include "singlestrip/soup.hpp"
#include "singlestrip/strip.hpp"

namespace singlestrip::testing {

/// Every cycle of `c` is a closed chain of at least two edge-adjacent faces of r's output with no
/// face twice, with a positive finite length (gtest failures name `what`). Sources are not
/// required (tree_cotree_cycles() gives none).
void expect_closed_chains(const StripResult& r, const Cycles& c, const std::string& what);

}  // namespace singlestrip::testing
