// Emissive media against the closed form of issue 18: a purely absorbing emissive slab seen
// head-on through vacuum renders Le (1 - exp(-sigma_a d)), pbrt-v4's convention that a medium
// emits sigma_a Le per unit length. Two slabs (tests/data/renderer/emissive-slab-*.pbrt), a
// "homogeneous" one and a "uniformgrid" one, both with sigma_a d = 1 and a white "rgb Le" of
// luminance 1, in pt, bdpt, vcm, bpm and sppm, which count the emission they see on their camera
// paths. lt is left out: its paths start anywhere in the slab, 100 units across, and only those
// within the 2-degree view reach the image; it is checked against pbrt-v4 on media/emissive
// (heterogeneous_media_witness_test.cpp).
//
// The bound: the camera path's collision estimator is 1 with probability 1 - exp(-1) and 0
// otherwise (the collision absorbs), a standard deviation of 0.48 per sample; 32 x 32 pixels at
// 1024 samples give a standard error of 0.075% of the mean per channel, so 0.4% is over 5
// standard errors. Negative control (run once, then undone): emission scaled by 1.02 in the walk
// fails every case by 1.9-2.0%.
#include "render_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace caustica::testing;

namespace {

struct SlabCase {
    std::string slab, integrator;
};

class EmissiveSlab : public ::testing::TestWithParam<SlabCase> {};

TEST_P(EmissiveSlab, RendersLeTimesOneMinusTransmittance) {
    const SlabCase &c = GetParam();
    const std::string out = scratch_dir("emissive-" + c.slab + "-" + c.integrator) + "/slab.exr";
    ASSERT_EQ(run_caustica("render " + data_path("renderer/emissive-slab-" + c.slab + ".pbrt") + " --integrator " +
                           c.integrator + " --seed 3 --quiet -o " + out),
              0);
    const RgbImage img = read_rgb(out);
    const double expected = 1 - std::exp(-1.0);
    for (int ch = 0; ch < 3; ++ch) {
        const double mean = block_mean(img, 0, 0, img.width, ch);
        EXPECT_NEAR(mean / expected, 1, 0.004) << "channel " << ch << ": " << mean << ", expected " << expected;
    }
}

INSTANTIATE_TEST_SUITE_P(Integrators, EmissiveSlab,
                         ::testing::Values(SlabCase{"homogeneous", "pt"}, SlabCase{"homogeneous", "bdpt"},
                                           SlabCase{"homogeneous", "vcm"}, SlabCase{"homogeneous", "bpm"},
                                           SlabCase{"homogeneous", "sppm"}, SlabCase{"grid", "pt"},
                                           SlabCase{"grid", "bdpt"}, SlabCase{"grid", "vcm"}, SlabCase{"grid", "bpm"},
                                           SlabCase{"grid", "sppm"}),
                         [](const ::testing::TestParamInfo<SlabCase> &info) {
                             return info.param.slab + "_" + info.param.integrator;
                         });

} // namespace
