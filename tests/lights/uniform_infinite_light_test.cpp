#include "lights/uniform_infinite_light.h"

#include "core/rng.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

Bounds3f unit_cube_bounds() {
    Bounds3f b;
    b.expand(Vec3f(-1, -1, -1));
    b.expand(Vec3f(1, 1, 1));
    return b;
}

// Irradiance from constant radiance over the hemisphere is pi L. Uniform sphere sampling gives
// the per-sample estimate 4 pi L cos+, whose relative standard deviation is sqrt(5/3) ~ 1.29;
// at N = 2e5 that is 0.29%, and the bound of 1.5% is over 5 sigma.
TEST(UniformInfiniteLight, IrradianceIsPiL) {
    UniformInfiniteLight light(std::make_shared<ConstantSpectrum>(0.8f), 2.f);
    light.preprocess(unit_cube_bounds());
    SampledWavelengths lambda = SampledWavelengths::sample_visible(0.2f);
    Vec3f n = normalize(Vec3f(1, 2, -1));
    LightSampleContext ctx{{0.1f, 0.2f, 0.3f}, n, n};
    Rng rng(3, 3);
    const int count = 200000;
    double E = 0;
    for (int i = 0; i < count; ++i) {
        auto s = light.sample_li(ctx, rng.uniform2(), lambda);
        ASSERT_TRUE(s);
        ASSERT_FLOAT_EQ(light.pdf_li(ctx, s->wi), s->pdf);
        EXPECT_TRUE(s->is_infinite);
        E += s->L[0] * std::max(0.f, dot(s->wi, n)) / s->pdf;
    }
    EXPECT_NEAR(E / count, Pi * 1.6, 0.015 * Pi * 1.6);
    EXPECT_FLOAT_EQ(light.Le({{0, 0, 0}, {0, 1, 0}}, lambda)[0], 1.6f);
}

// Power reaching the scene: radiance over 4 pi directions through the disk of the bounding
// sphere, 4 pi^2 r^2 L. Each emitted ray carries L / (pdf_pos pdf_dir) of it exactly.
TEST(UniformInfiniteLight, EmittedRaysCarryItsPowerAndCrossTheScene) {
    UniformInfiniteLight light(std::make_shared<ConstantSpectrum>(1.f), 1.f);
    light.preprocess(unit_cube_bounds());
    SampledWavelengths lambda = SampledWavelengths::sample_visible(0.2f);
    float r2 = 3;
    double expected = 4 * Pi * Pi * r2;
    EXPECT_NEAR(light.phi(lambda)[0], expected, 1e-5 * expected);
    Rng rng(1, 9);
    Vec3f mean_dir;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        auto s = light.sample_le(rng.uniform2(), rng.uniform2(), lambda);
        ASSERT_TRUE(s);
        float pos, dir;
        light.pdf_le(s->ray, s->n, &pos, &dir);
        ASSERT_FLOAT_EQ(pos, s->pdf_pos);
        ASSERT_FLOAT_EQ(dir, s->pdf_dir);
        ASSERT_NEAR(s->L[0] / (s->pdf_pos * s->pdf_dir), expected, 1e-4 * expected);
        float along = dot(-s->ray.o, s->ray.d);
        ASSERT_LE(length(-s->ray.o - s->ray.d * along), std::sqrt(r2) * (1 + 1e-5f));
        mean_dir += s->ray.d / float(n);
    }
    EXPECT_LT(length(mean_dir), 0.01f);  // uniform directions; sigma per component 1.8e-3
}

}  // namespace
}  // namespace caustica
