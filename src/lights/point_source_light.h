// The lights that emit from a single point (pbrt-v4's DeltaPosition lights: point, spot,
// goniometric, projection). They differ only in how their radiant intensity varies with direction
// and in how light paths leave them; next-event estimation is the same for all: the intensity
// towards the receiving point over the squared distance (the inverse-square law), a delta in
// position that no direction hits by chance.
#pragma once

#include "lights/light.h"

namespace caustica {

class PointSourceLight : public Light {
  public:
    LightType type() const override { return LightType::DeltaPosition; }
    std::optional<Bounds3f> spatial_bounds() const override {
        Bounds3f b;
        b.expand(position_);
        return b;
    }
    std::optional<LightLiSample> sample_li(const LightSampleContext &ctx, Vec2f u,
                                           const SampledWavelengths &lambda) const final;
    float pdf_li(const LightSampleContext &, Vec3f) const final { return 0; }
    Vec3f position() const { return position_; }
    // Radiant intensity leaving the light in render-space direction w (unit).
    virtual SampledSpectrum intensity_towards(Vec3f w, const SampledWavelengths &lambda) const = 0;

  protected:
    explicit PointSourceLight(Vec3f position) : position_(position) {}
    Vec3f position_;
};

}  // namespace caustica
