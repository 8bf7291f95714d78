// Fresnel reflectance for unpolarised light (Born and Wolf, "Principles of Optics", section 1.5;
// for absorbing media with a complex index, section 14.2).
//
// eta is always the index of the side the normal points into (the "inside" for cos_i < 0 light)
// relative to the side it points out of: eta = n_inside / n_outside.
#pragma once

#include "core/vecmath.h"
#include "spectral/sampled_spectrum.h"

#include <complex>

namespace caustica {

// Reflectance of a dielectric interface for light arriving with cosine cos_i to the normal.
// cos_i < 0 means the light arrives from inside, which is the same interface seen with 1/eta.
// Returns 1 under total internal reflection.
inline float fresnel_dielectric(float cos_i, float eta) {
    cos_i = clamp(cos_i, -1.f, 1.f);
    if (cos_i < 0) {
        eta = 1 / eta;
        cos_i = -cos_i;
    }
    // cos^2 of the refracted angle by Snell's law, 1 - (1 - cos_i^2) / eta^2, in the form
    // (cos_i^2 + (eta^2 - 1)) / eta^2: the first form rounds 1 - cos_i^2 to 1 for cos_i below
    // about 2.4e-4, which made an eta = 1 interface totally reflecting at grazing angles; the
    // second keeps cos_i^2 whole and is exactly cos_i^2 for eta = 1, so nothing is reflected.
    float cos2_t = (sqr(cos_i) + (sqr(eta) - 1)) / sqr(eta);
    if (cos2_t <= 0) return 1;
    float cos_t = std::sqrt(cos2_t);
    float r_parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    float r_perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return (sqr(r_parallel) + sqr(r_perpendicular)) / 2;
}

// The same formulas with a complex relative index eta + i k (an absorbing medium on the far
// side). cos_i is clamped to [0, 1]: conductors are opaque, so light only arrives from outside.
// Written out in real arithmetic (Born and Wolf 14.2; the form of pbrt-v3's FrConductor): with
// a^2 + b^2 = |eta^2 - sin^2 theta_i| and a = Re sqrt(eta^2 - sin^2 theta_i),
//   R_s = (a^2 + b^2 + cos^2 - 2 a cos) / (a^2 + b^2 + cos^2 + 2 a cos),
//   R_p = R_s (cos^2 (a^2 + b^2) + sin^4 - 2 a cos sin^2) / (cos^2 (a^2 + b^2) + sin^4 + 2 a cos sin^2).
// std::complex would compile to library calls that handle infinities (C99 Annex G) on every
// product and quotient. a^2 is (|z| + Re z) / 2 for z = eta^2 - sin^2; where Re z < 0 (metals,
// k > n) that sum cancels, so it is taken as (Im z)^2 / (2 (|z| - Re z)) instead.
inline float fresnel_complex(float cos_i, std::complex<float> eta) {
    cos_i = clamp(cos_i, 0.f, 1.f);
    const float n = eta.real(), k = eta.imag();
    const float cos2 = sqr(cos_i), sin2 = 1 - cos2;
    const float re = sqr(n) - sqr(k) - sin2, im = 2 * n * k;
    const float modulus = std::sqrt(sqr(re) + sqr(im)); // a^2 + b^2
    const float a2 = re >= 0 ? (modulus + re) / 2 : (modulus > re ? sqr(im) / (2 * (modulus - re)) : 0.f);
    const float two_a_cos = 2 * std::sqrt(a2) * cos_i;
    // Both ratios are (x - y) / (x + y) with x, y >= 0: at most 1, and at least 0 but for
    // rounding where x ~ y (an index near 1, which reflects nothing). Where both vanish (grazing
    // light at index 1) the interface reflects everything, as fresnel_dielectric says there.
    const float s_sum = modulus + cos2;
    if (!(s_sum + two_a_cos > 0)) return 1;
    const float r_perpendicular = std::max(0.f, (s_sum - two_a_cos) / (s_sum + two_a_cos));
    const float p_sum = cos2 * modulus + sqr(sin2), p_cross = two_a_cos * sin2;
    const float r_parallel =
        p_sum + p_cross > 0 ? r_perpendicular * std::max(0.f, (p_sum - p_cross) / (p_sum + p_cross)) : r_perpendicular;
    return (r_parallel + r_perpendicular) / 2;
}

// Conductor reflectance per wavelength from the spectral complex index (eta, k).
inline SampledSpectrum fresnel_conductor(float cos_i, const SampledSpectrum &eta,
                                         const SampledSpectrum &k) {
    SampledSpectrum r;
    for (int i = 0; i < NumWavelengths; ++i)
        r[i] = fresnel_complex(cos_i, std::complex<float>(eta[i], k[i]));
    return r;
}

// Schlick's approximation (Schlick 1994, "An Inexpensive BRDF Model for Physically-based
// Rendering"): the reflectance f0 at normal incidence raised towards 1 at grazing angles.
inline float fresnel_schlick(float f0, float cos_i) {
    float m = clamp(1 - std::abs(cos_i), 0.f, 1.f);
    float m2 = m * m;
    return f0 + (1 - f0) * (m2 * m2 * m);
}
inline SampledSpectrum fresnel_schlick(const SampledSpectrum &f0, float cos_i) {
    float m = clamp(1 - std::abs(cos_i), 0.f, 1.f);
    float m2 = m * m;
    return f0 + (SampledSpectrum(1) - f0) * (m2 * m2 * m);
}

} // namespace caustica
