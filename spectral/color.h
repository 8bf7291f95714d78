// Colour triples: CIE XYZ tristimulus values, RGB in some colour space, xy chromaticities, and
// the 3x3 matrices that convert between them.
#pragma once

#include <algorithm>
#include <array>

namespace caustica {

struct Chromaticity {
    float x = 0, y = 0;
};

struct XYZ {
    float x = 0, y = 0, z = 0;

    // The XYZ of chromaticity xy at luminance Y.
    static XYZ from_xy(Chromaticity xy, float luminance = 1) {
        if (xy.y == 0) return {};
        return {xy.x * luminance / xy.y, luminance, (1 - xy.x - xy.y) * luminance / xy.y};
    }
    Chromaticity xy() const {
        float sum = x + y + z;
        return sum == 0 ? Chromaticity{} : Chromaticity{x / sum, y / sum};
    }
    XYZ operator+(const XYZ &o) const { return {x + o.x, y + o.y, z + o.z}; }
    XYZ operator*(float s) const { return {x * s, y * s, z * s}; }
    XYZ operator/(float s) const { return {x / s, y / s, z / s}; }
    bool operator==(const XYZ &) const = default;
};

struct RGB {
    float r = 0, g = 0, b = 0;

    float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    float &operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }
    RGB operator+(const RGB &o) const { return {r + o.r, g + o.g, b + o.b}; }
    RGB operator-(const RGB &o) const { return {r - o.r, g - o.g, b - o.b}; }
    RGB operator*(const RGB &o) const { return {r * o.r, g * o.g, b * o.b}; }
    RGB operator/(const RGB &o) const { return {r / o.r, g / o.g, b / o.b}; }
    RGB operator*(float s) const { return {r * s, g * s, b * s}; }
    RGB operator/(float s) const { return {r / s, g / s, b / s}; }
    RGB &operator+=(const RGB &o) { return *this = *this + o; }
    RGB &operator*=(float s) { return *this = *this * s; }
    bool operator==(const RGB &) const = default;
    float max_component() const { return std::max(r, std::max(g, b)); }
    float min_component() const { return std::min(r, std::min(g, b)); }
    float average() const { return (r + g + b) / 3; }
};
inline RGB operator*(float s, const RGB &c) { return c * s; }
inline RGB clamp_zero(const RGB &c) {
    return {std::max(0.f, c.r), std::max(0.f, c.g), std::max(0.f, c.b)};
}

// IEC 61966-2-1 sRGB decoding of one 8-bit-style value in [0, 1] to linear.
float srgb_to_linear(float v);

// Row-major 3x3 matrix acting on column vectors.
struct Matrix3 {
    std::array<std::array<float, 3>, 3> m{};

    static Matrix3 identity() { return {{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}; }
    static Matrix3 diagonal(float a, float b, float c) {
        return {{{{a, 0, 0}, {0, b, 0}, {0, 0, c}}}};
    }
    const std::array<float, 3> &operator[](int row) const { return m[row]; }
    std::array<float, 3> &operator[](int row) { return m[row]; }

    std::array<float, 3> apply(float a, float b, float c) const {
        return {m[0][0] * a + m[0][1] * b + m[0][2] * c, m[1][0] * a + m[1][1] * b + m[1][2] * c,
                m[2][0] * a + m[2][1] * b + m[2][2] * c};
    }
    Matrix3 operator*(const Matrix3 &o) const {
        Matrix3 r;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
        return r;
    }
    // Inverse by the adjugate, in double for the ill-conditioned matrices of wide gamuts.
    // A singular matrix (degenerate primaries) gives the zero matrix.
    Matrix3 inverse() const {
        auto e = [&](int i, int j) { return double(m[i][j]); };
        double c00 = e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1);
        double c01 = e(1, 2) * e(2, 0) - e(1, 0) * e(2, 2);
        double c02 = e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0);
        double det = e(0, 0) * c00 + e(0, 1) * c01 + e(0, 2) * c02;
        if (det == 0) return {};
        double inv = 1 / det;
        Matrix3 r;
        r.m[0] = {float(c00 * inv), float((e(0, 2) * e(2, 1) - e(0, 1) * e(2, 2)) * inv),
                  float((e(0, 1) * e(1, 2) - e(0, 2) * e(1, 1)) * inv)};
        r.m[1] = {float(c01 * inv), float((e(0, 0) * e(2, 2) - e(0, 2) * e(2, 0)) * inv),
                  float((e(0, 2) * e(1, 0) - e(0, 0) * e(1, 2)) * inv)};
        r.m[2] = {float(c02 * inv), float((e(0, 1) * e(2, 0) - e(0, 0) * e(2, 1)) * inv),
                  float((e(0, 0) * e(1, 1) - e(0, 1) * e(1, 0)) * inv)};
        return r;
    }
};

inline XYZ operator*(const Matrix3 &m, const XYZ &v) {
    auto r = m.apply(v.x, v.y, v.z);
    return {r[0], r[1], r[2]};
}
inline RGB operator*(const Matrix3 &m, const RGB &v) {
    auto r = m.apply(v.r, v.g, v.b);
    return {r[0], r[1], r[2]};
}

// The matrix taking linear RGB to XYZ for primaries r, g, b whose white (1, 1, 1) is `white`:
// the columns are the primaries' XYZ at unit luminance, each scaled so that they sum to white.
inline Matrix3 rgb_to_xyz_matrix(Chromaticity r, Chromaticity g, Chromaticity b, XYZ white) {
    XYZ pr = XYZ::from_xy(r), pg = XYZ::from_xy(g), pb = XYZ::from_xy(b);
    Matrix3 primaries{{{{pr.x, pg.x, pb.x}, {pr.y, pg.y, pb.y}, {pr.z, pg.z, pb.z}}}};
    XYZ scale = primaries.inverse() * white;
    return primaries * Matrix3::diagonal(scale.x, scale.y, scale.z);
}

} // namespace caustica
