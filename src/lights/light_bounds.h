// What a light sampler may know about a light without sampling it: where it is, how much it
// emits, and towards which directions (Conty Estevez and Kulla 2018, "Importance Sampling of Many
// Lights with Adaptive Tree Splitting", section 4; pbrt-v4's LightBounds). From these, an upper
// estimate of the light's contribution at a receiving point, its importance, which is zero only
// where the light cannot contribute at all: a light sampler that chooses lights in proportion to
// it never leaves out a light that could light the point.
#pragma once

#include "core/vecmath.h"
#include "geometry/direction_cone.h"
#include "lights/light.h"

#include <optional>

namespace caustica {

struct LightBounds {
    Bounds3f bounds;
    float phi = 0; // emitted power; none: an empty node
    EmissionDirections directions;

    static LightBounds make(const Bounds3f &bounds, float phi, const EmissionDirections &directions);

    // The light's estimated contribution at p, received about the unit normal n (zero: a point in
    // a medium, which receives from every direction alike): phi over the squared distance to the
    // bounds' centre (clamped as pbrt-v4 does, light_bounds.cpp), times the largest cosine that any point
    // of the bounds can have towards p from its emission cone, and the largest cosine at p
    // towards any point of the bounds. Zero only when no point of the bounds emits towards p, or
    // all of them lie in the receiver's tangent plane.
    // At most MaxImportance, so that sums of a few importances stay finite.
    float importance(Vec3f p, Vec3f n) const;
    static constexpr float MaxImportance = 1e30f;

  private:
    // What importance() needs of the above, computed once: the bounding sphere, and the normal
    // cone's half-angle.
    Vec3f centre_;
    float radius_ = 0;
    float cos_o_ = -1, sin_o_ = 0;
};

// True when a and b hold the same bounds, power and directions, so that their importance is the
// same at every point: two triangles of an axis-aligned rectangle are such a pair.
bool same_bounds(const LightBounds &a, const LightBounds &b);

// Bounds of both lights' bounds together (a tree node's).
LightBounds bounds_union(const LightBounds &a, const LightBounds &b);

// A light's bounds, with phi its power (light_power); none for lights at infinity and those that
// emit no power.
std::optional<LightBounds> light_bounds(const Light &light);

} // namespace caustica
