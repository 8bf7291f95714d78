// A medium whose absorption, scattering and phase function are the same everywhere: transmittance
// is Beer-Lambert's exp(-sigma_t d) in closed form, and free-flight distances are exponential.
#pragma once

#include "media/medium.h"
#include "spectral/spectrum.h"

namespace caustica {

class HomogeneousMedium final : public Medium {
  public:
    // sigma_a and sigma_s per unit length of the scene, already multiplied by "scale".
    HomogeneousMedium(SpectrumPtr sigma_a, SpectrumPtr sigma_s, float scale, float g);

    SampledSpectrum sigma_a(const SampledWavelengths &lambda) const override;
    SampledSpectrum sigma_s(const SampledWavelengths &lambda) const override;
    const HenyeyGreenstein &phase() const override { return phase_; }
    SampledSpectrum transmittance(float distance, const SampledWavelengths &lambda) const override;
    MediumEvent sample_distance(float t_max, const SampledWavelengths &lambda, float u_channel,
                                float u_distance) const override;

  private:
    SpectrumPtr sigma_a_, sigma_s_;
    float scale_;
    HenyeyGreenstein phase_;
};

} // namespace caustica
