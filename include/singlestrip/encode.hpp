// singlestrip — GL_TRIANGLE_STRIP index encoding of a face sequence.
#pragma once

#include <cstdint>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// Shortest GL_TRIANGLE_STRIP index sequence that decodes (standard rule: triangle i =
/// (s[i], s[i+1], s[i+2]), odd i with flipped winding, triangles with a repeated index skipped)
/// to exactly `faces`, in order, each with its winding. A swap is a repeated index.
/// \pre consecutive faces share an edge; each face has three distinct vertices.
/// \throw InternalError if the precondition is violated. Complexity O(n).
std::vector<uint32_t> encode_triangle_strip(const std::vector<Triangle>& faces);

/// Decodes a GL_TRIANGLE_STRIP index sequence (degenerate triangles skipped).
std::vector<Triangle> decode_triangle_strip(const std::vector<uint32_t>& indices);

/// Upper bound on encode_triangle_strip(faces).size(): 3 * faces.size() (meshoptimizer style).
inline size_t triangle_strip_bound(size_t face_count) { return face_count == 0 ? 0 : 3 * face_count; }

}  // namespace singlestrip
