#include "lights/light_sampler.h"

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

PowerLightSampler::PowerLightSampler(const std::vector<LightPtr> &lights) {
    if (lights.empty()) return;
    // Fixed wavelengths from the visible density (the middle of its range), so the choice of
    // lights is the same in every run. Each light's phi / pdf, averaged over the wavelengths, is
    // an estimate of its power integrated over the spectrum.
    SampledWavelengths lambda = SampledWavelengths::sample_visible(0.5f);
    std::vector<float> power;
    power.reserve(lights.size());
    for (const LightPtr &l : lights) {
        SampledSpectrum phi = l->phi(lambda);
        float sum = 0;
        for (int i = 0; i < NumWavelengths; ++i) sum += phi[i] / visible_wavelengths_pdf(lambda[i]);
        power.push_back(std::isfinite(sum) ? std::max(0.f, sum / NumWavelengths) : 0.f);
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
