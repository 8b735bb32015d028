// The attribute check of verify() (verify.hpp, "attributes"), in a file of its own: the
// verifier's own barycentric blend, sharing no code with attributes.hpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "singlestrip/verify.hpp"

namespace singlestrip::verify_detail {

/// Failure lines (without the "attributes: " prefix) and notes of the attribute check, for the
/// output faces' parents `parent` (0xffffffff where unknown: those vertices are skipped).
void check_attributes(const VerifyInput& in, const std::vector<uint32_t>& parent, std::vector<std::string>& failures,
                      std::vector<std::string>& notes);

}  // namespace singlestrip::verify_detail
