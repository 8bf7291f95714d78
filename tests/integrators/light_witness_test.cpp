// pbrt-v4's goniometric and projection lights against pbrt-v4's images of scenes/lights/*.pbrt
// (a tilted diagram of a checkerboard lighting a closed box; a coloured slide projected onto its
// wall), with the hard-transport suite's check (render_test_support.h). pt tests the lookups;
// lt and bdpt also the sampling of light paths and their densities. Negative controls (one run
// each, then undone): the goniometric light without pbrt-v4's swap of light-space y and z fails
// with |z| 254 (pt), 69 (lt) and 160 (bdpt); the projection light without its y flip with 155,
// 187 and 189.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

class PbrtLights : public ::testing::TestWithParam<RenderCase> {};

TEST_P(PbrtLights, MatchPbrtV4) {
    const RenderCase &c = GetParam();
    expect_agreement_with_pbrt(c.scene, c.integrator, c.spp);
}

INSTANTIATE_TEST_SUITE_P(Integrators, PbrtLights,
                         ::testing::Values(RenderCase{"lights/goniometric", "pt", 64},
                                           RenderCase{"lights/goniometric", "lt", 16},
                                           RenderCase{"lights/goniometric", "bdpt", 16},
                                           RenderCase{"lights/projection", "pt", 64},
                                           RenderCase{"lights/projection", "lt", 16},
                                           RenderCase{"lights/projection", "bdpt", 16}),
                         [](const ::testing::TestParamInfo<RenderCase> &info) {
                             std::string scene = info.param.scene;
                             return scene.substr(scene.find('/') + 1) + "_" + info.param.integrator;
                         });

} // namespace
