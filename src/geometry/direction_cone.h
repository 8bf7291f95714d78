// A cone of directions: those within angle theta of a unit axis (pbrt-v4's DirectionCone). Light
// samplers bound the normals of an emitter with one (lights/light_bounds.h).
#pragma once

#include "core/vecmath.h"

namespace caustica {

// cos_theta = -1 is every direction; an empty cone has cos_theta = +Infinity.
struct DirectionCone {
    Vec3f w{0, 0, 1};
    float cos_theta = Infinity;

    static DirectionCone entire_sphere() { return {{0, 0, 1}, -1.f}; }
    // The angle (radians) by which bounds on directions are widened, so that float rounding
    // never leaves out a direction they should hold.
    static constexpr float RoundingMargin = 1e-3f;
    bool empty() const { return cos_theta == Infinity; }
};

// The smallest cone around both cones whose axis lies in the plane of their axes (pbrt-v4's
// Union, after Conty Estevez and Kulla 2018, algorithm 1).
DirectionCone cone_union(const DirectionCone &a, const DirectionCone &b);

} // namespace caustica
