// Environment light of constant radiance scale * L from every direction.
#pragma once

#include "lights/light.h"
#include "lights/scene_disk.h"
#include "spectral/spectrum.h"

namespace caustica {

class UniformInfiniteLight final : public Light {
  public:
    UniformInfiniteLight(SpectrumPtr radiance, float scale);

    LightType type() const override { return LightType::Infinite; }
    const Spectrum *emission_spectrum() const override { return radiance_.get(); }
    void preprocess(const Bounds3f &scene_bounds) override;
    SampledSpectrum phi(const SampledWavelengths &lambda) const override;
    std::optional<LightLiSample> sample_li(const LightSampleContext &ctx, Vec2f u,
                                           const SampledWavelengths &lambda) const override;
    float pdf_li(const LightSampleContext &ctx, Vec3f wi) const override;
    SampledSpectrum Le(const Ray &ray, const SampledWavelengths &lambda) const override;
    std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2,
                                           const SampledWavelengths &lambda) const override;
    void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const override;

  private:
    SpectrumPtr radiance_;
    float scale_;
    SceneSphere scene_;
};

}  // namespace caustica
