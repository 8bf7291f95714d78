// pbrt-v4's procedural "cloud" medium (pbrt-v4 section 11.4, CloudMedium): a density in [0, 1]
// from five octaves of Perlin noise at the point, displaced by two octaves of the noise's gradient
// ("wispiness"), scaled by "density" and thinning with height in the medium's space, times the
// spectra sigma_a and sigma_s, inside the box p0-p1. Its majorant is sigma_t itself, the largest
// density being 1.
#pragma once

#include "media/heterogeneous_medium.h"

namespace caustica {

class CloudMedium final : public ScalarDensityMedium {
  public:
    CloudMedium(const Transform &render_from_medium, const Bounds3f &bounds, SpectrumPtr sigma_a, SpectrumPtr sigma_s,
                float g, float density, float wispiness, float frequency);

    // The density at point p of the medium's space (pbrt-v4's CloudMedium::Density).
    float density(Vec3f p) const;

  private:
    float density_at(Vec3f u) const override;

    Vec3f lo_, extent_;
    float density_, wispiness_, frequency_;
};

} // namespace caustica
