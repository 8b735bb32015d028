// Test support: the verifier's test cases shared by tests/test_verify*.cpp: report helpers and
// two hand-made outputs (a quad, and the quad with its diagonal split).
#pragma once

#include <string>

#include "singlestrip/verify.hpp"

namespace singlestrip::testing {

/// Failure lines, then notes (prefixed "note: "), one a line: for assertion messages.
std::string joined(const VerifyReport& r);

/// True when some failure line starts with `check` + ":" (and contains `needle`, if given).
bool has_failure(const VerifyReport& r, const std::string& check, const std::string& needle = "");

bool has_failure_prefix(const VerifyReport& r, const std::string& check);

/// Unit square 0(0,0) 1(1,0) 2(1,1) 3(0,1), two CCW triangles sharing the diagonal 0-2.
VerifyInput quad();

/// The quad with the diagonal split at its midpoint 4, four faces in strip order.
VerifyInput split_quad();

}  // namespace singlestrip::testing
