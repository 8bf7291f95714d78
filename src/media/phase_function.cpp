#include "media/phase_function.h"

#include <cmath>

namespace caustica {

float HenyeyGreenstein::density(float cos_theta) const {
    float denominator = 1 + g_ * g_ - 2 * g_ * cos_theta;
    return Inv4Pi * (1 - g_ * g_) / (denominator * std::sqrt(std::max(denominator, 1e-12f)));
}

PhaseSample HenyeyGreenstein::sample_p(Vec3f wo, Vec2f u) const {
    // Inverting the CDF of cos(theta) (Pharr et al., "Physically Based Rendering", 4th ed.,
    // section 11.3.1).
    float cos_theta;
    if (g_ == 0) {
        cos_theta = 1 - 2 * u.x;
    } else {
        float s = (1 - g_ * g_) / (1 + g_ - 2 * g_ * u.x);
        cos_theta = std::clamp((1 + g_ * g_ - s * s) / (2 * g_), -1.f, 1.f);
    }
    float sin_theta = std::sqrt(std::max(0.f, 1 - cos_theta * cos_theta));
    float phi = 2 * Pi * u.y;
    // cos_theta is measured from the propagation direction -wo.
    Vec3f forward = -wo, s, t;
    coordinate_system(forward, &s, &t);
    Vec3f wi = normalize(s * (sin_theta * std::cos(phi)) + t * (sin_theta * std::sin(phi)) + forward * cos_theta);
    return {density(cos_theta), wi};
}

} // namespace caustica
