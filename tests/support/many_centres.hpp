// singlestrip tests — surfaces whose triangles lie around a few high-valence centres (issue 17).
#pragma once

#include <cstdint>

#include "singlestrip/soup.hpp"

namespace singlestrip::testing {

/// A planar disk of about `triangles` faces around `centres` vertices of high valence: a rim of
/// centres * per vertices on the unit circle (per = triangles / centres), centre j (radius 0.8)
/// fanned to its arc of per rim edges, one triangle closing each gap between neighbouring fans,
/// and the inner polygon of the centres fanned from the origin. Closed: the disk and its mirror
/// image (z = +0.5 / -0.5 centres) glued along the rim, about `triangles` faces around 2 * centres
/// centres, genus 0. \pre centres >= 3.
TriangleSoup make_many_centres(uint32_t triangles, uint32_t centres, bool closed);

}  // namespace singlestrip::testing
