#include "lights/portal_infinite_light.h"

#include "lights/equal_area_mapping.h"
#include "spectral/color_space.h"
#include "spectral/rgb_spectrum.h"

#include <cmath>
#include <stdexcept>

namespace caustica {

namespace {

RGB texel(const RGBImage &image, int x, int y) {
    const float *p = image.at(x, y);
    return clamp_zero(RGB{p[0], p[1], p[2]});
}

// A texel of a square equal-area map, for integer coordinates up to one texel outside it: the
// octahedral map continues across each edge mirrored about the edge's midpoint (pbrt-v4's
// WrapMode::OctahedralSphere).
RGB octahedral_texel(const RGBImage &image, int x, int y) {
    const int n = image.width;
    if (x < 0) x = -x, y = n - 1 - y;
    else if (x >= n) x = 2 * n - 1 - x, y = n - 1 - y;
    if (y < 0) x = n - 1 - x, y = -y;
    else if (y >= n) x = n - 1 - x, y = 2 * n - 1 - y;
    return texel(image, std::clamp(x, 0, n - 1), std::clamp(y, 0, n - 1));
}

RGB bilerp_equal_area(const RGBImage &image, Vec2f uv) {
    const float x = uv.x * image.width - 0.5f, y = uv.y * image.height - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float dx = x - float(x0), dy = y - float(y0);
    return octahedral_texel(image, x0, y0) * ((1 - dx) * (1 - dy)) + octahedral_texel(image, x0 + 1, y0) * (dx * (1 - dy)) +
           octahedral_texel(image, x0, y0 + 1) * ((1 - dx) * dy) + octahedral_texel(image, x0 + 1, y0 + 1) * (dx * dy);
}

// d omega / d(u, v) of the portal parameterisation at the local direction w.
float solid_angle_per_uv_local(Vec3f w) { return Pi * Pi * (1 - w.x * w.x) * (1 - w.y * w.y) / w.z; }

bool is_unit(Vec3f v) { return std::isfinite(v.x) && std::abs(length(v) - 1) < 1e-3f; }

}  // namespace

PortalInfiniteLight::PortalInfiniteLight(const Transform &render_from_light, const RGBImage &equal_area,
                                         const RGBColorSpace &color_space, float scale,
                                         const std::array<Vec3f, 4> &portal)
    : portal_(portal), color_space_(&color_space), scale_(scale) {
    if (equal_area.width != equal_area.height)
        throw std::invalid_argument("a portal's environment map must be square (equal-area)");
    const Vec3f p01 = normalize(portal[1] - portal[0]), p12 = normalize(portal[2] - portal[1]);
    const Vec3f p32 = normalize(portal[2] - portal[3]), p03 = normalize(portal[3] - portal[0]);
    if (!is_unit(p01) || !is_unit(p12) || !is_unit(p32) || !is_unit(p03))
        throw std::invalid_argument("the portal has coincident corners");
    // Opposite sides parallel and adjacent ones perpendicular, to pbrt-v4's tolerance.
    if (std::abs(dot(p01, p32) - 1) > 1e-3f || std::abs(dot(p12, p03) - 1) > 1e-3f ||
        std::abs(dot(p01, p12)) > 1e-3f || std::abs(dot(p12, p32)) > 1e-3f || std::abs(dot(p32, p03)) > 1e-3f ||
        std::abs(dot(p03, p01)) > 1e-3f)
        throw std::invalid_argument("the portal is not a planar rectangle (its corners go around it in order)");
    frame_.x = p03;
    frame_.y = p01;
    frame_.z = normalize(cross(p03, p01));

    // Resample the environment into the portal's parameterisation at the equal-area map's
    // resolution, bilinearly as pbrt-v4 does, and weigh each texel for sampling by its mean
    // value times its solid angle (a density in uv over the solid angle per uv is then
    // proportional to the radiance).
    const Transform light_from_render = render_from_light.inverse();
    const int n = equal_area.width;
    image_.width = image_.height = n;
    image_.pixels.resize(size_t(n) * n * 3);
    std::vector<float> weights(size_t(n) * n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const Vec2f uv{(x + 0.5f) / n, (y + 0.5f) / n};
            float solid_angle;
            const Vec3f w = normalize(light_from_render.apply_vector(direction_at(uv, &solid_angle)));
            const RGB rgb = bilerp_equal_area(equal_area, equal_area_sphere_to_square(w));
            float *p = image_.at(x, y);
            p[0] = rgb.r, p[1] = rgb.g, p[2] = rgb.b;
            weights[size_t(y) * n + x] = (rgb.r + rgb.g + rgb.b) / 3 * solid_angle;
        }
    distribution_ = WindowedDistribution2D(std::move(weights), n, n);
}

void PortalInfiniteLight::preprocess(const Bounds3f &scene_bounds) { scene_ = SceneSphere::from_bounds(scene_bounds); }

float PortalInfiniteLight::area() const { return length(portal_[1] - portal_[0]) * length(portal_[3] - portal_[0]); }

Vec3f PortalInfiniteLight::direction_at(Vec2f uv, float *solid_angle_per_uv) const {
    const float alpha = -Pi / 2 + uv.x * Pi, beta = -Pi / 2 + uv.y * Pi;
    const Vec3f w = normalize(Vec3f{std::tan(alpha), std::tan(beta), 1});
    if (solid_angle_per_uv) *solid_angle_per_uv = solid_angle_per_uv_local(w);
    return frame_.from_local(w);
}

std::optional<Vec2f> PortalInfiniteLight::uv_of(Vec3f w_render, float *solid_angle_per_uv) const {
    const Vec3f w = frame_.to_local(w_render);
    if (!(w.z > 0)) return std::nullopt;
    if (solid_angle_per_uv) *solid_angle_per_uv = solid_angle_per_uv_local(w);
    const float alpha = std::atan2(w.x, w.z), beta = std::atan2(w.y, w.z);
    return Vec2f{clamp((alpha + Pi / 2) / Pi, 0.f, 1.f), clamp((beta + Pi / 2) / Pi, 0.f, 1.f)};
}

std::optional<UVWindow> PortalInfiniteLight::window_from(Vec3f p) const {
    // The parameterisation maps lines to lines, so the rectangle's image is the box spanned by
    // the images of two opposite corners.
    std::optional<Vec2f> a = uv_of(normalize(portal_[0] - p)), b = uv_of(normalize(portal_[2] - p));
    if (!a || !b) return std::nullopt;
    return UVWindow{{std::min(a->x, b->x), std::min(a->y, b->y)}, {std::max(a->x, b->x), std::max(a->y, b->y)}};
}

SampledSpectrum PortalInfiniteLight::radiance(Vec2f uv, const SampledWavelengths &lambda) const {
    // The nearest texel, as pbrt-v4 looks it up.
    const int x = std::clamp(int(uv.x * image_.width), 0, image_.width - 1);
    const int y = std::clamp(int(uv.y * image_.height), 0, image_.height - 1);
    return scale_ * RGBIlluminantSpectrum(*color_space_, texel(image_, x, y)).sample(lambda);
}

SampledSpectrum PortalInfiniteLight::Le(const Ray &ray, const SampledWavelengths &lambda) const {
    std::optional<Vec2f> uv = uv_of(normalize(ray.d));
    std::optional<UVWindow> window = window_from(ray.o);
    if (!uv || !window || !window->contains(*uv)) return SampledSpectrum(0.f);
    return radiance(*uv, lambda);
}

SampledSpectrum PortalInfiniteLight::phi(const SampledWavelengths &lambda) const {
    // Radiance integrated over the directions through the portal, times its area: the power
    // through it, were every direction to see all of it.
    SampledSpectrum sum;
    const int n = image_.width;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            float solid_angle;
            direction_at({(x + 0.5f) / n, (y + 0.5f) / n}, &solid_angle);
            sum += RGBIlluminantSpectrum(*color_space_, texel(image_, x, y)).sample(lambda) * solid_angle;
        }
    return scale_ * area() * sum / float(n * n);
}

