#include "integrators/common/merge_radius.h"

#include "film/film.h"
#include "scene/scene.h"

#include <algorithm>
#include <optional>
#include <vector>

namespace caustica {

namespace {

// The distance along ray to the first surface that is not a bare boundary between media, or
// nothing if there is none.
std::optional<float> first_surface_distance(const Scene &scene, Ray ray) {
    constexpr int MaxBoundaries = 16;
    float travelled = 0;
    for (int crossing = 0; crossing < MaxBoundaries; ++crossing) {
        SurfaceInteraction si;
        if (!scene.intersect(ray, &si)) return std::nullopt;
        const float t = si.t * length(ray.d);
        if (si.material || si.area_light) return travelled + t;
        travelled += t;
        ray = si.spawn_ray(ray.d);
    }
    return travelled;
}

// The width of one pixel at the median distance of the surfaces seen through a grid of pixels
// (rays that escape are left out: a sky says nothing about the scale of what is rendered): the
// distance between the rays of two neighbouring pixels there, for any camera model. Zero when
// the camera sees nothing.
float median_pixel_footprint(const Scene &scene) {
    constexpr int Grid = 16;
    const SampledWavelengths lambda = SampledWavelengths::fixed(550);
    const Vec2i resolution = scene.film->resolution();
    std::vector<float> footprints;
    for (int j = 0; j < Grid; ++j)
        for (int i = 0; i < Grid; ++i) {
            CameraSample a, b;
            a.p_film = {(i + 0.5f) * resolution.x / Grid, (j + 0.5f) * resolution.y / Grid};
            b.p_film = a.p_film + Vec2f{1, 0};
            a.p_lens = b.p_lens = {0.5f, 0.5f};
            const std::optional<CameraRay> ra = scene.camera->generate_ray(a, lambda);
            const std::optional<CameraRay> rb = scene.camera->generate_ray(b, lambda);
            if (!ra || !rb) continue;
            const std::optional<float> d = first_surface_distance(scene, ra->ray);
            if (!d) continue;
            const Vec3f da = normalize(ra->ray.d), db = normalize(rb->ray.d);
            footprints.push_back(length(ra->ray.o + da * *d - (rb->ray.o + db * *d)));
        }
    if (footprints.empty()) return 0;
    std::nth_element(footprints.begin(), footprints.begin() + footprints.size() / 2, footprints.end());
    return footprints[footprints.size() / 2];
}

} // namespace

float default_merge_radius(const Scene &scene) {
    Vec3f center;
    float scene_radius = 0;
    scene.geometry.bounds().bounding_sphere(&center, &scene_radius);
    const Vec2i full = scene.film->resolution();
    const float from_bounds = 0.003f * scene_radius * 512.f / float(std::max({full.x, full.y, 1}));
    const float footprint = median_pixel_footprint(scene);
    return footprint > 0 ? std::min(from_bounds, 3 * footprint) : from_bounds;
}

float default_medium_merge_radius(const Scene &scene, float surface_radius) {
    constexpr int Samples = 8;
    float largest_sigma_t = 0;
    for (const MediumPtr &medium : scene.media)
        for (int i = 0; i < Samples; ++i) {
            const SampledWavelengths lambda = SampledWavelengths::sample_visible((i + 0.5f) / Samples);
            largest_sigma_t = std::max(largest_sigma_t, medium->max_sigma_t(lambda).max_value());
        }
    return largest_sigma_t > 0 ? std::min(surface_radius, 0.1f / largest_sigma_t) : surface_radius;
}

} // namespace caustica
