// pbrt-v4's path regularisation ("bool regularize") against pbrt-v4's path tracer's image of
// scenes/integrators/regularize-path.pbrt: a caustic that a smooth glass ball focuses into its
// shadow, met after a diffuse bounce and so seen through a ball widened to alpha 0.1, with the
// hard-transport suite's check (render_test_support.h). Regularisation is biased by design: the
// witness is pbrt-v4's regularised image, which is 2% darker than its unregularised one.
// Negative controls (one run each, then undone): the path tracer not regularising fails with a
// mean error of 1.85% (the bound is 1%); widening to at least alpha 0.15 instead of 0.1 fails
// with |z| 6.09 (0.73% dark). The right code gave 0.17% and |z| 2.92.
// bdpt regularises too, but is not compared here: a regularised estimate depends on which
// strategy found the path, so its image depends on the MIS weights, which differ between the two
// renderers' bdpt (pbrt-v4's own bdpt and path differ by 1.5% on this scene).
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

INSTANTIATE_TEST_SUITE_P(Regularize, PbrtWitness,
                         ::testing::Values(RenderCase{"integrators/regularize-path", "pt", 1024}), witness_case_name);

} // namespace
