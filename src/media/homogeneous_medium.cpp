#include "media/homogeneous_medium.h"

#include <algorithm>
#include <cmath>

namespace caustica {

namespace {

// exp(-sigma_t d) per wavelength, with a clear wavelength (sigma_t = 0) transmitting fully even
// over an infinite distance (where the product would be 0 * inf).
SampledSpectrum beer_lambert(const SampledSpectrum &sigma_t, float distance) {
    SampledSpectrum T;
    for (int i = 0; i < NumWavelengths; ++i)
        T[i] = sigma_t[i] > 0 ? std::exp(-sigma_t[i] * distance) : 1.f;
    return T;
}

// Free-flight sampling in a homogeneous medium with coefficients sigma_a, sigma_s at the path's
// wavelengths, with lane's extinction (see medium.h); Le: the emitted radiance (null: none).
MediumEvent sample_homogeneous_distance(const SampledSpectrum &sigma_a, const SampledSpectrum &sigma_s,
                                        bool secondary_terminated, float t_max, int lane, float u_distance,
                                        const SampledSpectrum *Le = nullptr) {
    const SampledSpectrum sigma_t = sigma_a + sigma_s;
    const int carried = secondary_terminated ? 1 : NumWavelengths;
    // A medium that only absorbs (at the carried wavelengths) cannot scatter: weighting by the
    // transmittance instead of sampling an absorption event removes all the variance. Unless it
    // emits: then its collisions are where the emission is counted.
    bool scatters = Le != nullptr;
    for (int k = 0; k < carried; ++k) scatters |= sigma_s[k] > 0;
    MediumEvent event;
    if (!scatters) {
        event.t = t_max;
        event.f = beer_lambert(sigma_t, t_max);
    } else {
        const float t = sigma_t[lane] > 0 ? -std::log1p(-u_distance) / sigma_t[lane] : Infinity;
        event.scattered = t < t_max;
        event.t = event.scattered ? t : t_max;
        const SampledSpectrum T = beer_lambert(sigma_t, event.t);
        event.f = event.scattered ? sigma_s * T : T;
        event.density = event.scattered ? sigma_t * T : T;
        if (event.scattered && Le) event.emitted = sigma_a * T * *Le;
    }
    for (int k = carried; k < NumWavelengths; ++k) event.f[k] = event.emitted[k] = 0;
    return event;
}

} // namespace

HomogeneousMedium::HomogeneousMedium(SpectrumPtr sigma_a, SpectrumPtr sigma_s, float scale, float g, SpectrumPtr Le,
                                     float Le_scale)
    : sigma_a_(std::move(sigma_a)), sigma_s_(std::move(sigma_s)), scale_(scale), phase_(g), Le_(std::move(Le)),
      Le_scale_(Le_scale) {}

SampledSpectrum HomogeneousMedium::Le(Vec3f, const SampledWavelengths &lambda) const {
    return is_emissive() ? Le_->sample(lambda) * Le_scale_ : SampledSpectrum(0.f);
}

SampledSpectrum HomogeneousMedium::sigma_a(const SampledWavelengths &lambda) const {
    return sigma_a_->sample(lambda) * scale_;
}

SampledSpectrum HomogeneousMedium::sigma_s(const SampledWavelengths &lambda) const {
    return sigma_s_->sample(lambda) * scale_;
}

SampledSpectrum HomogeneousMedium::transmittance(const Ray &, float distance, const SampledWavelengths &lambda) const {
    return beer_lambert(sigma_a(lambda) + sigma_s(lambda), distance);
}

MediumEvent HomogeneousMedium::sample_distance(const Ray &, float t_max, const SampledWavelengths &lambda, int lane,
                                               float u_distance) const {
    if (!is_emissive())
        return sample_homogeneous_distance(sigma_a(lambda), sigma_s(lambda), lambda.secondary_terminated(), t_max,
                                           lane, u_distance);
    const SampledSpectrum Le = this->Le({}, lambda);
    return sample_homogeneous_distance(sigma_a(lambda), sigma_s(lambda), lambda.secondary_terminated(), t_max, lane,
                                       u_distance, &Le);
}

SampledSpectrum SampledHomogeneousMedium::transmittance(const Ray &, float distance, const SampledWavelengths &) const {
    return beer_lambert(sigma_a_ + sigma_s_, distance);
}

MediumEvent SampledHomogeneousMedium::sample_distance(const Ray &, float t_max, const SampledWavelengths &lambda, int lane,
                                                      float u_distance) const {
    return sample_homogeneous_distance(sigma_a_, sigma_s_, lambda.secondary_terminated(), t_max, lane, u_distance);
}

} // namespace caustica
