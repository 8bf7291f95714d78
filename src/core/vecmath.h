// Small geometric value types. Points, vectors and normals share Vec3f: the renderer keeps them
// apart by naming, and transforms provide separate apply_point / apply_vector / apply_normal.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace caustica {

inline constexpr float Pi = 3.14159265358979323846f;
inline constexpr float InvPi = 0.31830988618379067154f;
inline constexpr float Inv2Pi = 0.15915494309189533577f;
inline constexpr float Inv4Pi = 0.07957747154594766788f;
inline constexpr float PiOver2 = 1.57079632679489661923f;
inline constexpr float PiOver4 = 0.78539816339744830961f;
inline constexpr float Infinity = std::numeric_limits<float>::infinity();
// Largest float strictly below 1: uniform samples live in [0, OneMinusEpsilon].
inline constexpr float OneMinusEpsilon = 0x1.fffffep-1f;

template <typename T> constexpr T sqr(T v) { return v * v; }
template <typename T> constexpr T clamp(T v, T lo, T hi) { return v < lo ? lo : (v > hi ? hi : v); }
inline float lerp(float t, float a, float b) { return (1 - t) * a + t * b; }
inline float safe_sqrt(float x) { return std::sqrt(std::max(0.f, x)); }
inline float safe_asin(float x) { return std::asin(clamp(x, -1.f, 1.f)); }
inline float safe_acos(float x) { return std::acos(clamp(x, -1.f, 1.f)); }
inline float radians(float degrees) { return degrees * (Pi / 180.f); }
inline float degrees(float rad) { return rad * (180.f / Pi); }

struct Vec2f {
    float x = 0, y = 0;
    constexpr Vec2f() = default;
    constexpr Vec2f(float x_, float y_) : x(x_), y(y_) {}
    float operator[](int i) const { return i == 0 ? x : y; }
    float &operator[](int i) { return i == 0 ? x : y; }
    Vec2f operator+(Vec2f o) const { return {x + o.x, y + o.y}; }
    Vec2f operator-(Vec2f o) const { return {x - o.x, y - o.y}; }
    Vec2f operator*(float s) const { return {x * s, y * s}; }
    Vec2f operator/(float s) const { return {x / s, y / s}; }
};
inline Vec2f operator*(float s, Vec2f v) { return v * s; }

struct Vec2i {
    int x = 0, y = 0;
    bool operator==(const Vec2i &) const = default;
};

