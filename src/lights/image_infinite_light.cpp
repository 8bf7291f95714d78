#include "lights/image_infinite_light.h"

#include "lights/equal_area_mapping.h"
#include "spectral/photometric.h"
#include "spectral/color_space.h"
#include "spectral/rgb_spectrum.h"

#include <stdexcept>

namespace caustica {

namespace {

// Solid angle of pixel row y of an equirectangular image, per pixel: (2 pi / width) times the
// difference of cos theta across the row.
float equirect_pixel_solid_angle(int y, int width, int height) {
    float cos0 = std::cos(Pi * y / height), cos1 = std::cos(Pi * (y + 1) / height);
    return 2 * Pi / width * (cos0 - cos1);
}

float luminance(RGB rgb, RGB weights) {
    return weights.r * rgb.r + weights.g * rgb.g + weights.b * rgb.b;
}

RGB raw_pixel(const RGBImage &image, int x, int y) {
    const float *p = image.at(x, y);
    return {p[0], p[1], p[2]};
}
// Emission ignores negative values (out-of-gamut pixels of some HDR files), as pbrt-v4 does.
RGB pixel_rgb(const RGBImage &image, int x, int y) { return clamp_zero(raw_pixel(image, x, y)); }

Vec3f mapping_direction(EnvironmentMapping mapping, Vec2f uv) {
    if (mapping == EnvironmentMapping::EqualArea) return equal_area_square_to_sphere(uv);
    float theta = Pi * uv.y, phi = 2 * Pi * uv.x;
    return spherical_direction(std::sin(theta), std::cos(theta), phi);
}

}  // namespace

ImageInfiniteLight::ImageInfiniteLight(const Transform &render_from_light, RGBImage image,
                                       EnvironmentMapping mapping, const RGBColorSpace &color_space,
                                       float scale)
    : render_from_light_(render_from_light),
      light_from_render_(render_from_light.inverse()),
      image_(std::move(image)),
      mapping_(mapping),
      color_space_(&color_space),
      scale_(scale) {
    if (mapping_ == EnvironmentMapping::EqualArea && image_.width != image_.height)
        throw std::invalid_argument("an equal-area environment map must be square");
    if (mapping_ == EnvironmentMapping::Equirectangular && image_.width != 2 * image_.height)
        throw std::invalid_argument("an equirectangular environment map must be 2:1");
    // Sample pixels in proportion to luminance times their solid angle (constant for the
    // equal-area map; sin theta at the row's centre for latitude-longitude). Luminance is
    // positive wherever any clamped channel is, so every emitting pixel can be sampled.
    RGB weights = luminance_weights(color_space);
    std::vector<float> f(size_t(image_.width) * image_.height);
    for (int y = 0; y < image_.height; ++y) {
        float row_weight = mapping_ == EnvironmentMapping::EqualArea
                               ? 1.f
                               : std::sin(Pi * (y + 0.5f) / image_.height);
        for (int x = 0; x < image_.width; ++x)
            f[size_t(y) * image_.width + x] =
                luminance(pixel_rgb(image_, x, y), weights) * row_weight;
    }
    distribution_ = PiecewiseConstant2D(f, image_.width, image_.height);
}

void ImageInfiniteLight::preprocess(const Bounds3f &scene_bounds) {
    scene_ = SceneSphere::from_bounds(scene_bounds);
}

Vec3f ImageInfiniteLight::direction_at(Vec2f uv) const { return mapping_direction(mapping_, uv); }

Vec2f ImageInfiniteLight::uv_of(Vec3f w) const {
    if (mapping_ == EnvironmentMapping::EqualArea) return equal_area_sphere_to_square(w);
    float theta = safe_acos(w.z);
    float phi = std::atan2(w.y, w.x);
    if (phi < 0) phi += 2 * Pi;
    return {clamp(phi * Inv2Pi, 0.f, 1.f), clamp(theta * InvPi, 0.f, 1.f)};
}

float ImageInfiniteLight::solid_angle_per_uv(Vec2f uv) const {
    if (mapping_ == EnvironmentMapping::EqualArea) return 4 * Pi;
    // d omega = sin theta d theta d phi = 2 pi^2 sin theta du dv.
    return 2 * Pi * Pi * std::sin(Pi * uv.y);
}

RGB ImageInfiniteLight::pixel(Vec2f uv) const {
    // Nearest texel, as pbrt-v4 looks environment maps up.
    int x = clamp(int(uv.x * image_.width), 0, image_.width - 1);
    int y = clamp(int(uv.y * image_.height), 0, image_.height - 1);
    return pixel_rgb(image_, x, y);
}

SampledSpectrum ImageInfiniteLight::radiance(Vec2f uv, const SampledWavelengths &lambda) const {
    return scale_ * RGBIlluminantSpectrum(*color_space_, pixel(uv)).sample(lambda);
}

SampledSpectrum ImageInfiniteLight::Le(const Ray &ray, const SampledWavelengths &lambda) const {
    Vec3f w_light = normalize(light_from_render_.apply_vector(ray.d));
    return radiance(uv_of(w_light), lambda);
}

SampledSpectrum ImageInfiniteLight::phi(const SampledWavelengths &lambda) const {
    // Radiance integrated over directions (the pixels' solid angles), times the area of the disk
    // through which it reaches the scene.
    SampledSpectrum sum;
    for (int y = 0; y < image_.height; ++y) {
        float solid_angle = mapping_ == EnvironmentMapping::EqualArea
                                ? 4 * Pi / (float(image_.width) * image_.height)
                                : equirect_pixel_solid_angle(y, image_.width, image_.height);
        SampledSpectrum row;
        for (int x = 0; x < image_.width; ++x)
            row += RGBIlluminantSpectrum(*color_space_, pixel_rgb(image_, x, y)).sample(lambda);
        sum += row * solid_angle;
    }
    return scale_ * scene_.disk_area() * sum;
}

std::optional<LightLiSample> ImageInfiniteLight::sample_li(const LightSampleContext &ctx, Vec2f u,
                                                           const SampledWavelengths &lambda) const {
    float map_pdf;
    Vec2f uv = distribution_.sample(u, &map_pdf);
    float jacobian = solid_angle_per_uv(uv);
    if (!(map_pdf > 0) || !(jacobian > 0)) return {};
    LightLiSample s;
    s.wi = normalize(render_from_light_.apply_vector(direction_at(uv)));
    s.pdf = map_pdf / jacobian;
    s.L = radiance(uv, lambda);
    s.p_light = ctx.p + s.wi * (2 * scene_.radius);
    s.is_infinite = true;
    return s;
}

float ImageInfiniteLight::pdf_li(const LightSampleContext &, Vec3f wi) const {
    Vec2f uv = uv_of(normalize(light_from_render_.apply_vector(wi)));
    float jacobian = solid_angle_per_uv(uv);
    return jacobian > 0 ? distribution_.pdf(uv) / jacobian : 0.f;
}

std::optional<LightLeSample> ImageInfiniteLight::sample_le(Vec2f u1, Vec2f u2,
                                                           const SampledWavelengths &lambda) const {
    if (scene_.radius <= 0) return {};
    float map_pdf;
    Vec2f uv = distribution_.sample(u1, &map_pdf);
    float jacobian = solid_angle_per_uv(uv);
    if (!(map_pdf > 0) || !(jacobian > 0)) return {};
    // Light arrives from direction_at(uv): the emitted ray travels the opposite way.
    Vec3f w = -normalize(render_from_light_.apply_vector(direction_at(uv)));
    LightLeSample s;
    s.ray = scene_.ray_into(w, u2);
    s.L = radiance(uv, lambda);
    s.pdf_pos = scene_.disk_pdf();
    s.pdf_dir = map_pdf / jacobian;
    return s;
}

void ImageInfiniteLight::pdf_le(const Ray &ray, Vec3f, float *pdf_pos, float *pdf_dir) const {
    Vec2f uv = uv_of(-normalize(light_from_render_.apply_vector(ray.d)));
    float jacobian = solid_angle_per_uv(uv);
    *pdf_dir = jacobian > 0 ? distribution_.pdf(uv) / jacobian : 0.f;
    *pdf_pos = scene_.disk_pdf();
}

float ImageInfiniteLight::pbrt_illuminance_normalization(const RGBImage &image,
                                                         EnvironmentMapping mapping,
                                                         RGB luminance_weights) {
    double sum = 0;
    for (int y = 0; y < image.height; ++y) {
        float v = (y + 0.5f) / image.height;
        // Half of each pixel's solid angle (see the header).
        float half_solid_angle = mapping == EnvironmentMapping::EqualArea
                                     ? 2 * Pi / (float(image.width) * image.height)
                                     : equirect_pixel_solid_angle(y, image.width, image.height) / 2;
        for (int x = 0; x < image.width; ++x) {
            Vec3f w = mapping_direction(mapping, {(x + 0.5f) / image.width, v});
            if (w.z <= 0) continue;
            sum += luminance(raw_pixel(image, x, y), luminance_weights) * w.z * half_solid_angle;
        }
    }
    return float(sum);
}

}  // namespace caustica
