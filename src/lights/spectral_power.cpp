#include "lights/spectral_power.h"

#include "spectral/sampled_wavelengths.h"
#include "spectral/spectrum.h"

#include <cmath>
#include <unordered_map>

namespace caustica {

namespace {

// G of a light of one colour S: phi(lambda) / S(lambda) at S's peak; 0 if S emits nothing.
double colour_scale(const Light &light, const Spectrum &s, float peak) {
    const float at_peak = s(peak);
    if (!(at_peak > 0)) return 0;
    const double g = light.phi(SampledWavelengths::fixed(peak))[0] / at_peak;
    return std::isfinite(g) && g > 0 ? g : 0;
}

} // namespace

float light_power(const Light &light) {
    if (const Spectrum *s = light.emission_spectrum())
        return float(colour_scale(light, *s, peak_wavelength(*s)) * visible_integral(*s));
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.5f);
    const SampledSpectrum phi = light.phi(lambda);
    float sum = 0;
    for (int i = 0; i < NumWavelengths; ++i) sum += phi[i] / visible_wavelengths_pdf(lambda[i]);
    return sum / NumWavelengths;
}

EmittedSpectralPower::EmittedSpectralPower(const std::vector<const Light *> &lights) {
    std::unordered_map<const Spectrum *, std::pair<float, size_t>> seen; // peak, index in coloured_
    for (const Light *light : lights) {
        if (const Spectrum *s = light->emission_spectrum()) {
            auto [it, inserted] = seen.try_emplace(s, 0.f, coloured_.size());
            if (inserted) {
                it->second.first = peak_wavelength(*s);
                coloured_.emplace_back(s, 0.0);
            }
            coloured_[it->second.second].second += colour_scale(*light, *s, it->second.first);
        } else {
            const float p = light_power(*light);
            if (std::isfinite(p) && p > 0) flat_ += p / (LambdaMax - LambdaMin);
        }
    }
}

float EmittedSpectralPower::operator()(float lambda) const {
    double sum = flat_;
    for (const auto &[s, g] : coloured_) sum += g * (*s)(lambda);
    return float(sum);
}

} // namespace caustica
