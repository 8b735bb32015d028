// singlestrip — the few 3-vector operations on Point3 that the mesh core, writers and programs
// need (split midpoints, face normals, camera frames). The verifier keeps its own
// (src/verify/verify_checks.hpp).
#pragma once

#include <cmath>

#include "singlestrip/soup.hpp"

namespace singlestrip::vec3 {

inline Point3 sub(const Point3& a, const Point3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Point3 cross(const Point3& a, const Point3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dot(const Point3& a, const Point3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline double norm(const Point3& a) {
    return std::sqrt(dot(a, a));
}
/// a / |a|, or the zero vector when |a| is 0.
inline Point3 normalized(const Point3& a) {
    const double l = norm(a);
    return l > 0 ? Point3{a[0] / l, a[1] / l, a[2] / l} : Point3{0, 0, 0};
}

/// |a - b|; where the squares overflow (coordinates near +-1.7e308), again in halves with hypot
/// (which scales, but is too slow for every step of a long cycle or route).
inline double distance(const Point3& a, const Point3& b) {
    const double d = norm(sub(a, b));
    return std::isfinite(d) ? d : 2 * std::hypot(a[0] * 0.5 - b[0] * 0.5, a[1] * 0.5 - b[1] * 0.5, a[2] * 0.5 - b[2] * 0.5);
}

/// (a + b) / 2 without overflow: the halves are added only where the sum overflows (coordinates
/// beyond 8.9e307), so every other midpoint is the correctly rounded (a + b) / 2, bit for bit.
inline double mid(double a, double b) {
    const double s = a + b;
    return std::isfinite(s) ? s * 0.5 : a * 0.5 + b * 0.5;
}
inline Point3 midpoint(const Point3& a, const Point3& b) {
    return {mid(a[0], b[0]), mid(a[1], b[1]), mid(a[2], b[2])};
}
/// (a + b + c) / 3 without overflow, as mid().
inline double mean(double a, double b, double c) {
    const double s = a + b + c;
    return std::isfinite(s) ? s / 3 : a / 3 + b / 3 + c / 3;
}
inline Point3 centroid(const Point3& a, const Point3& b, const Point3& c) {
    return {mean(a[0], b[0], c[0]), mean(a[1], b[1], c[1]), mean(a[2], b[2], c[2])};
}

}  // namespace singlestrip::vec3
