#include "geometry/shape.h"

namespace caustica {

// Converting an area density to solid angle at ref: dA = r^2 / |cos theta_light| dw.
std::optional<ShapeSample> Shape::sample(Vec3f ref, Vec2f u) const {
    std::optional<ShapeSample> ss = sample(u);
    if (!ss) return std::nullopt;
    Vec3f wi = ss->p - ref;
    float dist2 = length_squared(wi);
    if (dist2 == 0) return std::nullopt;
    wi = wi / std::sqrt(dist2);
    float cos_light = abs_dot(ss->n, wi);
    if (cos_light == 0) return std::nullopt;
    ss->pdf *= dist2 / cos_light;
    if (!std::isfinite(ss->pdf)) return std::nullopt;
    return ss;
}

float Shape::pdf(Vec3f ref, Vec3f wi) const {
    std::optional<Hit> hit = intersect(ref, wi, Infinity);
    if (!hit) return 0;
    float cos_light = abs_dot(hit->n, normalize(wi));
    if (cos_light == 0) return 0;
    float pdf = distance_squared(ref, hit->p) / (cos_light * area());
    return std::isfinite(pdf) ? pdf : 0;
}

} // namespace caustica
