// The one test of the pbrt-v4 witness suites (render_test_support.h, PbrtWitness): a scene
// rendered by one integrator agrees with pbrt-v4's image of the same file.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace caustica::testing {

TEST_P(PbrtWitness, MatchesPbrtV4) {
    const RenderCase &c = GetParam();
    expect_agreement_with_pbrt(c.scene, c.integrator, c.spp);
}

} // namespace caustica::testing
