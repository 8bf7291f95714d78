// pbrt-v4's goniometric light against pbrt-v4's image of scenes/lights/goniometric.pbrt (a tilted
// diagram of a checkerboard lighting a closed box), with the hard-transport suite's check
// (render_test_support.h). pt tests the diagram lookup; lt and bdpt also its sampling of light
// paths and their densities. Negative control (one run, then undone): without pbrt-v4's swap of
// light-space y and z, pt fails with |z| 254, lt with 69 and bdpt with 160.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

class GoniometricLight : public ::testing::TestWithParam<RenderCase> {};

TEST_P(GoniometricLight, MatchesPbrtV4) {
    const RenderCase &c = GetParam();
    const PbrtAgreement a = pbrt_agreement(c.scene, c.integrator, c.spp);
    EXPECT_LT(a.mean_relative_error, 0.01);
    EXPECT_LT(a.worst_z, 5.0);
}

INSTANTIATE_TEST_SUITE_P(Integrators, GoniometricLight,
                         ::testing::Values(RenderCase{"lights/goniometric", "pt", 64},
                                           RenderCase{"lights/goniometric", "lt", 16},
                                           RenderCase{"lights/goniometric", "bdpt", 16}),
                         [](const ::testing::TestParamInfo<RenderCase> &info) {
                             return std::string(info.param.integrator);
                         });

} // namespace
