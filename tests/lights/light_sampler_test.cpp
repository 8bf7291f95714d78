#include "lights/light_sampler.h"

#include "lights/bvh_light_sampler.h"

#include "core/rng.h"
#include "lights/point_light.h"
#include "lights/uniform_infinite_light.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

LightPtr point_light(float intensity) {
    return std::make_shared<PointLight>(Transform(), std::make_shared<ConstantSpectrum>(intensity),
                                        1.f);
}

TEST(PowerLightSampler, ChoosesInProportionToPower) {
    std::vector<LightPtr> lights = {point_light(1), point_light(3), point_light(0), point_light(4)};
    PowerLightSampler sampler(lights);
    const float expected[4] = {0.125f, 0.375f, 0.f, 0.5f};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(sampler.pmf(lights[i].get()), expected[i], 1e-6f);
    PointLight stranger(Transform(), std::make_shared<ConstantSpectrum>(1.f), 1.f);
    EXPECT_EQ(sampler.pmf(&stranger), 0.f);

    // Frequencies over a regular grid of u follow the pmf to within 1/n.
    int counts[4] = {};
    const int n = 10000;
    for (int i = 0; i < n; ++i) {
        std::optional<SampledLight> s = sampler.sample((i + 0.5f) / n);
        ASSERT_TRUE(s);
        int k = 0;
        while (lights[k].get() != s->light) ++k;
        EXPECT_FLOAT_EQ(s->pmf, expected[k]);
        ++counts[k];
    }
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(double(counts[k]) / n, expected[k], 2.0 / n);
}

TEST(PowerLightSampler, FallsBackToUniformWhenNothingEmits) {
    std::vector<LightPtr> lights = {point_light(0), point_light(0)};
    PowerLightSampler sampler(lights);
    EXPECT_FLOAT_EQ(sampler.pmf(lights[0].get()), 0.5f);
    EXPECT_FLOAT_EQ(sampler.sample(0.9f)->pmf, 0.5f);
    EXPECT_FALSE(PowerLightSampler({}).sample(0.5f));
}

TEST(UniformLightSampler, EveryLightEquallyLikely) {
    std::vector<LightPtr> lights = {point_light(1), point_light(5), point_light(2)};
    UniformLightSampler sampler(lights);
    for (const LightPtr &l : lights) EXPECT_FLOAT_EQ(sampler.pmf(l.get()), 1.f / 3);
    EXPECT_EQ(sampler.sample(0.f)->light, lights[0].get());
    EXPECT_EQ(sampler.sample(0.5f)->light, lights[1].get());
    EXPECT_EQ(sampler.sample(OneMinusEpsilon)->light, lights[2].get());
    EXPECT_FALSE(UniformLightSampler({}).sample(0.5f));
}

LightPtr point_light_at(float intensity, Vec3f p) {
    return std::make_shared<PointLight>(Transform::translate(p), std::make_shared<ConstantSpectrum>(intensity), 1.f);
}

// Next-event estimation's choice with point lamps above a receiver facing them: importance is
// power over squared distance (the receiver's cosine is 1 towards both), for the exhaustive
// sampler and the light BVH alike; sample() and pmf() agree, and the choice without a point
// stays by power (light paths).
template <class Sampler> void expect_near_lights_preferred() {
    // A weak lamp at distance 1 and one 100 times stronger at distance 20 from the origin.
    std::vector<LightPtr> lights = {point_light_at(1, {0, 0, 1}), point_light_at(100, {0, 0, 20})};
    Sampler sampler(lights);
    LightSampleContext origin{{0, 0, 0}, {0, 0, 1}, {0, 0, 1}};
    // Weights 1 / 1 and 100 / 400.
    EXPECT_NEAR(sampler.pmf(origin, lights[0].get()), 1 / 1.25f, 1e-6f);
    EXPECT_NEAR(sampler.pmf(origin, lights[1].get()), 0.25f / 1.25f, 1e-6f);
    EXPECT_NEAR(sampler.pmf(lights[0].get()), 1 / 101.f, 1e-6f); // without a point: by power
    int first = 0;
    const int n = 10000;
    for (int i = 0; i < n; ++i) {
        std::optional<SampledLight> s = sampler.sample(origin, (i + 0.5f) / n);
        ASSERT_TRUE(s);
        EXPECT_FLOAT_EQ(s->pmf, sampler.pmf(origin, s->light));
        first += s->light == lights[0].get();
    }
    EXPECT_NEAR(double(first) / n, 0.8, 2.0 / n);
    // Near the strong lamp it gets nearly every sample.
    LightSampleContext near_strong{{0, 0, 19}, {0, 0, 1}, {0, 0, 1}};
    EXPECT_GT(sampler.pmf(near_strong, lights[1].get()), 0.99f);
    // A lamp in the receiver's tangent plane cannot light it.
    LightSampleContext sideways{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}};
    EXPECT_EQ(sampler.pmf(sideways, lights[0].get()), 0.f);
    EXPECT_FALSE(sampler.sample(sideways, 0.5f));
}

TEST(ExhaustiveLightSampler, PrefersNearLightsByPowerOverSquaredDistance) {
    expect_near_lights_preferred<ExhaustiveLightSampler>();
}
TEST(BVHLightSampler, PrefersNearLightsByPowerOverSquaredDistance) {
    expect_near_lights_preferred<BVHLightSampler>();
}

template <class Sampler> void expect_infinite_share() {
    std::vector<LightPtr> lights = {point_light_at(1, {1, 0, 1}), point_light_at(5, {3, 0, 1}),
                                    std::make_shared<UniformInfiniteLight>(std::make_shared<ConstantSpectrum>(1.f), 1.f)};
    Sampler sampler(lights);
    LightSampleContext origin{{0, 0, 0}, {0, 0, 1}, {0, 0, 1}};
    // One share for the light at infinity, one for both lamps together.
    EXPECT_NEAR(sampler.pmf(origin, lights[2].get()), 0.5f, 1e-6f);
    float sum = 0;
    for (const LightPtr &l : lights) sum += sampler.pmf(origin, l.get());
    EXPECT_NEAR(sum, 1, 1e-6f);
}

TEST(ExhaustiveLightSampler, LightsAtInfinityShareLikePbrtV4) { expect_infinite_share<ExhaustiveLightSampler>(); }
TEST(BVHLightSampler, LightsAtInfinityShareLikePbrtV4) { expect_infinite_share<BVHLightSampler>(); }

}  // namespace
}  // namespace caustica
