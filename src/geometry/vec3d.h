// Double-precision 3-vectors for the few places where float rounding would put a computed point
// off the surface it belongs to (quadric intersection, spherical triangle sampling).
#pragma once

#include "core/transform.h"
#include "core/vecmath.h"

#include <cmath>

namespace caustica {

struct Vec3d {
    double x = 0, y = 0, z = 0;
    constexpr Vec3d() = default;
    constexpr Vec3d(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    explicit constexpr Vec3d(Vec3f v) : x(v.x), y(v.y), z(v.z) {}
    Vec3f to_float() const { return {float(x), float(y), float(z)}; }
    Vec3d operator+(Vec3d o) const { return {x + o.x, y + o.y, z + o.z}; }
    Vec3d operator-(Vec3d o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vec3d operator-() const { return {-x, -y, -z}; }
    Vec3d operator*(double s) const { return {x * s, y * s, z * s}; }
    Vec3d operator/(double s) const { return {x / s, y / s, z / s}; }
};
inline Vec3d operator*(double s, Vec3d v) { return v * s; }
inline double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3d cross(Vec3d a, Vec3d b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length_squared(Vec3d v) { return dot(v, v); }
inline double length(Vec3d v) { return std::sqrt(dot(v, v)); }
inline Vec3d normalize(Vec3d v) { return v / length(v); }

// Affine transforms applied in double; the projective row is ignored (shapes use affine maps).
inline Vec3d transform_point(const Matrix4 &m, Vec3d p) {
    const auto &a = m.m;
    return {a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z + a[0][3],
            a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z + a[1][3],
            a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z + a[2][3]};
}
inline Vec3d transform_vector(const Matrix4 &m, Vec3d v) {
    const auto &a = m.m;
    return {a[0][0] * v.x + a[0][1] * v.y + a[0][2] * v.z,
            a[1][0] * v.x + a[1][1] * v.y + a[1][2] * v.z,
            a[2][0] * v.x + a[2][1] * v.y + a[2][2] * v.z};
}
// Normals transform by the inverse transpose; m_inv is the inverse of the point transform.
inline Vec3d transform_normal(const Matrix4 &m_inv, Vec3d n) {
    const auto &a = m_inv.m;
    return {a[0][0] * n.x + a[1][0] * n.y + a[2][0] * n.z,
            a[0][1] * n.x + a[1][1] * n.y + a[2][1] * n.z,
            a[0][2] * n.x + a[1][2] * n.y + a[2][2] * n.z};
}

} // namespace caustica
