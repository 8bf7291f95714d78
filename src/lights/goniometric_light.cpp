#include "lights/goniometric_light.h"

#include "lights/equal_area_mapping.h"

#include <algorithm>

namespace caustica {

GoniometricLight::GoniometricLight(const Transform &render_from_light, SpectrumPtr intensity, float scale,
                                   const RGBImage &image)
    : PointSourceLight(render_from_light.apply_point({0, 0, 0})), render_from_light_(render_from_light),
      light_from_render_(render_from_light.inverse()),
      intensity_(std::move(intensity)), scale_(scale), resolution_(image.width) {
    values_.resize(size_t(image.width) * image.height);
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float *rgb = image.at(x, y);
            const float v = std::max(0.f, (rgb[0] + rgb[1] + rgb[2]) / 3);
            values_[size_t(y) * image.width + x] = v;
            sum += v;
        }
    mean_ = float(sum / double(values_.size()));
    distribution_ = PiecewiseConstant2D(values_, image.width, image.height);
}

// pbrt-v4 swaps y and z between light space and the diagram's sphere.
Vec3f GoniometricLight::to_diagram(Vec3f w_render) const {
    Vec3f w = normalize(light_from_render_.apply_vector(w_render));
    return {w.x, w.z, w.y};
}

Vec3f GoniometricLight::from_diagram(Vec3f w) const {
    return normalize(render_from_light_.apply_vector({w.x, w.z, w.y}));
}

float GoniometricLight::diagram(Vec3f w) const {
    const Vec2f uv = equal_area_sphere_to_square(to_diagram(w));
    const int x = std::clamp(int(uv.x * float(resolution_)), 0, resolution_ - 1);
    const int y = std::clamp(int(uv.y * float(resolution_)), 0, resolution_ - 1);
    return values_[size_t(y) * resolution_ + x];
}

SampledSpectrum GoniometricLight::phi(const SampledWavelengths &lambda) const {
    return 4 * Pi * scale_ * mean_ * intensity_->sample(lambda);
}

std::optional<LightLeSample> GoniometricLight::sample_le(Vec2f u1, Vec2f, const SampledWavelengths &lambda) const {
    float pdf = 0;
    const Vec2f uv = distribution_.sample(u1, &pdf);
    if (!(pdf > 0)) return {};
    LightLeSample s;
    s.ray = {position_, from_diagram(equal_area_square_to_sphere(uv)), Infinity};
    s.L = intensity_towards(s.ray.d, lambda);
    s.pdf_pos = 1;
    s.pdf_dir = pdf / (4 * Pi);
    return s;
}

void GoniometricLight::pdf_le(const Ray &ray, Vec3f, float *pdf_pos, float *pdf_dir) const {
    *pdf_pos = 0;
    *pdf_dir = distribution_.pdf(equal_area_sphere_to_square(to_diagram(ray.d))) / (4 * Pi);
}

}  // namespace caustica
