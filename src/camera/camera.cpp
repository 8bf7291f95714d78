#include "camera/camera.h"

#include <cmath>

namespace caustica {

bool Camera::set_motion(const AnimatedTransform &world_from_camera, TransformTimes times) {
    // Rigid when the two placements share their scale and skew: every placement between them is
    // then the start's turned and moved.
    const AffineFactors a = factor_affine(world_from_camera.start.matrix()),
                        b = factor_affine(world_from_camera.end.matrix());
    const float sa[6] = {a.s00, a.s01, a.s02, a.s11, a.s12, a.s22}, sb[6] = {b.s00, b.s01, b.s02, b.s11, b.s12, b.s22};
    for (int i = 0; i < 6; ++i)
        if (!(std::abs(sa[i] - sb[i]) <= 1e-4f * (1 + std::abs(sa[i])))) return false;
    motion_ = world_from_camera;
    start_factors_ = a;
    end_factors_ = b;
    rest_from_world_ = world_from_camera.start.inverse();
    times_ = times;
    moves_ = world_from_camera.is_animated();
    return true;
}

Transform Camera::moved_at(float time) const {
    const float u = times_.fraction(time);
    if (!moves_ || u <= 0) return Transform();
    if (u >= 1) return motion_.end * rest_from_world_;
    return interpolate(start_factors_, end_factors_, u) * rest_from_world_;
}

namespace {

Ray transformed(const Transform &t, const Ray &ray) {
    Ray r = ray;
    r.o = t.apply_point(ray.o);
    r.d = t.apply_vector(ray.d);
    return r;
}

} // namespace

std::optional<CameraRay> Camera::generate_ray(const CameraSample &sample, const SampledWavelengths &lambda) const {
    std::optional<CameraRay> r = ray_at_rest(sample, lambda);
    if (!r) return r;
    if (moves()) r->ray = transformed(moved_at(sample.time), r->ray);
    r->ray.time = sample.time;
    return r;
}

SampledSpectrum Camera::We(const Ray &ray, const SampledWavelengths &lambda, Vec2f *p_raster) const {
    if (!moves()) return we_at_rest(ray, lambda, p_raster);
    return we_at_rest(transformed(moved_at(ray.time).inverse(), ray), lambda, p_raster);
}

void Camera::pdf_we(const Ray &ray, float *pdf_pos, float *pdf_dir) const {
    if (!moves()) return pdf_we_at_rest(ray, pdf_pos, pdf_dir);
    pdf_we_at_rest(transformed(moved_at(ray.time).inverse(), ray), pdf_pos, pdf_dir);
}

std::optional<CameraWiSample> Camera::sample_wi(Vec3f ref, Vec2f u, const SampledWavelengths &lambda,
                                                float time) const {
    if (!moves()) return sample_wi_at_rest(ref, u, lambda);
    const Transform moved = moved_at(time);
    std::optional<CameraWiSample> s = sample_wi_at_rest(moved.inverse().apply_point(ref), u, lambda);
    if (!s) return s;
    s->wi = normalize(moved.apply_vector(s->wi));
    s->p_lens = moved.apply_point(s->p_lens);
    if (s->n_lens != Vec3f{}) s->n_lens = normalize(moved.apply_normal(s->n_lens));
    return s;
}

} // namespace caustica
