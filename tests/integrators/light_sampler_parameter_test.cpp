// The Integrator's "lightsampler" (scene_builder.cpp): each of pbrt-v4's names gives next-event
// estimation its own choice of light. Two point lights, a weak one near the receiving point and
// a strong one far from it, tell the choices apart:
//   - power: the weak light's share of the power, 1/10;
//   - uniform: 1/2;
//   - bvh and exhaustive: importance, here (point lights, a receiver without a normal) power
//     over squared distance, which favours the near light (1/1.9).
#include "integrators/integrator.h"
#include "parser/scene_description.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <string>

using namespace caustica;

namespace {

// The weak light (intensity 1) at the origin, the strong one (intensity 9) 3 units away.
float weak_light_pmf_near_it(const std::string &lightsampler) {
    set_warnings_enabled(false);
    std::string text = "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\n";
    if (!lightsampler.empty()) text += "Integrator \"path\" \"string lightsampler\" \"" + lightsampler + "\"\n";
    text += "WorldBegin\n"
            "LightSource \"point\" \"rgb I\" [ 1 1 1 ] \"point3 from\" [ 0 0 0 ]\n"
            "LightSource \"point\" \"rgb I\" [ 9 9 9 ] \"point3 from\" [ 3 0 0 ]\n";
    std::unique_ptr<Scene> scene = build_scene(parse_scene_string(text), RenderOverrides{});
    EXPECT_EQ(scene->lights.size(), 2u);
    const LightSampleContext receiver{Vec3f{0, 1, 0}, Vec3f{}, Vec3f{}};
    return scene->light_sampler->pmf(receiver, scene->lights[0].get());
}

} // namespace

TEST(LightSamplerParameter, EachNameGivesItsOwnChoice) {
    EXPECT_NEAR(weak_light_pmf_near_it("power"), 0.1f, 1e-4f);
    EXPECT_NEAR(weak_light_pmf_near_it("uniform"), 0.5f, 1e-6f);
    // Squared distances 1 and 10: weights 1 and 9/10.
    EXPECT_NEAR(weak_light_pmf_near_it("bvh"), 1.f / 1.9f, 1e-4f);
    EXPECT_NEAR(weak_light_pmf_near_it("exhaustive"), 1.f / 1.9f, 1e-4f);
    EXPECT_NEAR(weak_light_pmf_near_it(""), 1.f / 1.9f, 1e-4f); // the default is bvh
}

// Every integrator reports the Integrator parameters that nothing read (as shapes, materials and
// lights do theirs), and "lightsampler", which the scene builder reads, is not among them.
TEST(LightSamplerParameter, IntegratorsReportOnlyTheParametersNothingRead) {
    for (const char *name : {"pt", "lt", "bdpt", "sppm", "bpm", "vcm"}) {
        set_warnings_enabled(true);
        const std::string text = std::string("LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nIntegrator \"") +
                                 name +
                                 "\" \"string lightsampler\" \"power\" \"integer foo\" [ 3 ]\n"
                                 "WorldBegin\nLightSource \"point\" \"rgb I\" [ 1 1 1 ]\n";
        std::unique_ptr<Scene> scene = build_scene(parse_scene_string(text), RenderOverrides{});
        testing::internal::CaptureStderr();
        create_integrator(*scene);
        const std::string err = testing::internal::GetCapturedStderr();
        EXPECT_NE(err.find("unused parameter \"integer foo\""), std::string::npos) << name << ": " << err;
        EXPECT_EQ(err.find("lightsampler"), std::string::npos) << name << ": " << err;
    }
    set_warnings_enabled(false);
}
