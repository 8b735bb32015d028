#include "many_centres.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace singlestrip::testing {

namespace {

TriangleSoup centres_disk(uint32_t triangles, uint32_t centres) {
    const uint32_t per = std::max(3u, triangles / centres);
    const uint32_t rim = centres * per;
    TriangleSoup s;
    const double turn = 2 * std::numbers::pi / rim;
    for (uint32_t i = 0; i < rim; ++i) s.points.push_back({std::cos(turn * i), std::sin(turn * i), 0});
    for (uint32_t j = 0; j < centres; ++j) {
        const double a = turn * (j * per + per / 2.0);
        s.points.push_back({0.8 * std::cos(a), 0.8 * std::sin(a), 0});
    }
    const uint32_t origin = static_cast<uint32_t>(s.points.size());
    s.points.push_back({0, 0, 0});
    for (uint32_t j = 0; j < centres; ++j) {
        const uint32_t c = rim + j, c_next = rim + (j + 1) % centres;
        for (uint32_t i = j * per; i < (j + 1) * per; ++i) s.triangles.push_back({c, i, (i + 1) % rim});
        s.triangles.push_back({c, ((j + 1) * per) % rim, c_next});
        s.triangles.push_back({c, c_next, origin});
    }
    return s;
}

}  // namespace

TriangleSoup make_many_centres(uint32_t triangles, uint32_t centres, bool closed) {
    if (!closed) return centres_disk(triangles, centres);
    TriangleSoup s = centres_disk(triangles / 2, centres);
    const uint32_t nv = static_cast<uint32_t>(s.points.size()), nt = static_cast<uint32_t>(s.triangles.size());
    const uint32_t rim = nv - centres - 1;  // rim vertices are shared by both sides
    for (uint32_t i = rim; i < nv; ++i) {
        Point3 p = s.points[i];
        p[2] = -0.5;
        s.points.push_back(p);
        s.points[i][2] = 0.5;
    }
    const auto mirror = [&](uint32_t v) { return v < rim ? v : v + (nv - rim); };
    for (uint32_t t = 0; t < nt; ++t) {
        const Triangle tr = s.triangles[t];
        s.triangles.push_back({mirror(tr[0]), mirror(tr[2]), mirror(tr[1])});
    }
    return s;
}

}  // namespace singlestrip::testing