std::optional<LightLiSample> PortalInfiniteLight::sample_li(const LightSampleContext &ctx, Vec2f u,
                                                            const SampledWavelengths &lambda) const {
    std::optional<UVWindow> window = window_from(ctx.p);
    if (!window) return std::nullopt;
    float map_pdf;
    std::optional<Vec2f> uv = distribution_.sample(u, *window, &map_pdf);
    if (!uv) return std::nullopt;
    float solid_angle;
    LightLiSample s;
    s.wi = direction_at(*uv, &solid_angle);
    if (!(solid_angle > 0)) return std::nullopt;
    s.pdf = map_pdf / solid_angle;
    s.L = radiance(*uv, lambda);
    s.p_light = ctx.p + s.wi * (2 * scene_.radius);
    s.is_infinite = true;
    return s;
}

float PortalInfiniteLight::pdf_li(const LightSampleContext &ctx, Vec3f wi) const {
    float solid_angle;
    std::optional<Vec2f> uv = uv_of(wi, &solid_angle);
    std::optional<UVWindow> window = window_from(ctx.p);
    if (!uv || !window || !window->contains(*uv) || !(solid_angle > 0)) return 0;
    return distribution_.pdf(*uv, *window) / solid_angle;
}

std::optional<LightLeSample> PortalInfiniteLight::sample_le(Vec2f u1, Vec2f u2,
                                                            const SampledWavelengths &lambda) const {
    if (scene_.radius <= 0) return std::nullopt;
    float map_pdf;
    std::optional<Vec2f> uv = distribution_.sample(u1, {{0, 0}, {1, 1}}, &map_pdf);
    if (!uv) return std::nullopt;
    float solid_angle;
    const Vec3f w = -direction_at(*uv, &solid_angle);  // the direction the light travels
    const float cos_portal = std::abs(dot(w, frame_.z));
    if (!(solid_angle > 0) || !(cos_portal > 0)) return std::nullopt;
    // A point of the portal, uniformly; the ray starts outside the scene's sphere on the line
    // through it, so that whatever lies outside the portal still casts its shadow. Per unit
    // area across the ray, the density of such points is 1 / (area cos).
    const Vec3f on_portal = portal_[0] + (portal_[1] - portal_[0]) * u2.x + (portal_[3] - portal_[0]) * u2.y;
    LightLeSample s;
    s.ray = {on_portal - w * (2 * scene_.radius + length(on_portal - scene_.center)), w, Infinity};
    s.L = radiance(*uv, lambda);
    s.pdf_pos = 1 / (area() * cos_portal);
    s.pdf_dir = map_pdf / solid_angle;
    return s;
}

void PortalInfiniteLight::pdf_le(const Ray &ray, Vec3f, float *pdf_pos, float *pdf_dir) const {
    float solid_angle;
    const Vec3f w = normalize(ray.d);
    std::optional<Vec2f> uv = uv_of(-w, &solid_angle);
    const float cos_portal = std::abs(dot(w, frame_.z));
    if (!uv || !(solid_angle > 0) || !(cos_portal > 0)) {
        *pdf_pos = *pdf_dir = 0;
        return;
    }
    *pdf_pos = 1 / (area() * cos_portal);
    *pdf_dir = distribution_.pdf(*uv, {{0, 0}, {1, 1}}) / solid_angle;
}

}  // namespace caustica
