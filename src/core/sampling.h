// Warping uniform samples to distributions used throughout the renderer, with matching pdfs.
#pragma once

#include "core/vecmath.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

namespace caustica {

// The base-b radical inverse of index: its digits mirrored about the radix point (the van der
// Corput sequence in base b; Halton points take one prime base per dimension).
inline float radical_inverse(uint64_t base, uint64_t index) {
    double value = 0, scale = 1.0 / double(base);
    for (; index > 0; index /= base, scale /= double(base)) value += double(index % base) * scale;
    return std::min(OneMinusEpsilon, float(value));
}

inline float power_heuristic(int nf, float f_pdf, int ng, float g_pdf) {
    float f = nf * f_pdf, g = ng * g_pdf;
    if (std::isinf(sqr(f))) return 1;
    if (f == 0 && g == 0) return 0;
    return sqr(f) / (sqr(f) + sqr(g));
}

// Shirley and Chiu's concentric mapping: low distortion, preserves stratification.
inline Vec2f sample_uniform_disk_concentric(Vec2f u) {
    Vec2f o{2 * u.x - 1, 2 * u.y - 1};
    if (o.x == 0 && o.y == 0) return {0, 0};
    float r, theta;
    if (std::abs(o.x) > std::abs(o.y)) {
        r = o.x;
        theta = PiOver4 * (o.y / o.x);
    } else {
        r = o.y;
        theta = PiOver2 - PiOver4 * (o.x / o.y);
    }
    return {r * std::cos(theta), r * std::sin(theta)};
}

inline Vec3f sample_cosine_hemisphere(Vec2f u) {
    Vec2f d = sample_uniform_disk_concentric(u);
    float z = safe_sqrt(1 - d.x * d.x - d.y * d.y);
    return {d.x, d.y, z};
}
inline float cosine_hemisphere_pdf(float cos_theta) { return cos_theta * InvPi; }

inline Vec3f sample_uniform_sphere(Vec2f u) {
    float z = 1 - 2 * u.x;
    float r = safe_sqrt(1 - z * z);
    float phi = 2 * Pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}
inline float uniform_sphere_pdf() { return Inv4Pi; }

inline Vec3f sample_uniform_hemisphere(Vec2f u) {
    float z = u.x;
    float r = safe_sqrt(1 - z * z);
    float phi = 2 * Pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}
inline float uniform_hemisphere_pdf() { return Inv2Pi; }

// Directions within angle acos(cos_max) of +z, uniform in solid angle.
inline Vec3f sample_uniform_cone(Vec2f u, float cos_max) {
    float cos_t = (1 - u.x) + u.x * cos_max;
    float sin_t = safe_sqrt(1 - cos_t * cos_t);
    float phi = u.y * 2 * Pi;
    return spherical_direction(sin_t, cos_t, phi);
}
inline float uniform_cone_pdf(float cos_max) { return 1 / (2 * Pi * (1 - cos_max)); }

// Barycentrics uniform over a triangle's area (Heitz 2019's low-distortion map).
inline void sample_uniform_triangle(Vec2f u, float b[3]) {
    float b0, b1;
    if (u.x < u.y) {
        b0 = u.x / 2;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2;
        b0 = u.x - b1;
    }
    b[0] = b0;
    b[1] = b1;
    b[2] = 1 - b0 - b1;
}

// x in [0, 1] with density proportional to (1 - x) a + x b (a, b >= 0, not both 0): the root of
// the quadratic CDF (2 a x + (b - a) x^2) / (a + b) = u, in the form that stays accurate when
// a and b are nearly equal.
inline float sample_linear(float u, float a, float b) {
    if (a + b == 0) return u;
    const float denominator = a + std::sqrt((1 - u) * a * a + u * b * b);
    if (denominator == 0) return 0;
    return std::min(u * (a + b) / denominator, OneMinusEpsilon);
}
inline float linear_pdf(float x, float a, float b) {
    if (x < 0 || x > 1) return 0;
    return a + b == 0 ? 1 : 2 * ((1 - x) * a + x * b) / (a + b);
}

// (u, v) in [0, 1]^2 with density proportional to the bilinear interpolation of the corner
// weights w = {w(0,0), w(1,0), w(0,1), w(1,1)}: v from its marginal, then u given v.
inline Vec2f sample_bilinear(Vec2f u, const float w[4]) {
    const float v = sample_linear(u.y, w[0] + w[1], w[2] + w[3]);
    return {sample_linear(u.x, (1 - v) * w[0] + v * w[2], (1 - v) * w[1] + v * w[3]), v};
}
inline float bilinear_pdf(Vec2f p, const float w[4]) {
    if (p.x < 0 || p.x > 1 || p.y < 0 || p.y > 1) return 0;
    const float sum = w[0] + w[1] + w[2] + w[3];
    if (sum == 0) return 1;
    return 4 * ((1 - p.x) * (1 - p.y) * w[0] + p.x * (1 - p.y) * w[1] + (1 - p.x) * p.y * w[2] + p.x * p.y * w[3]) /
           sum;
}

// Samples {0..n-1} proportionally to weights, reusing u for continuous sampling afterwards.
class DiscreteDistribution {
  public:
    DiscreteDistribution() = default;
    explicit DiscreteDistribution(std::span<const float> weights);
    int size() const { return int(pmf_.size()); }
    bool empty() const { return pmf_.empty(); }
    // Returns the index; *u_remapped is u rescaled to [0,1) within the chosen bin.
    int sample(float u, float *pmf, float *u_remapped = nullptr) const;
    float pmf(int i) const { return pmf_[i]; }

  private:
    std::vector<float> pmf_, cdf_;
};

// Piecewise-constant 1D density over [0,1] (used for tabulated filters and environment maps).
class PiecewiseConstant1D {
  public:
    PiecewiseConstant1D() = default;
    explicit PiecewiseConstant1D(std::span<const float> f);
    float sample(float u, float *pdf, int *offset = nullptr) const;
    float pdf(float x) const;
    float integral() const { return func_int_; }
    int size() const { return int(func_.size()); }

  private:
    std::vector<float> func_, cdf_;
    float func_int_ = 0;
};

// Piecewise-constant 2D density over [0,1]^2: marginal in v, conditionals in u.
class PiecewiseConstant2D {
  public:
    PiecewiseConstant2D() = default;
    // f has nv rows of nu values each.
    PiecewiseConstant2D(std::span<const float> f, int nu, int nv);
    Vec2f sample(Vec2f u, float *pdf) const;
    float pdf(Vec2f p) const;
    float integral() const { return marginal_.integral(); }

  private:
    std::vector<PiecewiseConstant1D> conditional_;
    PiecewiseConstant1D marginal_;
};

} // namespace caustica
