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

/// The attributes of the strip primitive of a glTF OUT (`strip in.obj -o out.glb`) into
/// vi.out_attributes, under the input's names (a custom "_NAME" is the input's `name`), with
/// float32 tolerance; the input's NORMAL is compared normalised (glTF holds unit normals; a
/// note says so). \throw InputError naming the file when it cannot be read.
void read_gltf_strip_attributes(const std::string& path, VerifyInput& vi, std::vector<std::string>& notes);

}  // namespace singlestrip::verify_detail
