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
/// corner. Two counting-sort passes: O(F), 16 bytes a face of scratch.
std::vector<uint32_t> spatial_face_order(const std::vector<Point3>& points, const std::vector<Triangle>& triangles);

/// Share of the interior edges (twin[h] != kNone, h = 3f + k) whose two faces are at least
/// `distance` apart in face order: near 1 for a shuffled soup, near 0 for a file written by
/// sweeping its surface. O(F).
double far_neighbour_share(const std::vector<uint32_t>& twin, uint32_t distance);

}  // namespace singlestrip
