// singlestrip — internal: request checks, constraint edges and vertex queries shared by the two
// strip engines (src/algo/strip.cpp and growth_*.cpp, src/algo/strip_matching.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"

namespace singlestrip {

/// \throw InputError if the mesh has no faces; RequestError for a seed face, source or target out
/// of range or unused, or a seed face not incident to the source. O(1).
void check_strip_request(const Mesh& mesh, const StripOptions& options);

/// Per half-edge: 1 on the constraint edges (both half-edges). \throw RequestError naming the
/// first pair that is not an edge, or giving the pieces' sizes when the constraints cut the faces
/// apart. O(F + sum of the degrees of the constraint vertices).
std::vector<uint8_t> constraint_halfedges(const Mesh& mesh, const StripOptions& options);

/// The half-edge u->v or v->u, or kNone. O(degree of u), any degree.
uint32_t find_halfedge(const Mesh& mesh, uint32_t u, uint32_t v);

/// A face at vertex v with the most sides that are boundary or blocked; `avoid` only when no other
/// face exists. kNone if v has no face. O(degree of v).
uint32_t face_at_vertex(const Mesh& mesh, const std::vector<uint8_t>& blocked, uint32_t v, uint32_t avoid);

[[nodiscard]] inline bool face_has_vertex(const Mesh& mesh, uint32_t f, uint32_t v) {
    const auto& cv = mesh.corner_vertices();
    return cv[3 * f] == v || cv[3 * f + 1] == v || cv[3 * f + 2] == v;
}

/// Consecutive turns in the same direction along `order` (each costs one GL index).
/// \throw InternalError if two consecutive faces do not share an edge. O(order.size()).
uint32_t count_swaps(const Mesh& mesh, const std::vector<uint32_t>& order);

}  // namespace singlestrip