struct Vec3f {
    float x = 0, y = 0, z = 0;
    constexpr Vec3f() = default;
    constexpr Vec3f(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    float &operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    Vec3f operator+(Vec3f o) const { return {x + o.x, y + o.y, z + o.z}; }
    Vec3f operator-(Vec3f o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vec3f operator-() const { return {-x, -y, -z}; }
    Vec3f operator*(float s) const { return {x * s, y * s, z * s}; }
    Vec3f operator/(float s) const { float inv = 1 / s; return {x * inv, y * inv, z * inv}; }
    Vec3f &operator+=(Vec3f o) { x += o.x; y += o.y; z += o.z; return *this; }
    Vec3f &operator-=(Vec3f o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    Vec3f &operator*=(float s) { x *= s; y *= s; z *= s; return *this; }
    bool operator==(const Vec3f &) const = default;
};
inline Vec3f operator*(float s, Vec3f v) { return v * s; }
inline Vec3f mul(Vec3f a, Vec3f b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline float dot(Vec3f a, Vec3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline float abs_dot(Vec3f a, Vec3f b) { return std::abs(dot(a, b)); }
inline Vec3f cross(Vec3f a, Vec3f b) {
    // Evaluated in double so that nearly parallel inputs keep their tiny but meaningful result.
    double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
    return {float(ay * bz - az * by), float(az * bx - ax * bz), float(ax * by - ay * bx)};
}
inline float length_squared(Vec3f v) { return dot(v, v); }
inline float length(Vec3f v) { return std::sqrt(dot(v, v)); }
inline Vec3f normalize(Vec3f v) { return v / length(v); }
inline float distance(Vec3f a, Vec3f b) { return length(a - b); }
inline float distance_squared(Vec3f a, Vec3f b) { return length_squared(a - b); }
inline Vec3f abs(Vec3f v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }
inline Vec3f min(Vec3f a, Vec3f b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
inline Vec3f max(Vec3f a, Vec3f b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
inline float max_component(Vec3f v) { return std::max(v.x, std::max(v.y, v.z)); }
inline float min_component(Vec3f v) { return std::min(v.x, std::min(v.y, v.z)); }
inline int max_dimension(Vec3f v) { return v.x > v.y ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2); }
inline Vec3f face_forward(Vec3f n, Vec3f v) { return dot(n, v) < 0 ? -n : n; }
inline bool is_finite(Vec3f v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Builds two unit vectors completing an orthonormal basis with unit vector v
// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
inline void coordinate_system(Vec3f v, Vec3f *a, Vec3f *b) {
    float sign = std::copysign(1.f, v.z);
    float s = -1 / (sign + v.z);
    float t = v.x * v.y * s;
    *a = {1 + sign * sqr(v.x) * s, sign * t, -sign * v.x};
    *b = {t, sign + sqr(v.y) * s, -v.y};
}

inline Vec3f spherical_direction(float sin_theta, float cos_theta, float phi) {
    float st = clamp(sin_theta, -1.f, 1.f);
    return {st * std::cos(phi), st * std::sin(phi), clamp(cos_theta, -1.f, 1.f)};
}

// An orthonormal frame; BSDFs work in the local frame where the shading normal is +z.
struct Frame {
    Vec3f x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    static Frame from_z(Vec3f z) { Frame f; f.z = z; coordinate_system(z, &f.x, &f.y); return f; }
    // Uses x (projected to be orthogonal to z) so anisotropic materials follow dpdu.
    static Frame from_xz(Vec3f x, Vec3f z) {
        Vec3f xo = x - z * dot(x, z);
        float len2 = length_squared(xo);
        if (!(len2 > 1e-12f)) return from_z(z);
        Frame f; f.z = z; f.x = xo / std::sqrt(len2); f.y = cross(z, f.x); return f;
    }
    Vec3f to_local(Vec3f v) const { return {dot(v, x), dot(v, y), dot(v, z)}; }
    Vec3f from_local(Vec3f v) const { return x * v.x + y * v.y + z * v.z; }
};

// Trigonometry of directions in a local shading frame (normal = +z).
inline float cos_theta(Vec3f w) { return w.z; }
inline float cos2_theta(Vec3f w) { return w.z * w.z; }
inline float abs_cos_theta(Vec3f w) { return std::abs(w.z); }
inline float sin2_theta(Vec3f w) { return std::max(0.f, 1 - cos2_theta(w)); }
inline float sin_theta(Vec3f w) { return std::sqrt(sin2_theta(w)); }
inline float tan_theta(Vec3f w) { return sin_theta(w) / cos_theta(w); }
inline float tan2_theta(Vec3f w) { return sin2_theta(w) / cos2_theta(w); }
inline float cos_phi(Vec3f w) {
    float s = sin_theta(w);
    return s == 0 ? 1 : clamp(w.x / s, -1.f, 1.f);
}
inline float sin_phi(Vec3f w) {
    float s = sin_theta(w);
    return s == 0 ? 0 : clamp(w.y / s, -1.f, 1.f);
}
inline bool same_hemisphere(Vec3f a, Vec3f b) { return a.z * b.z > 0; }

inline Vec3f reflect(Vec3f wo, Vec3f n) { return -wo + n * (2 * dot(wo, n)); }

// Snell refraction of wi about n, where eta = eta_transmitted / eta_incident relative to the side
// n points into. Returns false on total internal reflection; etap receives the relative IOR
// actually used (inverted when wi is on the back side).
inline bool refract(Vec3f wi, Vec3f n, float eta, float *etap, Vec3f *wt) {
    float cos_i = dot(n, wi);
    if (cos_i < 0) {
        eta = 1 / eta;
        cos_i = -cos_i;
        n = -n;
    }
    float sin2_i = std::max(0.f, 1 - sqr(cos_i));
    float sin2_t = sin2_i / sqr(eta);
    if (sin2_t >= 1) return false;
    float cos_t = safe_sqrt(1 - sin2_t);
    *wt = -wi / eta + n * (cos_i / eta - cos_t);
    if (etap) *etap = eta;
    return true;
}

struct Bounds3f {
    Vec3f lo{Infinity, Infinity, Infinity};
    Vec3f hi{-Infinity, -Infinity, -Infinity};
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void expand(Vec3f p) { lo = min(lo, p); hi = max(hi, p); }
    void expand(const Bounds3f &b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }
    Vec3f diagonal() const { return hi - lo; }
    Vec3f center() const { return (lo + hi) * 0.5f; }
    void bounding_sphere(Vec3f *c, float *radius) const {
        *c = center();
        *radius = empty() ? 0 : distance(*c, hi);
    }
};

} // namespace caustica
