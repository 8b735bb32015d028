// The strip's route as a polyline (route.hpp).
#include "singlestrip/route.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "singlestrip/errors.hpp"
#include "singlestrip/vec3.hpp"

namespace singlestrip {
namespace {

Point3 centroid(const StripArrays& a, uint32_t f) {
    const Triangle& t = a.faces[f];
    return vec3::centroid(a.points[t[0]], a.points[t[1]], a.points[t[2]]);
}

/// Midpoint of the edge faces f and g share; false when they share none (g starts the next
/// strip of an output with several components).
bool shared_midpoint(const StripArrays& a, uint32_t f, uint32_t g, Point3& mid) {
    uint32_t shared[3];
    int n = 0;
    for (uint32_t v : a.faces[f])
        if (std::find(a.faces[g].begin(), a.faces[g].end(), v) != a.faces[g].end() && n < 3) shared[n++] = v;
    if (n != 2) return false;
    mid = vec3::midpoint(a.points[shared[0]], a.points[shared[1]]);
    return true;
}

/// Every vertex of a face has the same z, up to 1e-9 of the mesh's extent (rounding in the
/// file's decimals must not turn a floor plan into a 3D surface).
bool faces_planar_in_z(const StripArrays& a) {
    if (a.faces.empty()) return false;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (const Triangle& t : a.faces)
        for (uint32_t v : t)
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], a.points[v][k]), hi[k] = std::max(hi[k], a.points[v][k]);
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    return hi[2] - lo[2] <= 1e-9 * extent;
}

}  // namespace

Route strip_route(const StripArrays& a) {
    if (a.parent.size() != a.faces.size()) throw InternalError("route: faces and parents differ in size");
    Route r;
    r.planar_z = faces_planar_in_z(a);
    const auto n = static_cast<uint32_t>(a.faces.size());
    r.points.reserve(n ? 2 * n - 1 : 0);
    bool jump = false;  // the next centroid starts a new strip: the move to it is off the surface
    auto add = [&](const Point3& p, uint32_t f, bool is_centroid) {
        if (!r.points.empty() && !jump) r.length += vec3::distance(r.points.back().position, p);
        r.points.push_back({p, f, a.parent[f], is_centroid, r.length, jump});
        jump = false;
    };
    for (uint32_t f = 0; f < n; ++f) {
        add(centroid(a, f), f, true);
        Point3 mid{};
        if (f + 1 < n && shared_midpoint(a, f, f + 1, mid))
            add(mid, f, false);
        else
            jump = f + 1 < n;
    }
    return r;
}

}  // namespace singlestrip
