#include "lights/point_source_light.h"

namespace caustica {

std::optional<LightLiSample> PointSourceLight::sample_li(const LightSampleContext &ctx, Vec2f,
                                                         const SampledWavelengths &lambda) const {
    const Vec3f to_light = position_ - ctx.p;
    const float d2 = length_squared(to_light);
    if (d2 == 0) return {};
    LightLiSample s;
    s.wi = to_light / std::sqrt(d2);
    // Irradiance on a surface facing the light: I / r^2 (the cosine is the integrator's).
    s.L = intensity_towards(-s.wi, lambda) / d2;
    if (s.L.is_black()) return {};
    s.pdf = 1;
    s.p_light = position_;
    return s;
}

}  // namespace caustica
