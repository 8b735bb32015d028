// singlestrip — GL_TRIANGLE_STRIP index encoding of a face sequence.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// Shortest GL_TRIANGLE_STRIP index sequence that decodes (standard rule: triangle i =
/// (s[i], s[i+1], s[i+2]), odd i with flipped winding, triangles with a repeated index skipped)
/// to exactly `faces`, in order, each with its winding. A swap is a repeated index.
/// \pre consecutive faces share an edge; each face has three distinct vertices.
/// \throw InternalError if the precondition is violated. Complexity O(n).
std::vector<uint32_t> encode_triangle_strip(std::span<const Triangle> faces);
inline std::vector<uint32_t> encode_triangle_strip(const std::vector<Triangle>& faces) {
    return encode_triangle_strip(std::span<const Triangle>(faces));
}
inline std::vector<uint32_t> encode_triangle_strip(std::initializer_list<Triangle> faces) {
    return encode_triangle_strip(std::span<const Triangle>(faces.begin(), faces.size()));
}

/// Decodes a GL_TRIANGLE_STRIP index sequence (degenerate triangles skipped). With `restart`,
/// that value ends a strip and the next index starts a new one at even parity (primitive
/// restart). Complexity O(n).
std::vector<Triangle> decode_triangle_strip(const std::vector<uint32_t>& indices, std::optional<uint32_t> restart = std::nullopt);

/// How several strips (one per edge-connected component) share one index sequence.
enum class JoinMode : uint8_t {
    /// Degenerate triangles: after strip A, A's last index and B's first index are repeated
    /// (B's first twice when A has odd length, so B starts at even parity). Every triangle across
    /// the join repeats an index, so any GL_TRIANGLE_STRIP decoder skips it; no primitive restart
    /// needed (glTF core has none).
    Degenerate,
    /// A restart index between strips (GL primitive restart; 0xFFFFFFFF by default).
    Restart,
};

/// "degenerate" / "restart"; parse_join_mode() returns std::nullopt for anything else.
const char* join_mode_name(JoinMode mode) noexcept;
std::optional<JoinMode> parse_join_mode(std::string_view name) noexcept;

/// The strips joined as described at JoinMode; one strip is returned unchanged.
/// \pre no strip is empty. Complexity O(total length).
std::vector<uint32_t> join_strips(const std::vector<std::vector<uint32_t>>& strips, JoinMode mode, uint32_t restart = 0xffffffffu);

/// Upper bound on encode_triangle_strip(faces).size(): 3 * faces.size() (meshoptimizer style).
inline size_t triangle_strip_bound(size_t face_count) {
    return face_count == 0 ? 0 : 3 * face_count;
}

/// Upper bound on join_strips() of `strips` strips holding `face_count` faces in all: each strip
/// within its own bound, plus at most 3 indices per join.
inline size_t joined_strip_bound(size_t face_count, size_t strips) {
    return triangle_strip_bound(face_count) + (strips > 1 ? 3 * (strips - 1) : 0);
}

}  // namespace singlestrip
