#include "lights/point_light.h"

#include "core/sampling.h"

namespace caustica {

PointLight::PointLight(const Transform &render_from_light, SpectrumPtr intensity, float scale)
    : PointSourceLight(render_from_light.apply_point({0, 0, 0})),
      intensity_(std::move(intensity)),
      scale_(scale) {}

SampledSpectrum PointLight::phi(const SampledWavelengths &lambda) const {
    // Intensity integrated over the whole sphere of directions.
    return 4 * Pi * scale_ * intensity_->sample(lambda);
}

std::optional<LightLeSample> PointLight::sample_le(Vec2f u1, Vec2f,
                                                   const SampledWavelengths &lambda) const {
    LightLeSample s;
    s.ray = {position_, sample_uniform_sphere(u1), Infinity};
    s.L = scale_ * intensity_->sample(lambda);
    s.pdf_pos = 1;  // the one possible position, chosen with probability 1
    s.pdf_dir = uniform_sphere_pdf();
    return s;
}

void PointLight::pdf_le(const Ray &, Vec3f, float *pdf_pos, float *pdf_dir) const {
    *pdf_pos = 0;  // a point cannot be hit by chance
    *pdf_dir = uniform_sphere_pdf();
}

}  // namespace caustica
