// Motion blur against pbrt-v4's image of the same file, in every integrator, with the
// hard-transport suite's check (render_test_support.h: image mean within 1%, every 16x16 block
// and channel within |z| < 5).
// scenes/motion/moving-sphere.pbrt: a sphere sliding and an object instance spinning during the
// shutter, with TransformTimes longer than the shutter, and their blurred shadows under a lamp
// the camera does not see.
// scenes/motion/moving-camera.pbrt: the camera turns and slides during a shutter that covers the
// middle half of the TransformTimes, in front of still objects; lt, bdpt, bpm and vcm connect light
// paths to the lens where the camera is at the path's time.
// - pt, lt and bdpt draw a time per path (bdpt's light subpath takes its camera path's).
// - sppm, bpm and vcm give every path of an iteration one time, stratified over the iterations
//   (IterationRenderer::time), so that merges and connections join paths of one time.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

INSTANTIATE_TEST_SUITE_P(MotionBlur, PbrtWitness,
                         ::testing::Values(RenderCase{"motion/moving-sphere", "pt", 256},
                                           RenderCase{"motion/moving-sphere", "lt", 256},
                                           RenderCase{"motion/moving-sphere", "bdpt", 128},
                                           RenderCase{"motion/moving-sphere", "sppm", 256},
                                           RenderCase{"motion/moving-sphere", "bpm", 256},
                                           RenderCase{"motion/moving-sphere", "vcm", 256},
                                           RenderCase{"motion/moving-camera", "pt", 256},
                                           RenderCase{"motion/moving-camera", "lt", 256},
                                           RenderCase{"motion/moving-camera", "bdpt", 128},
                                           RenderCase{"motion/moving-camera", "sppm", 256},
                                           RenderCase{"motion/moving-camera", "bpm", 256},
                                           RenderCase{"motion/moving-camera", "vcm", 256}),
                         witness_case_name);

} // namespace
