// pbrt-v4's AnimatedTransform: the placement of a shape or an object instance that moves from
// `start` at the scene's first TransformTimes time to `end` at its second (ActiveTransform picks
// which of the two a transform directive changes). Between the two the geometry interpolates
// (geometry/embree_scene.h says how); before the first time and after the second it rests.
#pragma once

#include "core/transform.h"

namespace caustica {

struct AnimatedTransform {
    Transform start, end;

    AnimatedTransform() = default;
    AnimatedTransform(const Transform &still) : start(still), end(still) {}
    AnimatedTransform(const Transform &at_start, const Transform &at_end) : start(at_start), end(at_end) {}

    bool is_animated() const { return !(start == end); }
};

// The scene's TransformTimes: when `start` and `end` apply. pbrt-v4's defaults.
struct TransformTimes {
    float start = 0, end = 1;

    // Where time t lies between them, clamped to [0, 1] (0 when they coincide).
    float fraction(float t) const {
        if (!(end > start)) return 0;
        const float f = (t - start) / (end - start);
        return f < 0 ? 0 : (f > 1 ? 1 : f);
    }
};

} // namespace caustica
