// singlestrip_bench — the "read" section (read_bench.cpp).
#pragma once

#include <string>

/// Writes generated meshes of 1M (and, unless `quick`, 10M) triangles in every input format to
/// `tmp`, times read_mesh_file on each, and returns a markdown table.
std::string read_section(const std::string& tmp, bool quick);
