// pbrt-v4's AnimatedTransform: the placement of a shape, an object instance or the camera that
// moves from `start` at the scene's first TransformTimes time to `end` at its second
// (ActiveTransform picks which of the two a transform directive changes). Before the first time
// and after the second it rests at the nearer end.
//
// Between the ends a placement is interpolated through its factors m = T R S (AffineFactors):
// the translation T and the upper-triangular scale-and-skew S linearly, the rotation R by
// spherical linear interpolation (Shoemake 1985). These are the factors of Embree's quaternion
// motion blur, which moves shapes and instances (geometry/embree_scene.h). pbrt-v4 factors S as
// a symmetric matrix (a polar decomposition) instead; the two agree for every motion of
// translations, rotations and uniform scales, and for non-uniform scales applied after the
// rotation (nearest the object), and differ between the ends only when a non-uniform scale is
// applied before a rotation that changes.
#pragma once

#include "core/transform.h"
#include "core/vecmath.h"

namespace caustica {

// An affine map m = T R S: T the translation, R a proper rotation (a unit quaternion w + xi + yj
// + zk) and S upper triangular, from the Gram-Schmidt QR factorisation of m's linear part. A
// mirroring m has a negative s22 (a quaternion cannot reflect).
struct AffineFactors {
    Vec3f translation;
    float w = 1, x = 0, y = 0, z = 0;
    float s00 = 1, s01 = 0, s02 = 0, s11 = 1, s12 = 0, s22 = 1;
};
AffineFactors factor_affine(const Matrix4 &m);
Matrix4 compose(const AffineFactors &factors);
// The placement at fraction u in (0, 1) of the way from the placement with factors a to that
// with factors b: T and S interpolated linearly, R by slerp. For callers that ask many times
// and keep the factors (AnimatedTransform::at factors both ends on every call).
Transform interpolate(const AffineFactors &a, const AffineFactors &b, float u);

struct AnimatedTransform {
    Transform start, end;

    AnimatedTransform() = default;
    AnimatedTransform(const Transform &still) : start(still), end(still) {}
    AnimatedTransform(const Transform &at_start, const Transform &at_end) : start(at_start), end(at_end) {}

    bool is_animated() const { return !(start == end); }
    // The placement at `fraction` of the way from start to end (in [0, 1]).
    Transform at(float fraction) const;
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
