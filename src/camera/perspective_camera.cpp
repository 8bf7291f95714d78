#include "camera/perspective_camera.h"

#include "core/sampling.h"

namespace caustica {

PerspectiveCamera::PerspectiveCamera(const Transform &world_from_camera, const FilmExtent &film,
                                     float fov, const ScreenWindow &screen, float lens_radius,
                                     float focal_distance)
    : ProjectiveCamera(world_from_camera, Transform::perspective(fov, 1e-2f, 1000.f), screen, film,
                       lens_radius, focal_distance) {
    // The film corner grown by the filter radius is the farthest any contribution can land.
    Vec3f corner = normalize(camera_from_raster_.apply_point(
        {-film.filter_radius.x, -film.filter_radius.y, 0}));
    cos_total_width_ = corner.z;

    Vec3f p_min = camera_from_raster_.apply_point({0, 0, 0});
    Vec3f p_max = camera_from_raster_.apply_point(
        {float(film.full_resolution.x), float(film.full_resolution.y), 0});
    p_min = p_min / p_min.z;
    p_max = p_max / p_max.z;
    image_area_ = std::abs((p_max.x - p_min.x) * (p_max.y - p_min.y));
}

std::optional<CameraRay> PerspectiveCamera::ray_at_rest(const CameraSample &sample,
                                                         const SampledWavelengths &) const {
    Vec3f p_camera = camera_from_raster_.apply_point({sample.p_film.x, sample.p_film.y, 0});
    Vec3f o{0, 0, 0};
    Vec3f d = normalize(p_camera);
    if (lens_radius_ > 0) {
        // Every ray through the lens from this film point meets the pinhole ray on the plane of
        // focus.
        Vec2f lens = sample_uniform_disk_concentric(sample.p_lens) * lens_radius_;
        Vec3f p_focus = d * (focal_distance_ / d.z);
        o = {lens.x, lens.y, 0};
        d = normalize(p_focus - o);
    }
    CameraRay cr;
    cr.ray.o = world_from_camera_.apply_point(o);
    cr.ray.d = normalize(world_from_camera_.apply_vector(d));
    return cr;
}

bool PerspectiveCamera::project(const Ray &ray, float *cos_theta, Vec2f *p_raster) const {
    *cos_theta = dot(ray.d, forward_);
    if (*cos_theta <= cos_total_width_) return false;
    // The point the ray reaches on the plane of focus (z = 1 for a pinhole, where every plane
    // gives the same raster position) maps back to the film.
    Vec3f p_focus = ray.at((lens_radius_ > 0 ? focal_distance_ : 1) / *cos_theta);
    Vec3f p = raster_from_camera_.apply_point(camera_from_world_.apply_point(p_focus));
    *p_raster = {p.x, p.y};
    return inside_sample_bounds(*p_raster);
}

SampledSpectrum PerspectiveCamera::we_at_rest(const Ray &ray, const SampledWavelengths &,
                                      Vec2f *p_raster) const {
    float cos_theta;
    Vec2f p;
    bool inside = project(ray, &cos_theta, &p);
    if (p_raster && cos_theta > cos_total_width_) *p_raster = p;
    if (!inside) return SampledSpectrum(0.f);
    // Uniform over the lens and over the image plane at z = 1; the density of a direction per
    // unit image-plane area is cos^3, and one more cosine converts radiance to irradiance.
    return SampledSpectrum(1 / (image_area_ * lens_area() * sqr(sqr(cos_theta))));
}

void PerspectiveCamera::pdf_we_at_rest(const Ray &ray, float *pdf_pos, float *pdf_dir) const {
    float cos_theta;
    Vec2f p;
    if (!project(ray, &cos_theta, &p)) {
        *pdf_pos = *pdf_dir = 0;
        return;
    }
    *pdf_pos = 1 / lens_area();
    *pdf_dir = 1 / (image_area_ * cos_theta * cos_theta * cos_theta);
}

std::optional<CameraWiSample> PerspectiveCamera::sample_wi_at_rest(Vec3f ref, Vec2f u,
                                                           const SampledWavelengths &lambda) const {
    Vec2f lens = sample_uniform_disk_concentric(u) * lens_radius_;
    Vec3f p_lens = world_from_camera_.apply_point({lens.x, lens.y, 0});
    Vec3f wi = p_lens - ref;
    float dist = length(wi);
    if (!(dist > 0)) return std::nullopt;
    wi = wi / dist;
    // Uniform density over the lens area, converted to solid angle at ref.
    float pdf = sqr(dist) / (abs_dot(forward_, wi) * lens_area());
    Vec2f p_raster;
    SampledSpectrum importance = we_at_rest(Ray{p_lens, -wi}, lambda, &p_raster);
    if (importance.is_black() || !std::isfinite(pdf)) return std::nullopt;
    return CameraWiSample{importance, wi, pdf, p_raster, p_lens, forward_};
}

} // namespace caustica
