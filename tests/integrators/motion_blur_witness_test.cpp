// Motion blur against pbrt-v4's image of the same file, in every integrator, with the
// hard-transport suite's check (render_test_support.h: image mean within 1%, every 16x16 block
// and channel within |z| < 5).
// scenes/motion/moving-sphere.pbrt: a sphere sliding and an object instance spinning during the
// shutter, with TransformTimes longer than the shutter, and their blurred shadows under a lamp
// the camera does not see.
// - pt, lt and bdpt draw a time per path (bdpt's light subpath takes its camera path's).
// - sppm, bpm and vcm give every path of an iteration one time, stratified over the iterations
//   (IterationRenderer::time), so that merges and connections join paths of one time.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

TEST(MotionBlur, PathTracerMatchesPbrtV4) { expect_agreement_with_pbrt("motion/moving-sphere", "pt", 256); }
TEST(MotionBlur, LightTracerMatchesPbrtV4) { expect_agreement_with_pbrt("motion/moving-sphere", "lt", 256); }
TEST(MotionBlur, BdptMatchesPbrtV4) { expect_agreement_with_pbrt("motion/moving-sphere", "bdpt", 128); }
TEST(MotionBlur, SppmMatchesPbrtV4) { expect_agreement_with_pbrt("motion/moving-sphere", "sppm", 256); }
TEST(MotionBlur, BpmMatchesPbrtV4) { expect_agreement_with_pbrt("motion/moving-sphere", "bpm", 256); }
TEST(MotionBlur, VcmMatchesPbrtV4) { expect_agreement_with_pbrt("motion/moving-sphere", "vcm", 256); }

} // namespace
