// singlestrip — internal: request checks, constraint edges and vertex queries shared by the two
// strip engines (src/algo/strip.cpp and growth_*.cpp, src/algo/strip_matching.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "core/face_sides.hpp"
#include "core/id_vector.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"

namespace singlestrip {

/// A flag per half-edge (as the constraint edges).
using EdgeFlags = IdVector<HalfedgeId, uint8_t>;

/// \throw InputError if the mesh has no faces; RequestError for a seed face, source or target out
/// of range or unused, or a seed face not incident to the source. O(1).
void check_strip_request(const Mesh& mesh, const StripOptions& options);

/// Per half-edge: 1 on the constraint edges (both half-edges). \throw RequestError naming the
/// first pair that is not an edge, or giving the pieces' sizes when the constraints cut the faces
/// apart. O(F + sum of the degrees of the constraint vertices).
EdgeFlags constraint_halfedges(const Mesh& mesh, const StripOptions& options);

/// The half-edge u->v or v->u, or kNone (also for a vertex out of range). O(degree of u), any
/// degree.
HalfedgeId find_halfedge(const Mesh& mesh, VertexId u, VertexId v);

/// A face at vertex v with the most sides that are boundary or blocked; `avoid` only when no other
/// face exists. kNone if v has no face. O(degree of v).
FaceId face_at_vertex(const Mesh& mesh, const EdgeFlags& blocked, VertexId v, FaceId avoid);

[[nodiscard]] inline bool face_has_vertex(const Mesh& mesh, FaceId f, VertexId v) {
    const HalfedgeId h = Mesh::halfedge(f, 0);
    return mesh.from(h) == v || mesh.to(h) == v || mesh.opposite(h) == v;
}

/// Consecutive turns in the same direction along `order` (each costs one GL index).
/// \throw InternalError if two consecutive faces do not share an edge. O(order.size()).
uint32_t count_swaps(const Mesh& mesh, const std::vector<uint32_t>& order);

}  // namespace singlestrip
