// AnimatedTransform: the T R S factors reproduce the placement they come from, and the
// interpolation rests at the ends, moves translations linearly and turns rotations at a constant
// rate (slerp).
#include "core/animated_transform.h"

#include <gtest/gtest.h>

#include <cmath>

namespace caustica {
namespace {

void expect_matrix_near(const Matrix4 &a, const Matrix4 &b, float tol) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tol) << i << "," << j;
}

TEST(AnimatedTransform, FactorsComposeBackToThePlacement) {
    const Transform placements[] = {
        Transform(),
        Transform::translate({1, -2, 3}) * Transform::rotate(70, {1, 2, 0.5f}) * Transform::scale(2, 0.5f, 3),
        Transform::rotate(-170, {0, 1, 1}) * Transform::scale(-1, 2, 1),  // a mirror
        Transform::scale(1, 1, 4) * Transform::rotate(30, {1, 0, 0}),     // a shear after the rotation
        Transform::rotate(180, {0, 0, 1}),                                 // a half turn (trace -1)
    };
    for (const Transform &t : placements) {
        const AffineFactors f = factor_affine(t.matrix());
        EXPECT_NEAR(f.w * f.w + f.x * f.x + f.y * f.y + f.z * f.z, 1.f, 1e-5f);
        expect_matrix_near(compose(f), t.matrix(), 2e-5f);
    }
}

TEST(AnimatedTransform, InterpolatesBetweenRestingEnds) {
    const Transform start = Transform::translate({0, 0, 0});
    const Transform end = Transform::translate({4, 0, 0}) * Transform::rotate(120, {0, 1, 0});
    const AnimatedTransform motion(start, end);
    ASSERT_TRUE(motion.is_animated());
    EXPECT_FALSE(AnimatedTransform(start).is_animated());
    expect_matrix_near(motion.at(-1).matrix(), start.matrix(), 0);
    expect_matrix_near(motion.at(2).matrix(), end.matrix(), 0);
    for (float u : {0.25f, 0.5f, 0.75f}) {
        const Transform at = motion.at(u);
        // The origin moves linearly, and the x axis turns by u times 120 degrees about y.
        const Vec3f o = at.apply_point({0, 0, 0});
        EXPECT_NEAR(o.x, 4 * u, 1e-5f);
        EXPECT_NEAR(o.y, 0, 1e-5f);
        const Vec3f x = at.apply_vector({1, 0, 0});
        const float angle = radians(120 * u);
        EXPECT_NEAR(x.x, std::cos(angle), 1e-5f);
        EXPECT_NEAR(x.z, -std::sin(angle), 1e-5f);
        EXPECT_NEAR(length(x), 1, 1e-5f);
        // The inverse is kept with it.
        expect_matrix_near(at.inverse().matrix(), *inverse(at.matrix()), 1e-5f);
    }
}

} // namespace
} // namespace caustica
