// Isotropic point light: radiant intensity scale * I in every direction from one point.
#pragma once

#include "core/transform.h"
#include "lights/point_source_light.h"
#include "spectral/spectrum.h"

namespace caustica {

class PointLight final : public PointSourceLight {
  public:
    // The light sits at render_from_light's origin; intensity is multiplied by scale.
    PointLight(const Transform &render_from_light, SpectrumPtr intensity, float scale);

    const Spectrum *emission_spectrum() const override { return intensity_.get(); }
    SampledSpectrum phi(const SampledWavelengths &lambda) const override;
    SampledSpectrum intensity_towards(Vec3f, const SampledWavelengths &lambda) const override {
        return scale_ * intensity_->sample(lambda);
    }
    std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2,
                                           const SampledWavelengths &lambda) const override;
    void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const override;

  private:
    SpectrumPtr intensity_;
    float scale_;
};

}  // namespace caustica
