// Point, spot and distant lights against closed forms.
#include "core/rng.h"
#include "lights/distant_light.h"
#include "lights/point_light.h"
#include "lights/spot_light.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

SampledWavelengths some_wavelengths() { return SampledWavelengths::sample_visible(0.37f); }

TEST(PointLight, IncidentIntensityFallsOffWithSquaredDistance) {
    auto I = std::make_shared<ConstantSpectrum>(3.f);
    PointLight light(Transform::translate({1, 2, 3}), I, 2.f);
    SampledWavelengths lambda = some_wavelengths();
    LightSampleContext ctx{{1, 2, -1}, {0, 0, 1}, {0, 0, 1}};
    auto s = light.sample_li(ctx, {0.3f, 0.6f}, lambda);
    ASSERT_TRUE(s);
    EXPECT_FLOAT_EQ(s->pdf, 1.f);
    EXPECT_NEAR(s->wi.z, 1.f, 1e-6f);
    // I scale / r^2 with r = 4.
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_NEAR(s->L[i], 6.f / 16, 1e-6f);
    EXPECT_EQ(light.pdf_li(ctx, s->wi), 0.f);
    EXPECT_EQ(s->p_light, Vec3f(1, 2, 3));
}

// Total power from emitted rays: E[L / pdf_dir] over sample_le is the integral of the
// intensity over the sphere, 4 pi I for a point light (every sample gives exactly that).
TEST(PointLight, EmittedRaysCarryItsPower) {
    auto I = std::make_shared<ConstantSpectrum>(1.5f);
    PointLight light(Transform::translate({0, 1, 0}), I, 1.f);
    SampledWavelengths lambda = some_wavelengths();
    Rng rng(5, 1);
    const int n = 100000;
    double power = 0;
    Vec3f mean_dir;
    for (int i = 0; i < n; ++i) {
        auto s = light.sample_le(rng.uniform2(), rng.uniform2(), lambda);
        ASSERT_TRUE(s);
        float pos, dir;
        light.pdf_le(s->ray, s->n, &pos, &dir);
        ASSERT_NEAR(dir, s->pdf_dir, 1e-6f);
        EXPECT_EQ(s->pdf_pos, 1.f);  // the discrete choice of the one position
        EXPECT_EQ(pos, 0.f);         // ... which a ray cannot hit by chance
        power += s->L[0] / (s->pdf_pos * s->pdf_dir);
        mean_dir += s->ray.d / float(n);
    }
    EXPECT_NEAR(power / n, 4 * Pi * 1.5, 1e-3);
    EXPECT_NEAR(light.phi(lambda)[0], 4 * Pi * 1.5, 1e-4);
    // Uniform directions: each component's mean has standard deviation sqrt(1/3n) ~ 1.8e-3.
    EXPECT_LT(length(mean_dir), 0.01f);
}

TEST(SpotLight, ProfileIsFullInsideSmoothInFalloffAndZeroOutside) {
    auto I = std::make_shared<ConstantSpectrum>(1.f);
    // Axis along +z from the origin; cone 30 degrees, falloff starts at 20 degrees.
    SpotLight light(Transform(), I, 1.f, 30.f, 20.f);
    SampledWavelengths lambda = some_wavelengths();
    auto at_angle = [&](float degrees) {
        float t = radians(degrees);
        return light.intensity({std::sin(t), 0, std::cos(t)}, lambda)[0];
    };
    EXPECT_FLOAT_EQ(at_angle(0), 1.f);
    EXPECT_FLOAT_EQ(at_angle(19.9f), 1.f);
    EXPECT_FLOAT_EQ(at_angle(30.1f), 0.f);
    // smoothstep in cos theta between cos 30 and cos 20.
    float c = std::cos(radians(25.f)), a = std::cos(radians(30.f)), b = std::cos(radians(20.f));
    float t = (c - a) / (b - a);
    EXPECT_NEAR(at_angle(25), t * t * (3 - 2 * t), 1e-5f);

    LightSampleContext outside{{10, 0, 1}, {}, {}};
    EXPECT_FALSE(light.sample_li(outside, {0.5f, 0.5f}, lambda));
    LightSampleContext inside{{0, 0, 2}, {}, {}};
    auto s = light.sample_li(inside, {0.5f, 0.5f}, lambda);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->L[0], 1.f / 4, 1e-6f);
    EXPECT_NEAR(s->wi.z, -1.f, 1e-6f);
}

