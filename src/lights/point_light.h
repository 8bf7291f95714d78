// Isotropic point light: radiant intensity scale * I in every direction from one point.
#pragma once

#include "core/transform.h"
#include "lights/light.h"
#include "spectral/spectrum.h"

namespace caustica {

class PointLight final : public Light {
  public:
    // The light sits at render_from_light's origin; intensity is multiplied by scale.
    PointLight(const Transform &render_from_light, SpectrumPtr intensity, float scale);

    LightType type() const override { return LightType::DeltaPosition; }
    const Spectrum *emission_spectrum() const override { return intensity_.get(); }
    SampledSpectrum phi(const SampledWavelengths &lambda) const override;
    std::optional<Bounds3f> spatial_bounds() const override {
        Bounds3f b;
        b.expand(position_);
        return b;
    }
    std::optional<LightLiSample> sample_li(const LightSampleContext &ctx, Vec2f u,
                                           const SampledWavelengths &lambda) const override;
    float pdf_li(const LightSampleContext &ctx, Vec3f wi) const override;
    std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2,
                                           const SampledWavelengths &lambda) const override;
    void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const override;

    Vec3f position() const { return position_; }

  private:
    Vec3f position_;
    SpectrumPtr intensity_;
    float scale_;
};

}  // namespace caustica
