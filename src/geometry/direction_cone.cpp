#include "geometry/direction_cone.h"

#include <algorithm>
#include <cmath>

namespace caustica {

namespace {

// The angle between unit vectors, accurate near 0 and pi too (from the chord, not the cosine).
float angle_between(Vec3f a, Vec3f b) {
    if (dot(a, b) < 0) return Pi - 2 * std::asin(std::min(1.f, length(a + b) / 2));
    return 2 * std::asin(std::min(1.f, length(b - a) / 2));
}

} // namespace

DirectionCone cone_union(const DirectionCone &a, const DirectionCone &b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    const float theta_a = safe_acos(a.cos_theta), theta_b = safe_acos(b.cos_theta);
    const float theta_d = angle_between(a.w, b.w);
    // One cone inside the other.
    if (std::min(theta_d + theta_b, Pi) <= theta_a) return a;
    if (std::min(theta_d + theta_a, Pi) <= theta_b) return b;
    // The spread from a's far edge to b's far edge, halved, about an axis turned from a.w towards
    // b.w by what that half-angle exceeds theta_a.
    // A thousandth of a radian wider, so that rounding never leaves a direction of a or b out.
    const float theta_o = (theta_a + theta_d + theta_b) / 2 + DirectionCone::RoundingMargin;
    if (theta_o >= Pi) return DirectionCone::entire_sphere();
    const float theta_r = (theta_d + theta_b - theta_a) / 2;
    const Vec3f axis = cross(a.w, b.w);
    if (length_squared(axis) == 0) return DirectionCone::entire_sphere();
    // Rodrigues' rotation of a.w about the unit axis, which is orthogonal to it.
    const Vec3f k = normalize(axis);
    const Vec3f w = a.w * std::cos(theta_r) + cross(k, a.w) * std::sin(theta_r);
    return {normalize(w), std::cos(theta_o)};
}

} // namespace caustica
