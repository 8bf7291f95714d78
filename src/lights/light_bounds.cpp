#include "lights/light_bounds.h"

#include "lights/spectral_power.h"

#include <algorithm>
#include <cmath>

namespace caustica {

namespace {

// cos(max(0, a - b)) and sin(max(0, a - b)) of angles in [0, pi] from their sines and cosines.
float cos_difference_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    if (cos_a > cos_b) return 1; // a < b
    return cos_a * cos_b + sin_a * sin_b;
}
float sin_difference_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    if (cos_a > cos_b) return 0;
    return sin_a * cos_b - cos_a * sin_b;
}

bool inside_box(const Bounds3f &b, Vec3f p) {
    return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y && p.z >= b.lo.z && p.z <= b.hi.z;
}

} // namespace

LightBounds LightBounds::make(const Bounds3f &bounds, float phi, const EmissionDirections &directions) {
    LightBounds b;
    b.bounds = bounds;
    b.phi = phi;
    b.directions = directions;
    bounds.bounding_sphere(&b.centre_, &b.radius_);
    b.cos_o_ = std::clamp(directions.normals.cos_theta, -1.f, 1.f);
    b.sin_o_ = safe_sqrt(1 - b.cos_o_ * b.cos_o_);
    return b;
}

float LightBounds::importance(Vec3f p, Vec3f n) const {
    const Vec3f to_centre = centre_ - p;
    const float distance2 = length_squared(to_centre);
    // Inside the bounds any light point may be arbitrarily near, so the squared distance is taken
    // no smaller than the bounds' radius (pbrt-v4's clamp, a length, not the radius squared: it
    // depends on the scene's unit, but it keeps the same choice as pbrt-v4 on the same file, and
    // it damps the preference for lamps a hair away, which light receivers nearby only partly).
    const float d2 = std::max(distance2, radius_);
    if (!(d2 > 0)) return phi > 0 ? MaxImportance : 0.f;
    const float inv_distance = distance2 > 0 ? 1 / std::sqrt(distance2) : 0.f;

    // theta_b: the half-angle of a cone from p about the direction to the centre that holds the
    // bounds: the bounding sphere's, or where p lies inside that sphere but outside the box, the
    // widest direction to a corner (the box is convex, so a cone narrower than a hemisphere that
    // holds its corners holds it all); every direction when p lies inside the box.
    const float sin2_b = radius_ * radius_ / distance2;
    float cos_b = -1, sin_b = 0;
    if (sin2_b < 1) {
        cos_b = std::sqrt(1 - sin2_b);
        sin_b = radius_ * inv_distance;
    } else if (!inside_box(bounds, p)) {
        const Vec3f axis = to_centre * inv_distance;
        float widest = 1;
        for (int i = 0; i < 8; ++i) {
            const Vec3f corner{i & 1 ? bounds.hi.x : bounds.lo.x, i & 2 ? bounds.hi.y : bounds.lo.y,
                               i & 4 ? bounds.hi.z : bounds.lo.z};
            widest = std::min(widest, dot(axis, normalize(corner - p)));
        }
        // A margin for rounding (DirectionCone::RoundingMargin).
        if (widest > 1e-3f) {
            cos_b = std::cos(std::acos(widest) + DirectionCone::RoundingMargin);
            sin_b = safe_sqrt(1 - cos_b * cos_b);
        }
    }
    const bool inside = cos_b == -1;

    // theta_w: from the normals' axis to the direction from the light to p; theta' = theta_w -
    // theta_o - theta_b is the least angle between any emitting normal and the direction from any
    // point of the bounds to p.
    const Vec3f wi = distance2 > 0 ? to_centre * -inv_distance : Vec3f{0, 0, 1};
    float cos_w = dot(directions.normals.w, wi);
    if (directions.two_sided) cos_w = std::abs(cos_w);
    const float sin_w = safe_sqrt(1 - cos_w * cos_w);
    const float cos_o = cos_o_, sin_o = sin_o_;
    // Inside the bounds, some emitter may face p whatever the cone.
    float cos_prime = 1;
    if (!inside) {
        const float cos_x = cos_difference_clamped(sin_w, cos_w, sin_o, cos_o);
        const float sin_x = sin_difference_clamped(sin_w, cos_w, sin_o, cos_o);
        cos_prime = cos_difference_clamped(sin_x, cos_x, sin_b, cos_b);
    }
    if (cos_prime <= directions.cos_theta_e) return 0;

    float importance = phi * cos_prime / d2;
    // The receiver's cosine, at its largest over the directions towards the bounds.
    if (n != Vec3f{} && !inside) {
        const float cos_i = abs_dot(wi, n), sin_i = safe_sqrt(1 - cos_i * cos_i);
        importance *= cos_difference_clamped(sin_i, cos_i, sin_b, cos_b);
    }
    return std::clamp(importance, 0.f, MaxImportance);
}

bool same_bounds(const LightBounds &a, const LightBounds &b) {
    const EmissionDirections &da = a.directions, &db = b.directions;
    return a.bounds.lo == b.bounds.lo && a.bounds.hi == b.bounds.hi && a.phi == b.phi &&
           da.normals.w == db.normals.w && da.normals.cos_theta == db.normals.cos_theta &&
           da.cos_theta_e == db.cos_theta_e && da.two_sided == db.two_sided;
}

LightBounds bounds_union(const LightBounds &a, const LightBounds &b) {
    if (a.phi == 0) return b;
    if (b.phi == 0) return a;
    Bounds3f bounds = a.bounds;
    bounds.expand(b.bounds.lo);
    bounds.expand(b.bounds.hi);
    const EmissionDirections directions{cone_union(a.directions.normals, b.directions.normals),
                                        std::min(a.directions.cos_theta_e, b.directions.cos_theta_e),
                                        a.directions.two_sided || b.directions.two_sided};
    return LightBounds::make(bounds, a.phi + b.phi, directions);
}

std::optional<LightBounds> light_bounds(const Light &light) {
    const std::optional<Bounds3f> bounds = light.spatial_bounds();
    if (!bounds || bounds->empty()) return std::nullopt;
    const float phi = light_power(light);
    if (!(phi > 0) || !std::isfinite(phi)) return std::nullopt;
    return LightBounds::make(*bounds, phi, light.emission_directions());
}

} // namespace caustica
