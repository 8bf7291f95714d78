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
// wavelengths (see medium.h for the mixture over the carried wavelengths).
MediumEvent sample_homogeneous_distance(const SampledSpectrum &sigma_a, const SampledSpectrum &sigma_s,
                                        bool secondary_terminated, float t_max, float u_channel,
                                        float u_distance) {
    const SampledSpectrum sigma_t = sigma_a + sigma_s;
    // The wavelengths still carried by the path form the mixture (see medium.h).
    const int carried = secondary_terminated ? 1 : NumWavelengths;
    const int channel = std::min(int(u_channel * carried), carried - 1);
    float t = sigma_t[channel] > 0 ? -std::log1p(-u_distance) / sigma_t[channel] : Infinity;
    // A medium that only absorbs (at the carried wavelengths) cannot scatter: weighting by the
    // transmittance instead of sampling an absorption event removes all the variance.
    bool scatters = false;
    for (int k = 0; k < carried; ++k) scatters |= sigma_s[k] > 0;
    if (!scatters) t = Infinity;

    MediumEvent event;
    if (t < t_max) {
        // Density of t: the average over the mixture of sigma_t,k exp(-sigma_t,k t).
        SampledSpectrum T = beer_lambert(sigma_t, t);
        float density = 0;
        for (int k = 0; k < carried; ++k) density += sigma_t[k] * T[k];
        density /= carried;
        event.scattered = true;
        event.t = t;
        if (density > 0) event.weight = sigma_s * T / density;
    } else {
        // Probability of passing t_max: the average of the mixture's transmittances (one when
        // the medium cannot scatter).
        SampledSpectrum T = beer_lambert(sigma_t, t_max);
        float probability = 0;
        for (int k = 0; k < carried; ++k) probability += T[k];
        probability = scatters ? probability / carried : 1;
        event.t = t_max;
        if (probability > 0) event.weight = T / probability;
    }
    for (int k = carried; k < NumWavelengths; ++k) event.weight[k] = 0;
    return event;
}

} // namespace

HomogeneousMedium::HomogeneousMedium(SpectrumPtr sigma_a, SpectrumPtr sigma_s, float scale, float g)
    : sigma_a_(std::move(sigma_a)), sigma_s_(std::move(sigma_s)), scale_(scale), phase_(g) {}

SampledSpectrum HomogeneousMedium::sigma_a(const SampledWavelengths &lambda) const {
    return sigma_a_->sample(lambda) * scale_;
}

SampledSpectrum HomogeneousMedium::sigma_s(const SampledWavelengths &lambda) const {
    return sigma_s_->sample(lambda) * scale_;
}

SampledSpectrum HomogeneousMedium::transmittance(float distance, const SampledWavelengths &lambda) const {
    return beer_lambert(sigma_a(lambda) + sigma_s(lambda), distance);
}

MediumEvent HomogeneousMedium::sample_distance(float t_max, const SampledWavelengths &lambda, float u_channel,
                                               float u_distance) const {
    return sample_homogeneous_distance(sigma_a(lambda), sigma_s(lambda), lambda.secondary_terminated(), t_max,
                                       u_channel, u_distance);
}

SampledSpectrum SampledHomogeneousMedium::transmittance(float distance, const SampledWavelengths &) const {
    return beer_lambert(sigma_a_ + sigma_s_, distance);
}

MediumEvent SampledHomogeneousMedium::sample_distance(float t_max, const SampledWavelengths &lambda, float u_channel,
                                                      float u_distance) const {
    return sample_homogeneous_distance(sigma_a_, sigma_s_, lambda.secondary_terminated(), t_max, u_channel,
                                       u_distance);
}

} // namespace caustica