// phi: 2 pi times the integral of the profile over cos theta, checked against a midpoint-rule
// quadrature (error far below 1e-4 with 20000 intervals); and the emitted-ray estimate of power
// (relative standard deviation below 0.3% at N = 2e5 since I / pdf varies by less than 2x).
TEST(SpotLight, PowerMatchesQuadratureAndEmittedRays) {
    auto I = std::make_shared<ConstantSpectrum>(2.f);
    Transform t = Transform::translate({0, 0, 1}) * Transform::rotate(40, {1, 1, 0});
    SpotLight light(t, I, 1.f, 45.f, 15.f);
    SampledWavelengths lambda = some_wavelengths();
    double quad = 0;
    const int m = 20000;
    for (int i = 0; i < m; ++i) {
        float c = -1 + 2 * (i + 0.5f) / m;
        quad += smooth_step(c, std::cos(radians(45.f)), std::cos(radians(15.f))) * 2.0 / m;
    }
    double expected = 2 * Pi * quad * 2;
    EXPECT_NEAR(light.phi(lambda)[0], expected, 1e-3 * expected);

    Rng rng(9, 2);
    const int n = 200000;
    double power = 0;
    for (int i = 0; i < n; ++i) {
        auto s = light.sample_le(rng.uniform2(), rng.uniform2(), lambda);
        ASSERT_TRUE(s);
        float pos, dir;
        light.pdf_le(s->ray, s->n, &pos, &dir);
        ASSERT_NEAR(dir, s->pdf_dir, 1e-4f * s->pdf_dir);
        ASSERT_NEAR(length(s->ray.o - Vec3f(0, 0, 1)), 0.f, 1e-6f);
        power += s->L[0] / s->pdf_dir;
    }
    EXPECT_NEAR(power / n, expected, 0.01 * expected);
}

TEST(SmoothStepSampling, InvertsTheCdf) {
    // The fraction of samples below x must be the normalised integral of the smoothstep.
    const float a = 0.2f, b = 0.9f;
    for (float u : {0.0f, 0.1f, 0.5f, 0.77f, 0.999f}) {
        float x = sample_smooth_step(u, a, b);
        ASSERT_GE(x, a);
        ASSERT_LE(x, b);
        double cdf = 0;
        const int m = 10000;
        for (int i = 0; i < m; ++i) {
            float xi = a + (x - a) * (i + 0.5f) / m;
            cdf += smooth_step_pdf(xi, a, b) * (x - a) / m;
        }
        EXPECT_NEAR(cdf, u, 1e-4);
    }
}

TEST(DistantLight, IlluminatesAlongItsDirectionAndEmitsThroughTheSceneDisk) {
    auto L = std::make_shared<ConstantSpectrum>(1.f);
    // Light-space +z mapped to the direction towards the light.
    Vec3f towards_light = normalize(Vec3f(1, -2, 2));
    Frame f = Frame::from_z(towards_light);
    float m[16] = {f.x.x, f.y.x, f.z.x, 0, f.x.y, f.y.y, f.z.y, 0,
                   f.x.z, f.y.z, f.z.z, 0, 0,     0,     0,     1};
    DistantLight light(Transform(Matrix4::from_row_major(m)), L, 3.f);
    Bounds3f bounds;
    bounds.expand(Vec3f(-1, -1, -1));
    bounds.expand(Vec3f(3, 1, 1));
    light.preprocess(bounds);
    Vec3f center{1, 0, 0};
    float radius = std::sqrt(6.f);
    SampledWavelengths lambda = some_wavelengths();

    LightSampleContext ctx{{0.5f, 0, 0}, {0, 0, 1}, {0, 0, 1}};
    auto s = light.sample_li(ctx, {0.1f, 0.2f}, lambda);
    ASSERT_TRUE(s);
    EXPECT_NEAR(distance(s->wi, towards_light), 0.f, 1e-6f);
    EXPECT_FLOAT_EQ(s->L[0], 3.f);
    EXPECT_TRUE(s->is_infinite);
    EXPECT_GT(distance(s->p_light, center), radius);  // outside the scene

    // Power through the disk: 3 * pi r^2, each emitted ray carrying L / pdf_pos of it.
    EXPECT_NEAR(light.phi(lambda)[0], 3 * Pi * 6, 1e-3);
    Rng rng(4, 4);
    for (int i = 0; i < 1000; ++i) {
        auto e = light.sample_le(rng.uniform2(), rng.uniform2(), lambda);
        ASSERT_TRUE(e);
        EXPECT_NEAR(distance(e->ray.d, -towards_light), 0.f, 1e-6f);
        // The ray starts outside the scene sphere and passes within its radius of the centre.
        Vec3f oc = center - e->ray.o;
        float along = dot(oc, e->ray.d);
        EXPECT_NEAR(along, radius, 1e-4f);
        EXPECT_LE(length(oc - e->ray.d * along), radius * (1 + 1e-5f));
        float pos, dir;
        light.pdf_le(e->ray, e->n, &pos, &dir);
        EXPECT_NEAR(pos, e->pdf_pos, 1e-7f);
        EXPECT_NEAR(pos, 1 / (Pi * 6), 1e-6f);
        EXPECT_EQ(e->pdf_dir, 1.f);
        EXPECT_EQ(dir, 0.f);
        EXPECT_NEAR(e->L[0] / e->pdf_pos, light.phi(lambda)[0], 1e-3f);
    }
}

}  // namespace
}  // namespace caustica
