// singlestrip bench — scaling-series meshes that the library generators cannot size finely.
#pragma once

#include <cstdint>
#include <string>

#include "singlestrip/soup.hpp"

namespace singlestrip::bench {

/// Geodesic sphere: every icosahedron face cut into n x n triangles (frequency-n subdivision),
/// points projected on the unit sphere. Unlike make_icosphere (F = 20*4^s) it reaches any size
/// near 20 n^2. \pre n >= 1. V = 10 n^2 + 2, F = 20 n^2, chi = 2, outward CCW faces. O(F).
TriangleSoup make_geodesic_sphere(uint32_t n);

/// Writes `soup` as a binary little-endian PLY ("property float x y z",
/// "property list uchar int vertex_indices": the common Stanford layout).
/// \throw OutputError on any I/O failure. O(V + F).
void write_binary_ply(const std::string& path, const TriangleSoup& soup);

}  // namespace singlestrip::bench
