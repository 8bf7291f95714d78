// Directional light from infinitely far away: irradiance scale * L on surfaces perpendicular to
// the light-space +z direction (the direction light arrives from). Its emitted rays and power
// need the scene's bounding sphere, set by preprocess().
#pragma once

#include "core/transform.h"
#include "lights/light.h"
#include "lights/scene_disk.h"
#include "spectral/spectrum.h"

namespace caustica {

class DistantLight final : public Light {
  public:
    DistantLight(const Transform &render_from_light, SpectrumPtr radiance, float scale);

    LightType type() const override { return LightType::DeltaDirection; }
    const Spectrum *emission_spectrum() const override { return radiance_.get(); }
    void preprocess(const Bounds3f &scene_bounds) override;
    SampledSpectrum phi(const SampledWavelengths &lambda) const override;
    std::optional<LightLiSample> sample_li(const LightSampleContext &ctx, Vec2f u,
                                           const SampledWavelengths &lambda) const override;
    float pdf_li(const LightSampleContext &ctx, Vec3f wi) const override;
    std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2,
                                           const SampledWavelengths &lambda) const override;
    void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const override;

    // Unit direction towards the light (opposite to the direction light travels).
    Vec3f direction() const { return w_; }

  private:
    Vec3f w_;
    SpectrumPtr radiance_;
    float scale_;
    SceneSphere scene_;
};

}  // namespace caustica
