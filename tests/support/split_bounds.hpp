// singlestrip — tests: the least splits some meshes need, from their dual graph alone.
#pragma once

#include <cstdint>

#include "singlestrip/soup.hpp"

namespace singlestrip::testing {

/// The most edges one path of faces crosses when the dual graph of `s` (faces, joined across
/// edges of two faces) is a tree: its diameter, by two breadth-first searches. Any single strip
/// splits every other interior edge (+2 triangles each). \pre the dual graph is a tree. O(F log F).
uint32_t dual_tree_diameter(const TriangleSoup& s);

}  // namespace singlestrip::testing
