#include "lights/light_sampler.h"

#include "spectral/spectrum.h"

#include <algorithm>
#include <cmath>

namespace caustica {

UniformLightSampler::UniformLightSampler(const std::vector<LightPtr> &lights) {
    for (const LightPtr &l : lights) {
        index_.emplace(l.get(), int(lights_.size()));
        lights_.push_back(l.get());
    }
}

std::optional<SampledLight> UniformLightSampler::sample(float u) const {
    if (lights_.empty()) return {};
    int n = int(lights_.size());
    int i = std::min(int(u * n), n - 1);
    return SampledLight{lights_[i], 1.f / n};
}

float UniformLightSampler::pmf(const Light *light) const {
    return index_.contains(light) ? 1.f / lights_.size() : 0.f;
}

namespace {

// A light's power integrated over the visible spectrum. A light of one colour (emission_spectrum)
// emits phi(lambda) = G S(lambda), with G the same at every wavelength: one phi at S's peak gives
// G, and the integral of S every nanometre does the rest, so that a light emitting only in a
// narrow line gets its share. Any other light (an environment image, whose texels are smooth
// RGB illuminant spectra) is estimated from phi at four wavelengths spread over the visible range.
float light_power(const Light &light) {
    if (const Spectrum *s = light.emission_spectrum()) {
        const float peak = peak_wavelength(*s), at_peak = (*s)(peak);
        if (!(at_peak > 0)) return 0;
        return light.phi(SampledWavelengths::fixed(peak))[0] / at_peak * visible_integral(*s);
    }
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.5f);
    const SampledSpectrum phi = light.phi(lambda);
    float sum = 0;
    for (int i = 0; i < NumWavelengths; ++i) sum += phi[i] / visible_wavelengths_pdf(lambda[i]);
    return sum / NumWavelengths;
}

} // namespace

PowerLightSampler::PowerLightSampler(const std::vector<LightPtr> &lights) {
    if (lights.empty()) return;
    std::vector<float> power;
    power.reserve(lights.size());
    for (const LightPtr &l : lights) {
        const float p = light_power(*l);
        power.push_back(std::isfinite(p) ? std::max(0.f, p) : 0.f);
        index_.emplace(l.get(), int(lights_.size()));
        lights_.push_back(l.get());
    }
    // DiscreteDistribution falls back to uniform weights when all are zero.
    distribution_ = DiscreteDistribution(power);
}

std::optional<SampledLight> PowerLightSampler::sample(float u) const {
    if (lights_.empty()) return {};
    float pmf;
    int i = distribution_.sample(u, &pmf);
    return SampledLight{lights_[i], pmf};
}

float PowerLightSampler::pmf(const Light *light) const {
    auto it = index_.find(light);
    return it == index_.end() ? 0.f : distribution_.pmf(it->second);
}

}  // namespace caustica
