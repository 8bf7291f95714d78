#include "lights/distant_light.h"

namespace caustica {

DistantLight::DistantLight(const Transform &render_from_light, SpectrumPtr radiance, float scale)
    : w_(normalize(render_from_light.apply_vector({0, 0, 1}))),
      radiance_(std::move(radiance)),
      scale_(scale) {}

void DistantLight::preprocess(const Bounds3f &scene_bounds) {
    scene_ = SceneSphere::from_bounds(scene_bounds);
}

SampledSpectrum DistantLight::phi(const SampledWavelengths &lambda) const {
    // All the power that reaches the scene crosses the disk of its bounding sphere.
    return scale_ * radiance_->sample(lambda) * scene_.disk_area();
}

std::optional<LightLiSample> DistantLight::sample_li(const LightSampleContext &ctx, Vec2f,
                                                     const SampledWavelengths &lambda) const {
    LightLiSample s;
    s.L = scale_ * radiance_->sample(lambda);
    s.wi = w_;
    s.pdf = 1;
    // A point certainly outside the scene, for the occlusion ray.
    s.p_light = ctx.p + w_ * (2 * scene_.radius);
    s.is_infinite = true;
    return s;
}

float DistantLight::pdf_li(const LightSampleContext &, Vec3f) const { return 0; }

std::optional<LightLeSample> DistantLight::sample_le(Vec2f u1, Vec2f,
                                                     const SampledWavelengths &lambda) const {
    if (scene_.radius <= 0) return {};
    LightLeSample s;
    s.ray = scene_.ray_into(-w_, u1);
    s.L = scale_ * radiance_->sample(lambda);
    s.pdf_pos = scene_.disk_pdf();
    s.pdf_dir = 1;  // the one possible direction, chosen with probability 1
    return s;
}

void DistantLight::pdf_le(const Ray &, Vec3f, float *pdf_pos, float *pdf_dir) const {
    *pdf_pos = scene_.disk_pdf();
    *pdf_dir = 0;  // a single direction cannot be hit by chance
}

}  // namespace caustica
