// Affine and projective transforms as 4x4 matrices with their inverses (pbrt's conventions:
// left-handed LookAt, column vectors, Rotate by degrees about an axis).
#pragma once

#include "core/vecmath.h"

#include <optional>

namespace caustica {

struct Matrix4 {
    float m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    static Matrix4 from_row_major(const float v[16]);
    Matrix4 operator*(const Matrix4 &o) const;
    Matrix4 transposed() const;
    bool is_identity() const;
    bool operator==(const Matrix4 &) const = default;
};
// Inverse computed in double precision; empty when the matrix is singular.
std::optional<Matrix4> inverse(const Matrix4 &m);

class Transform {
  public:
    Transform() = default;
    Transform(const Matrix4 &m, const Matrix4 &m_inv) : m_(m), m_inv_(m_inv) {}
    // Throws std::invalid_argument if m is not invertible.
    explicit Transform(const Matrix4 &m);

    const Matrix4 &matrix() const { return m_; }
    const Matrix4 &inverse_matrix() const { return m_inv_; }
    Transform inverse() const { return {m_inv_, m_}; }
    Transform operator*(const Transform &o) const { return {m_ * o.m_, o.m_inv_ * m_inv_}; }
    bool is_identity() const { return m_.is_identity(); }
    bool swaps_handedness() const;
    bool operator==(const Transform &) const = default;

    Vec3f apply_point(Vec3f p) const;
    Vec3f apply_vector(Vec3f v) const;
    // Normals transform by the inverse transpose so they stay perpendicular to surfaces.
    Vec3f apply_normal(Vec3f n) const;

    static Transform translate(Vec3f d);
    static Transform scale(float x, float y, float z);
    static Transform rotate(float degrees, Vec3f axis);
    // World-from-camera is the inverse of this (pbrt's LookAt returns camera-from-world).
    static Transform look_at(Vec3f pos, Vec3f look, Vec3f up);
    static Transform perspective(float fov_degrees, float near_z, float far_z);

  private:
    Matrix4 m_, m_inv_;
};

} // namespace caustica
