// singlestrip — internal to the verifier's readers of OUTPUT files (verify_read.cpp: OBJ, OFF,
// index and cycle files, the helpers; verify_read_ply.cpp: PLY). Like them, independent of
// src/io/*: a writer's bug must not hide by being read back with the same code.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "singlestrip/verify.hpp"

namespace singlestrip::verify_read_detail {

/// \throw InputError "path: what".
[[noreturn]] void fail(const std::string& path, const std::string& what);
/// The whole file; fail()s when it cannot be opened or read.
std::string slurp(const std::string& path);
/// The whole token as a number (a leading '+' allowed); false otherwise.
bool parse_double(std::string_view tok, double& out);
bool parse_long(std::string_view tok, long long& out);
/// Whitespace-separated tokens.
std::vector<std::string_view> split_ws(std::string_view line);
/// Splits text into lines (handles \n and \r\n), keeping line numbers implicit by position.
std::vector<std::string_view> split_lines(std::string_view text);
/// The attribute called `name`, or nullptr.
const OutputAttribute* find_output_attribute(const std::vector<OutputAttribute>& attrs, const std::string& name);
/// fail()s on a non-finite coordinate of vertex v.
void check_point(const std::string& path, size_t v, const Point3& p);
/// fail()s on a face referencing a vertex the file does not have.
void check_indices(const std::string& path, const OutputMesh& m);

/// A PLY result (ASCII or binary, with its parent and attribute properties).
OutputMesh read_ply(const std::string& path);

}  // namespace singlestrip::verify_read_detail
