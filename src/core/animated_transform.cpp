#include "core/animated_transform.h"

#include <cmath>

namespace caustica {

AffineFactors factor_affine(const Matrix4 &m) {
    const Vec3f c0{m.m[0][0], m.m[1][0], m.m[2][0]}, c1{m.m[0][1], m.m[1][1], m.m[2][1]},
        c2{m.m[0][2], m.m[1][2], m.m[2][2]};
    AffineFactors f;
    f.translation = {m.m[0][3], m.m[1][3], m.m[2][3]};
    f.s00 = length(c0);
    const Vec3f q0 = c0 / f.s00;
    f.s01 = dot(q0, c1);
    const Vec3f u1 = c1 - q0 * f.s01;
    f.s11 = length(u1);
    const Vec3f q1 = u1 / f.s11;
    f.s02 = dot(q0, c2);
    f.s12 = dot(q1, c2);
    const Vec3f u2 = c2 - q0 * f.s02 - q1 * f.s12;
    f.s22 = length(u2);
    Vec3f q2 = u2 / f.s22;
    if (dot(cross(q0, q1), q2) < 0) {
        q2 = -q2;
        f.s22 = -f.s22;
    }
    // The quaternion of the rotation with columns q0, q1, q2, from the largest of its four
    // components for accuracy.
    const float r[3][3] = {{q0.x, q1.x, q2.x}, {q0.y, q1.y, q2.y}, {q0.z, q1.z, q2.z}};
    const float trace = r[0][0] + r[1][1] + r[2][2];
    if (trace > 0) {
        const float s = 2 * std::sqrt(trace + 1);
        f.w = s / 4, f.x = (r[2][1] - r[1][2]) / s, f.y = (r[0][2] - r[2][0]) / s, f.z = (r[1][0] - r[0][1]) / s;
    } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
        const float s = 2 * std::sqrt(1 + r[0][0] - r[1][1] - r[2][2]);
        f.w = (r[2][1] - r[1][2]) / s, f.x = s / 4, f.y = (r[0][1] + r[1][0]) / s, f.z = (r[0][2] + r[2][0]) / s;
    } else if (r[1][1] > r[2][2]) {
        const float s = 2 * std::sqrt(1 + r[1][1] - r[0][0] - r[2][2]);
        f.w = (r[0][2] - r[2][0]) / s, f.x = (r[0][1] + r[1][0]) / s, f.y = s / 4, f.z = (r[1][2] + r[2][1]) / s;
    } else {
        const float s = 2 * std::sqrt(1 + r[2][2] - r[0][0] - r[1][1]);
        f.w = (r[1][0] - r[0][1]) / s, f.x = (r[0][2] + r[2][0]) / s, f.y = (r[1][2] + r[2][1]) / s, f.z = s / 4;
    }
    return f;
}

Matrix4 compose(const AffineFactors &f) {
    const float w = f.w, x = f.x, y = f.y, z = f.z;
    const float r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    const float s[3][3] = {{f.s00, f.s01, f.s02}, {0, f.s11, f.s12}, {0, 0, f.s22}};
    Matrix4 m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m.m[i][j] = r[i][0] * s[0][j] + r[i][1] * s[1][j] + r[i][2] * s[2][j];
    m.m[0][3] = f.translation.x;
    m.m[1][3] = f.translation.y;
    m.m[2][3] = f.translation.z;
    return m;
}

Transform AnimatedTransform::at(float u) const {
    if (!is_animated() || u <= 0) return start;
    if (u >= 1) return end;
    return interpolate(factor_affine(start.matrix()), factor_affine(end.matrix()), u);
}

Transform interpolate(const AffineFactors &a, const AffineFactors &b, float u) {
    auto lerp = [u](float p, float q) { return (1 - u) * p + u * q; };
    AffineFactors f;
    f.translation = a.translation * (1 - u) + b.translation * u;
    f.s00 = lerp(a.s00, b.s00), f.s01 = lerp(a.s01, b.s01), f.s02 = lerp(a.s02, b.s02);
    f.s11 = lerp(a.s11, b.s11), f.s12 = lerp(a.s12, b.s12), f.s22 = lerp(a.s22, b.s22);
    // Slerp along the shorter arc (q and -q are one rotation).
    float cos_theta = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
    const float sign = cos_theta < 0 ? -1.f : 1.f;
    cos_theta *= sign;
    float wa = 1 - u, wb = u;
    if (cos_theta < 0.9995f) {
        const float theta = std::acos(cos_theta), sin_theta = std::sin(theta);
        wa = std::sin((1 - u) * theta) / sin_theta;
        wb = std::sin(u * theta) / sin_theta;
    }
    wb *= sign;
    f.w = wa * a.w + wb * b.w, f.x = wa * a.x + wb * b.x, f.y = wa * a.y + wb * b.y, f.z = wa * a.z + wb * b.z;
    const float norm = std::sqrt(f.w * f.w + f.x * f.x + f.y * f.y + f.z * f.z);
    f.w /= norm, f.x /= norm, f.y /= norm, f.z /= norm;
    const Matrix4 m = compose(f);
    return Transform(m, *inverse(m));
}

} // namespace caustica
