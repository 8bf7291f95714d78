// pbrt-v4's procedural "cloud" medium (pbrt-v4 section 11.4, CloudMedium): a density in [0, 1]
// from five octaves of Perlin noise at the point, displaced by two octaves of the noise's gradient
// ("wispiness"), scaled by "density" and thinning with height in the medium's space, times the
// spectra sigma_a and sigma_s, inside the box p0-p1. Its majorant is sigma_t itself, the largest
// density being 1.
#pragma once

#include "media/heterogeneous_medium.h"
#include "spectral/spectrum.h"

namespace caustica {

class CloudMedium final : public HeterogeneousMedium {
  public:
    CloudMedium(const Transform &render_from_medium, const Bounds3f &bounds, SpectrumPtr sigma_a, SpectrumPtr sigma_s,
                float g, float density, float wispiness, float frequency);

    // The density at point p of the medium's space (pbrt-v4's CloudMedium::Density).
    float density(Vec3f p) const;

  protected:
    MediumProperties local(Vec3f u, const SampledWavelengths &lambda) const override;
    SampledSpectrum majorant_scale(const SampledWavelengths &lambda) const override;
    bool may_scatter(const SampledWavelengths &lambda, int carried) const override;

  private:
    Vec3f lo_, extent_;
    SpectrumPtr sigma_a_, sigma_s_;
    float density_, wispiness_, frequency_;
};

} // namespace caustica
