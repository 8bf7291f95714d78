#include "lights/spot_light.h"

#include "core/sampling.h"

namespace caustica {

float smooth_step(float x, float a, float b) {
    if (a == b) return x < a ? 0 : 1;
    float t = clamp((x - a) / (b - a), 0.f, 1.f);
    return t * t * (3 - 2 * t);
}

// The smoothstep integrates to (b - a) / 2 over [a, b].
float smooth_step_pdf(float x, float a, float b) {
    if (x < a || x > b || a == b) return 0;
    return 2 * smooth_step(x, a, b) / (b - a);
}

float sample_smooth_step(float u, float a, float b) {
    // The CDF in t = (x - a) / (b - a) is 2 t^3 - t^4, monotonic on [0, 1]: invert it by Newton
    // steps safeguarded by bisection.
    float lo = 0, hi = 1, t = 0.5f;
    for (int i = 0; i < 30; ++i) {
        float f = 2 * t * t * t - t * t * t * t - u;
        if (std::abs(f) < 1e-7f) break;
        if (f < 0)
            lo = t;
        else
            hi = t;
        float df = 6 * t * t - 4 * t * t * t;
        float next = df > 0 ? t - f / df : -1.f;
        t = (next > lo && next < hi) ? next : 0.5f * (lo + hi);
    }
    return a + t * (b - a);
}

SpotLight::SpotLight(const Transform &render_from_light, SpectrumPtr intensity, float scale,
                     float total_width_degrees, float falloff_start_degrees)
    : PointSourceLight(render_from_light.apply_point({0, 0, 0})),
      render_from_light_(render_from_light),
      light_from_render_(render_from_light.inverse()),
      intensity_(std::move(intensity)),
      scale_(scale),
      cos_falloff_end_(std::cos(radians(total_width_degrees))),
      cos_falloff_start_(std::cos(radians(falloff_start_degrees))) {}

SampledSpectrum SpotLight::intensity(Vec3f w_light, const SampledWavelengths &lambda) const {
    return smooth_step(cos_theta(w_light), cos_falloff_end_, cos_falloff_start_) * scale_ *
           intensity_->sample(lambda);
}

EmissionDirections SpotLight::emission_directions() const {
    const Vec3f axis = normalize(render_from_light_.apply_vector({0, 0, 1}));
    const float theta_e = std::acos(cos_falloff_end_) - std::acos(cos_falloff_start_) + DirectionCone::RoundingMargin;
    return {{axis, cos_falloff_start_}, std::cos(std::min(theta_e, Pi)), false};
}

SampledSpectrum SpotLight::phi(const SampledWavelengths &lambda) const {
    // Integral over the sphere of the angular profile: 2 pi (cone + falloff ring).
    return scale_ * intensity_->sample(lambda) * 2 * Pi * (cone_weight() + falloff_weight());
}

std::optional<LightLeSample> SpotLight::sample_le(Vec2f u1, Vec2f u2,
                                                  const SampledWavelengths &lambda) const {
    // Choose the cone or the falloff ring in proportion to their power, then sample the
    // direction within it: uniformly in the cone, by the smoothstep profile in the ring.
    float total = cone_weight() + falloff_weight();
    if (!(total > 0)) return {};  // a zero-width spot emits nothing
    float p_cone = cone_weight() / total;
    Vec3f w_light;
    float pdf_dir;
    if (u2.x < p_cone) {
        w_light = sample_uniform_cone(u1, cos_falloff_start_);
        pdf_dir = uniform_cone_pdf(cos_falloff_start_) * p_cone;
    } else {
        float cos_t = sample_smooth_step(u1.x, cos_falloff_end_, cos_falloff_start_);
        float sin_t = safe_sqrt(1 - cos_t * cos_t);
        w_light = spherical_direction(sin_t, cos_t, 2 * Pi * u1.y);
        pdf_dir =
            smooth_step_pdf(cos_t, cos_falloff_end_, cos_falloff_start_) * (1 - p_cone) / (2 * Pi);
    }
    if (pdf_dir == 0) return {};
    LightLeSample s;
    s.ray = {position_, normalize(render_from_light_.apply_vector(w_light)), Infinity};
    s.L = intensity(w_light, lambda);
    s.pdf_pos = 1;
    s.pdf_dir = pdf_dir;
    return s;
}

void SpotLight::pdf_le(const Ray &ray, Vec3f, float *pdf_pos, float *pdf_dir) const {
    *pdf_pos = 0;
    *pdf_dir = 0;
    float total = cone_weight() + falloff_weight();
    if (!(total > 0)) return;
    float p_cone = cone_weight() / total;
    float cos_t = cos_theta(normalize(light_from_render_.apply_vector(ray.d)));
    if (cos_t >= cos_falloff_start_)
        *pdf_dir = uniform_cone_pdf(cos_falloff_start_) * p_cone;
    else
        *pdf_dir =
            smooth_step_pdf(cos_t, cos_falloff_end_, cos_falloff_start_) * (1 - p_cone) / (2 * Pi);
}

}  // namespace caustica
