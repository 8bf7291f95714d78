#include "lights/uniform_infinite_light.h"

#include "core/sampling.h"

namespace caustica {

UniformInfiniteLight::UniformInfiniteLight(SpectrumPtr radiance, float scale)
    : radiance_(std::move(radiance)), scale_(scale) {}

void UniformInfiniteLight::preprocess(const Bounds3f &scene_bounds) {
    scene_ = SceneSphere::from_bounds(scene_bounds);
}

SampledSpectrum UniformInfiniteLight::phi(const SampledWavelengths &lambda) const {
    // Radiance over all 4 pi directions, each crossing the scene's disk of area pi r^2.
    return 4 * Pi * scene_.disk_area() * scale_ * radiance_->sample(lambda);
}

SampledSpectrum UniformInfiniteLight::Le(const Ray &, const SampledWavelengths &lambda) const {
    return scale_ * radiance_->sample(lambda);
}

std::optional<LightLiSample> UniformInfiniteLight::sample_li(
    const LightSampleContext &ctx, Vec2f u, const SampledWavelengths &lambda) const {
    LightLiSample s;
    s.wi = sample_uniform_sphere(u);
    s.pdf = uniform_sphere_pdf();
    s.L = scale_ * radiance_->sample(lambda);
    s.p_light = ctx.p + s.wi * (2 * scene_.radius);
    s.is_infinite = true;
    return s;
}

float UniformInfiniteLight::pdf_li(const LightSampleContext &, Vec3f) const {
    return uniform_sphere_pdf();
}

std::optional<LightLeSample> UniformInfiniteLight::sample_le(
    Vec2f u1, Vec2f u2, const SampledWavelengths &lambda) const {
    if (scene_.radius <= 0) return {};
    LightLeSample s;
    s.ray = scene_.ray_into(sample_uniform_sphere(u1), u2);
    s.L = scale_ * radiance_->sample(lambda);
    s.pdf_pos = scene_.disk_pdf();
    s.pdf_dir = uniform_sphere_pdf();
    return s;
}

void UniformInfiniteLight::pdf_le(const Ray &, Vec3f, float *pdf_pos, float *pdf_dir) const {
    *pdf_pos = scene_.disk_pdf();
    *pdf_dir = uniform_sphere_pdf();
}

}  // namespace caustica
