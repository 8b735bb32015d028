// singlestrip — faces reordered along a Z-order (Morton) curve of their centroids, for inputs
// whose face order has no locality (e.g. shuffled): the strip engines walk from a face to its
// neighbours, and on a 1M-triangle shuffled torus every such step missed the cache (matching
// strip stage 6.9 s against 0.9 s in this order; docs/benchmarks.md, "Face order").
#pragma once

#include <cstdint>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// Faces of `triangles` by the Morton code of their centroids on a 1024^3 grid over the
/// points' bounding box, ties in face order: result[i] = the face that goes to position i.
/// \pre every vertex index is < points.size(). Non-finite coordinates count as the box's low
/// corner. Three counting-sort passes: O(F), 20 bytes a face of scratch.
std::vector<uint32_t> spatial_face_order(const std::vector<Point3>& points, const std::vector<Triangle>& triangles);

/// The order to strip a large soup in when its face order has no locality, else empty. A soup
/// is judged by its consecutive faces: in a file written by sweeping its surface their lowest
/// vertices are close in number, in a shuffled one they are not. Empty below 2^18 faces (the
/// engines' per-face arrays then stay in cache) or when a vertex index is out of range. O(F).
std::vector<uint32_t> locality_order(const TriangleSoup& soup);

/// For a soup already in locality_order(): when its consecutive faces still lie far apart in
/// vertex numbers (a file whose vertices were shuffled), its vertices numbered by first use
/// along the faces, unused ones last: result[i] = the vertex that becomes vertex i. Else empty.
/// Adjacency is found by sorting on vertex numbers, which then stay local. O(V + F).
std::vector<uint32_t> locality_vertex_order(const TriangleSoup& soup);

/// p's inverse: result[p[i]] = i. \pre p is a permutation of 0 .. p.size() - 1. O(n).
std::vector<uint32_t> inverse_permutation(const std::vector<uint32_t>& p);

/// Renumbers the soup's vertices (points, attribute values, triangles): vertex origin[i] becomes
/// i, or with `back` i becomes origin[i] again. \pre origin is a permutation of the vertices.
/// O(V + F).
void permute_vertices(TriangleSoup& soup, const std::vector<uint32_t>& origin, bool back);

}  // namespace singlestrip
