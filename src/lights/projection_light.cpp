#include "lights/projection_light.h"

#include "spectral/photometric.h"
#include "spectral/rgb_spectrum.h"

#include <algorithm>
#include <cmath>

namespace caustica {

namespace {
// pbrt-v4's near plane: directions closer to the plane z = 0 than this carry nothing.
constexpr float Hither = 1e-3f;
} // namespace

ProjectionLight::ProjectionLight(const Transform &render_from_light, RGBImage image, float scale, float fov_degrees)
    : PointSourceLight(render_from_light.apply_point({0, 0, 0})),
      render_from_light_(render_from_light * Transform::scale(1, -1, 1)),
      light_from_render_(render_from_light_.inverse()), image_(std::move(image)), scale_(scale),
      tan_half_fov_(std::tan(radians(fov_degrees) / 2)) {
    const float aspect = float(image_.width) / float(image_.height);
    window_min_ = aspect > 1 ? Vec2f(-aspect, -1) : Vec2f(-1, -1 / aspect);
    window_max_ = aspect > 1 ? Vec2f(aspect, 1) : Vec2f(1, 1 / aspect);
    window_area_ = (window_max_.x - window_min_.x) * (window_max_.y - window_min_.y) * tan_half_fov_ * tan_half_fov_;
    std::vector<float> weights(size_t(image_.width) * image_.height);
    for (int y = 0; y < image_.height; ++y)
        for (int x = 0; x < image_.width; ++x) {
            const float *rgb = image_.at(x, y);
            const Vec3f w = window_direction({(x + 0.5f) / image_.width, (y + 0.5f) / image_.height});
            weights[size_t(y) * image_.width + x] =
                std::max(0.f, (rgb[0] + rgb[1] + rgb[2]) / 3) * w.z * w.z * w.z;
        }
    distribution_ = PiecewiseConstant2D(weights, image_.width, image_.height);
}

EmissionDirections ProjectionLight::emission_directions() const {
    const Vec3f axis = normalize(render_from_light_.apply_vector({0, 0, 1}));
    float cos_widest = 1;
    for (Vec2f corner : {Vec2f{0, 0}, Vec2f{1, 0}, Vec2f{0, 1}, Vec2f{1, 1}})
        cos_widest = std::min(cos_widest, dot(axis, normalize(render_from_light_.apply_vector(window_direction(corner)))));
    return {{axis, cos_widest}, std::cos(DirectionCone::RoundingMargin), false};
}

Vec3f ProjectionLight::window_direction(Vec2f unit) const {
    const float sx = window_min_.x + unit.x * (window_max_.x - window_min_.x);
    const float sy = window_min_.y + unit.y * (window_max_.y - window_min_.y);
    return normalize(Vec3f(sx * tan_half_fov_, sy * tan_half_fov_, 1));
}

std::optional<Vec2f> ProjectionLight::window_point(Vec3f w) const {
    if (w.z < Hither) return std::nullopt;
    const float sx = w.x / (w.z * tan_half_fov_), sy = w.y / (w.z * tan_half_fov_);
    if (sx < window_min_.x || sx > window_max_.x || sy < window_min_.y || sy > window_max_.y) return std::nullopt;
    return Vec2f((sx - window_min_.x) / (window_max_.x - window_min_.x),
                 (sy - window_min_.y) / (window_max_.y - window_min_.y));
}

SampledSpectrum ProjectionLight::intensity(Vec2f unit, const SampledWavelengths &lambda) const {
    const int x = std::clamp(int(unit.x * float(image_.width)), 0, image_.width - 1);
    const int y = std::clamp(int(unit.y * float(image_.height)), 0, image_.height - 1);
    const float *p = image_.at(x, y);
    const RGB rgb{std::max(p[0], 0.f), std::max(p[1], 0.f), std::max(p[2], 0.f)};
    return scale_ * RGBIlluminantSpectrum(RGBColorSpace::srgb(), rgb).sample(lambda);
}

SampledSpectrum ProjectionLight::phi(const SampledWavelengths &lambda) const {
    SampledSpectrum sum;
    for (int y = 0; y < image_.height; ++y)
        for (int x = 0; x < image_.width; ++x) {
            const Vec3f w = window_direction({(x + 0.5f) / image_.width, (y + 0.5f) / image_.height});
            sum += intensity({(x + 0.5f) / image_.width, (y + 0.5f) / image_.height}, lambda) * (w.z * w.z * w.z);
        }
    return sum * (window_area_ / float(image_.width * image_.height));
}

float ProjectionLight::unit_luminous_power() const {
    const RGB weights = luminance_weights(RGBColorSpace::srgb());
    double sum = 0;
    for (int y = 0; y < image_.height; ++y)
        for (int x = 0; x < image_.width; ++x) {
            const Vec3f w = window_direction({(x + 0.5f) / image_.width, (y + 0.5f) / image_.height});
            const float *rgb = image_.at(x, y);
            sum += (rgb[0] * weights.r + rgb[1] * weights.g + rgb[2] * weights.b) * w.z * w.z * w.z;
        }
    return float(window_area_ * sum / double(image_.width * image_.height));
}

SampledSpectrum ProjectionLight::intensity_towards(Vec3f w, const SampledWavelengths &lambda) const {
    std::optional<Vec2f> unit = window_point(normalize(light_from_render_.apply_vector(w)));
    return unit ? intensity(*unit, lambda) : SampledSpectrum(0.f);
}

std::optional<LightLeSample> ProjectionLight::sample_le(Vec2f u1, Vec2f, const SampledWavelengths &lambda) const {
    float pdf = 0;
    const Vec2f unit = distribution_.sample(u1, &pdf);
    if (!(pdf > 0)) return {};
    const Vec3f w = window_direction(unit);
    LightLeSample s;
    s.ray = {position_, normalize(render_from_light_.apply_vector(w)), Infinity};
    s.L = intensity(unit, lambda);
    s.pdf_pos = 1;
    // The window's unit square maps to area window_area_ on the plane z = 1, whose points a
    // direction w reaches with dA = dw / cos^3.
    s.pdf_dir = pdf / (window_area_ * w.z * w.z * w.z);
    return s;
}

void ProjectionLight::pdf_le(const Ray &ray, Vec3f, float *pdf_pos, float *pdf_dir) const {
    *pdf_pos = 0;
    const Vec3f w = normalize(light_from_render_.apply_vector(ray.d));
    std::optional<Vec2f> unit = window_point(w);
    *pdf_dir = unit ? distribution_.pdf(*unit) / (window_area_ * w.z * w.z * w.z) : 0.f;
}

}  // namespace caustica
