#include "camera/orthographic_camera.h"

#include "core/sampling.h"

namespace caustica {

// pbrt-v4 projects with Orthographic(0, 1), which maps z in [0, 1] onto itself: screen space
// and camera space coincide.
OrthographicCamera::OrthographicCamera(const Transform &world_from_camera, const FilmExtent &film,
                                       const ScreenWindow &screen, float lens_radius,
                                       float focal_distance)
    : ProjectiveCamera(world_from_camera, Transform(), screen, film, lens_radius, focal_distance) {}

std::optional<CameraRay> OrthographicCamera::ray_at_rest(const CameraSample &sample,
                                                          const SampledWavelengths &) const {
    Vec3f o = camera_from_raster_.apply_point({sample.p_film.x, sample.p_film.y, 0});
    Vec3f d{0, 0, 1};
    if (lens_radius_ > 0) {
        // pbrt-v4's construction, kept as is so images match: the ray leaves the lens point and
        // passes through the film point's position on the plane of focus.
        Vec2f lens = sample_uniform_disk_concentric(sample.p_lens) * lens_radius_;
        Vec3f p_focus = o + d * focal_distance_;
        o = {lens.x, lens.y, 0};
        d = normalize(p_focus - o);
    }
    CameraRay cr;
    cr.ray.o = world_from_camera_.apply_point(o);
    cr.ray.d = normalize(world_from_camera_.apply_vector(d));
    return cr;
}

SampledSpectrum OrthographicCamera::we_at_rest(const Ray &, const SampledWavelengths &, Vec2f *) const {
    return SampledSpectrum(0.f);
}

void OrthographicCamera::pdf_we_at_rest(const Ray &, float *pdf_pos, float *pdf_dir) const {
    *pdf_pos = *pdf_dir = 0;
}

std::optional<CameraWiSample> OrthographicCamera::sample_wi_at_rest(Vec3f, Vec2f,
                                                            const SampledWavelengths &) const {
    return std::nullopt;
}

} // namespace caustica
