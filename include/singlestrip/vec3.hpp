// singlestrip — the few 3-vector operations on Point3 that writers and programs need (face
// normals, camera frames). The verifier keeps its own (src/verify/verify.cpp).
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

}  // namespace singlestrip::vec3
