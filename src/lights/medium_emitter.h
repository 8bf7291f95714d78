// An emissive medium as the start of light paths. A medium emits sigma_a Le per unit length and
// solid angle, isotropically (pbrt-v4's convention); the light paths of lt, sppm, bdpt, vcm and
// bpm start some of their paths here, chosen with the lights by power. Camera subpaths count the
// same emission by the collision estimator (SubpathWalk::emitted), which pt and sppm use alone
// and bdpt, vcm and bpm weigh against their light subpaths (integrators/common/medium_emission.h):
// a medium emitter is never sampled for next-event estimation (sample_li has nothing to offer,
// pdf_li is 0) and is not among Scene::lights.
//
// Where a path starts: a heterogeneous medium draws the point by its emission over its majorant
// cells (heterogeneous_medium.h); a homogeneous medium has no bounds of its own and is sampled
// uniformly over the scene's bounding box. Either box may hold points that lie outside the
// medium, beyond the interfaces that bound it: start_light_path (light_path_start.h) finds the
// medium at the point and drops the path there, which keeps the estimate unbiased.
#pragma once

#include "lights/light.h"
#include "media/medium.h"

namespace caustica {

class MediumEmitter final : public Light {
  public:
    explicit MediumEmitter(const Medium &medium);

    LightType type() const override { return LightType::Volume; }
    // Homogeneous media: the box their paths start in.
    void preprocess(const Bounds3f &scene_bounds) override;
    // 4 pi times the integral of sigma_a Le over the medium (or the scene's box).
    SampledSpectrum phi(const SampledWavelengths &lambda) const override;

    std::optional<LightLiSample> sample_li(const LightSampleContext &, Vec2f, const SampledWavelengths &) const override {
        return std::nullopt;
    }
    float pdf_li(const LightSampleContext &, Vec3f) const override { return 0; }

    // sigma_a Le at p: the radiance emitted per unit length, towards any direction.
    SampledSpectrum L(Vec3f p, Vec3f n, Vec2f uv, Vec3f w, const SampledWavelengths &lambda) const override;

    // A point drawn as above (pdf_pos per unit volume), a direction uniform over the sphere; u1.x
    // chooses the cell, and the point within it comes from a stream seeded by u1 and u2.
    std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2, const SampledWavelengths &lambda) const override;
    void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const override;

  private:
    const Medium &medium_;
    Bounds3f scene_bounds_;
};

} // namespace caustica
