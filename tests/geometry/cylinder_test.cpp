// pbrt's cylinder against closed forms: hits from outside and inside, the cut ends and the phi
// cut, the outward normal and (u, v), the area (an elliptic cylinder's perimeter under a
// non-uniform scale), and sampling densities.
#include "core/sampling.h"
#include "geometry/cylinder.h"
#include "geometry_test_util.h"

#include <cmath>

namespace caustica {
namespace {

using test::expect_near_vec;

TEST(Cylinder, HitsAgainstClosedForm) {
    auto cylinder = std::make_shared<Cylinder>(Transform{}, false, 2, -1, 3, 360);
    auto scene = test::scene_of({test::analytic_group(cylinder)});
    SurfaceInteraction si;
    // From outside along -x at height 1: the near wall at x = 2.
    ASSERT_TRUE(scene->intersect({{5, 0, 1}, {-1, 0, 0}}, &si));
    EXPECT_NEAR(si.t, 3, 1e-6);
    expect_near_vec(si.p, {2, 0, 1}, 1e-6f);
    expect_near_vec(si.n, {1, 0, 0}, 1e-6f);
    EXPECT_NEAR(si.uv.x, 0, 1e-6);
    EXPECT_NEAR(si.uv.y, 0.5, 1e-6); // (1 - (-1)) / 4
    // From inside: the far wall, normal still away from the axis.
    ASSERT_TRUE(scene->intersect({{0, 0, 0}, {0, 1, 0}}, &si));
    EXPECT_NEAR(si.t, 2, 1e-6);
    expect_near_vec(si.n, {0, 1, 0}, 1e-6f);
    EXPECT_NEAR(si.uv.x, 0.25, 1e-6);
    // Above the top, along the axis, and beyond t_max: misses.
    EXPECT_FALSE(scene->intersect({{5, 0, 3.5f}, {-1, 0, 0}}, &si));
    EXPECT_FALSE(scene->intersect({{0, 0, -5}, {0, 0, 1}}, &si));
    EXPECT_FALSE(scene->intersect({{5, 0, 1}, {-1, 0, 0}, 2.9f}, &si));
    // Open ends: a slanted ray enters through the top and hits the inside of the wall.
    ASSERT_TRUE(scene->intersect({{0, 0, 4}, normalize(Vec3f{1, 0, -1})}, &si));
    expect_near_vec(si.p, {2, 0, 2}, 1e-5f);
}

TEST(Cylinder, PhiCutAndTransform) {
    // A half cylinder (phi in [0, 180]) moved up by 10: rays at negative y pass through.
    auto half = std::make_shared<Cylinder>(Transform::translate({0, 0, 10}), false, 1, 0, 1, 180);
    auto scene = test::scene_of({test::analytic_group(half)});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{0, 5, 10.5f}, {0, -1, 0}}, &si));
    expect_near_vec(si.p, {0, 1, 10.5f}, 1e-5f);
    // Through the missing half the ray reaches the inside of the kept one.
    ASSERT_TRUE(scene->intersect({{0, -5, 10.5f}, {0, 1, 0}}, &si));
    expect_near_vec(si.p, {0, 1, 10.5f}, 1e-5f);
    EXPECT_FALSE(scene->intersect({{5, -0.5f, 10.5f}, {-1, 0, 0}}, &si));
}

TEST(Cylinder, AreaAndSamplingDensities) {
    // Unit radius, height 2, stretched to an ellipse of semi-axes 3 and 1: the area is the
    // ellipse's perimeter times 2, the perimeter by the series of Gauss-Kummer.
    auto elliptic = std::make_shared<Cylinder>(Transform::scale(3, 1, 1), false, 1, -1, 1, 360);
    double a = 3, b = 1, h = (a - b) * (a - b) / ((a + b) * (a + b));
    double perimeter = M_PI * (a + b) * (1 + h / 4 + h * h / 64 + h * h * h / 256 + 25 * h * h * h * h / 16384);
    EXPECT_NEAR(elliptic->area(), 2 * perimeter, 1e-4 * 2 * perimeter);
    // Area sampling: the mean of 1 / pdf is the area, and samples lie on the surface.
    Rng rng(3, 3);
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        auto ss = elliptic->sample(rng.uniform2());
        ASSERT_TRUE(ss);
        sum += 1 / double(ss->pdf);
        EXPECT_NEAR(sqr(ss->p.x / 3) + sqr(ss->p.y), 1, 1e-5);
    }
    EXPECT_NEAR(sum / n, elliptic->area(), 5e-3 * elliptic->area());
    // Solid-angle sampling from a point outside (the Shape default, through area sampling):
    // where a sample is the first surface point in its direction, pdf() agrees with its density
    // (a direction meets a cylinder twice; pdf() describes the visible point, as in pbrt-v4).
    Vec3f ref{5, 1, 0.5f};
    int compared = 0;
    for (int i = 0; i < 20000; ++i) {
        auto ss = elliptic->sample(ref, rng.uniform2());
        if (!ss) continue;
        Vec3f wi = normalize(ss->p - ref);
        // Grazing samples are left out: there float rounding of the point and normal dominates
        // both densities (they grow as 1 / cos).
        if (abs_dot(ss->n, wi) < 0.05f) continue;
        auto hit = elliptic->intersect(ref, wi, Infinity);
        ASSERT_TRUE(hit);
        if (std::abs(hit->t - distance(ref, ss->p)) > 1e-4f * distance(ref, ss->p)) continue;
        EXPECT_NEAR(elliptic->pdf(ref, wi), ss->pdf, 1e-3f * ss->pdf);
        ++compared;
    }
    EXPECT_GT(compared, 5000);
}

} // namespace
} // namespace caustica
