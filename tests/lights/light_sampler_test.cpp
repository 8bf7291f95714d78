#include "lights/light_sampler.h"

#include "core/rng.h"
#include "lights/point_light.h"

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

}  // namespace
}  // namespace caustica
