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
inline float fresnel_complex(float cos_i, std::complex<float> eta) {
    using C = std::complex<float>;
    cos_i = clamp(cos_i, 0.f, 1.f);
    C sin2_t = C(1 - sqr(cos_i)) / (eta * eta);
    C cos_t = std::sqrt(C(1) - sin2_t);
    C r_parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    C r_perpendicular = (C(cos_i) - eta * cos_t) / (C(cos_i) + eta * cos_t);
    return (std::norm(r_parallel) + std::norm(r_perpendicular)) / 2;
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
