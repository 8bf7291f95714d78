#include "core/transform.h"

#include <stdexcept>

namespace caustica {

Matrix4 Matrix4::from_row_major(const float v[16]) {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = v[i * 4 + j];
    return r;
}

Matrix4 Matrix4::operator*(const Matrix4 &o) const {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += double(m[i][k]) * double(o.m[k][j]);
            r.m[i][j] = float(s);
        }
    return r;
}

Matrix4 Matrix4::transposed() const {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
    return r;
}

bool Matrix4::is_identity() const {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (m[i][j] != (i == j ? 1.f : 0.f)) return false;
    return true;
}

std::optional<Matrix4> inverse(const Matrix4 &mat) {
    // Gauss-Jordan elimination with partial pivoting, in double.
    double a[4][8];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            a[i][j] = mat.m[i][j];
            a[i][j + 4] = (i == j) ? 1 : 0;
        }
    double max_abs = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) max_abs = std::max(max_abs, std::abs(a[i][j]));
    if (!(max_abs > 0) || !std::isfinite(max_abs)) return std::nullopt;
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        if (std::abs(a[pivot][col]) < 1e-12 * max_abs) return std::nullopt;
        if (pivot != col)
            for (int j = 0; j < 8; ++j) std::swap(a[col][j], a[pivot][j]);
        double inv = 1 / a[col][col];
        for (int j = 0; j < 8; ++j) a[col][j] *= inv;
        for (int r = 0; r < 4; ++r) {
            if (r == col) continue;
            double f = a[r][col];
            if (f != 0)
                for (int j = 0; j < 8; ++j) a[r][j] -= f * a[col][j];
        }
    }
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = float(a[i][j + 4]);
    return r;
}

Transform::Transform(const Matrix4 &m) : m_(m) {
    auto inv = caustica::inverse(m);
    if (!inv) throw std::invalid_argument("transform matrix is not invertible");
    m_inv_ = *inv;
}

bool Transform::swaps_handedness() const {
    const auto &a = m_.m;
    double det = double(a[0][0]) * (double(a[1][1]) * a[2][2] - double(a[1][2]) * a[2][1]) -
                 double(a[0][1]) * (double(a[1][0]) * a[2][2] - double(a[1][2]) * a[2][0]) +
                 double(a[0][2]) * (double(a[1][0]) * a[2][1] - double(a[1][1]) * a[2][0]);
    return det < 0;
}

Vec3f Transform::apply_point(Vec3f p) const {
    const auto &a = m_.m;
    double x = double(a[0][0]) * p.x + double(a[0][1]) * p.y + double(a[0][2]) * p.z + a[0][3];
    double y = double(a[1][0]) * p.x + double(a[1][1]) * p.y + double(a[1][2]) * p.z + a[1][3];
    double z = double(a[2][0]) * p.x + double(a[2][1]) * p.y + double(a[2][2]) * p.z + a[2][3];
    double w = double(a[3][0]) * p.x + double(a[3][1]) * p.y + double(a[3][2]) * p.z + a[3][3];
    if (w == 1) return {float(x), float(y), float(z)};
    return {float(x / w), float(y / w), float(z / w)};
}

Vec3f Transform::apply_vector(Vec3f v) const {
    const auto &a = m_.m;
    return {float(double(a[0][0]) * v.x + double(a[0][1]) * v.y + double(a[0][2]) * v.z),
            float(double(a[1][0]) * v.x + double(a[1][1]) * v.y + double(a[1][2]) * v.z),
            float(double(a[2][0]) * v.x + double(a[2][1]) * v.y + double(a[2][2]) * v.z)};
}

Vec3f Transform::apply_normal(Vec3f n) const {
    const auto &a = m_inv_.m;
    return {float(double(a[0][0]) * n.x + double(a[1][0]) * n.y + double(a[2][0]) * n.z),
            float(double(a[0][1]) * n.x + double(a[1][1]) * n.y + double(a[2][1]) * n.z),
            float(double(a[0][2]) * n.x + double(a[1][2]) * n.y + double(a[2][2]) * n.z)};
}

Transform Transform::translate(Vec3f d) {
    Matrix4 m, mi;
    m.m[0][3] = d.x; m.m[1][3] = d.y; m.m[2][3] = d.z;
    mi.m[0][3] = -d.x; mi.m[1][3] = -d.y; mi.m[2][3] = -d.z;
    return {m, mi};
}

Transform Transform::scale(float x, float y, float z) {
    Matrix4 m, mi;
    m.m[0][0] = x; m.m[1][1] = y; m.m[2][2] = z;
    mi.m[0][0] = 1 / x; mi.m[1][1] = 1 / y; mi.m[2][2] = 1 / z;
    return {m, mi};
}

Transform Transform::rotate(float deg, Vec3f axis) {
    Vec3f a = normalize(axis);
    double theta = double(deg) * 3.14159265358979323846 / 180.0;
    double s = std::sin(theta), c = std::cos(theta);
    Matrix4 m;
    m.m[0][0] = float(a.x * a.x + (1 - a.x * a.x) * c);
    m.m[0][1] = float(a.x * a.y * (1 - c) - a.z * s);
    m.m[0][2] = float(a.x * a.z * (1 - c) + a.y * s);
    m.m[1][0] = float(a.x * a.y * (1 - c) + a.z * s);
    m.m[1][1] = float(a.y * a.y + (1 - a.y * a.y) * c);
    m.m[1][2] = float(a.y * a.z * (1 - c) - a.x * s);
    m.m[2][0] = float(a.x * a.z * (1 - c) - a.y * s);
    m.m[2][1] = float(a.y * a.z * (1 - c) + a.x * s);
    m.m[2][2] = float(a.z * a.z + (1 - a.z * a.z) * c);
    return {m, m.transposed()};
}

Transform Transform::look_at(Vec3f pos, Vec3f look, Vec3f up) {
    Vec3f dir = look - pos;
    if (length_squared(dir) == 0) throw std::invalid_argument("LookAt: eye and target coincide");
    dir = normalize(dir);
    if (length_squared(up) == 0) throw std::invalid_argument("LookAt: up vector is zero");
    Vec3f right = cross(normalize(up), dir);
    if (length(right) < 1e-6f)
        throw std::invalid_argument("LookAt: up vector and viewing direction are parallel");
    right = normalize(right);
    Vec3f new_up = cross(dir, right);
    Matrix4 world_from_camera;
    for (int i = 0; i < 3; ++i) {
        world_from_camera.m[i][0] = right[i];
        world_from_camera.m[i][1] = new_up[i];
        world_from_camera.m[i][2] = dir[i];
        world_from_camera.m[i][3] = pos[i];
    }
    Matrix4 camera_from_world = *caustica::inverse(world_from_camera);
    return {camera_from_world, world_from_camera};
}

Transform Transform::perspective(float fov, float n, float f) {
    Matrix4 persp;
    persp.m[2][2] = f / (f - n);
    persp.m[2][3] = -f * n / (f - n);
    persp.m[3][2] = 1;
    persp.m[3][3] = 0;
    float inv_tan = 1 / std::tan(radians(fov) / 2);
    return scale(inv_tan, inv_tan, 1) * Transform(persp);
}

} // namespace caustica
