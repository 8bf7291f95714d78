// Beer-Lambert absorption inside a dielectric, tracked by the path tracer between the surfaces
// where a path enters and leaves the material.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

// tests/data/renderer/absorbing-cube.pbrt: with eta = 1 there is no reflection, so each pixel's
// expectation is exactly the transmittance along a 2-unit chord, 0.5 by construction (T given at
// distance 2). The noise comes from Russian roulette after the exit (throughput 0.5: the path
// survives with probability 0.5 at twice the weight): a per-sample standard deviation of 0.5,
// so 0.0078 per pixel at 4096 samples and 0.00065 for the mean of the 12x12 interior pixels.
// The mean is held to 0.003 (4.6 standard errors) and each pixel to 0.04 (5.1); a missing or
// doubled absorption gives 1.0 or 0.25.
TEST(PathTracerAbsorption, TransmittanceAtDistanceIsExactThroughTheCube) {
    std::string dir = scratch_dir("absorption");
    std::string out = dir + "/cube.exr";
    ASSERT_EQ(run_caustica("render " + data_path("renderer/absorbing-cube.pbrt") + " --quiet -o " + out), 0);
    RgbImage img = read_rgb(out);
    for (int c = 0; c < 3; ++c) {
        double sum = 0;
        int n = 0;
        for (int y = 2; y < img.height - 2; ++y)
            for (int x = 2; x < img.width - 2; ++x, ++n) {
                sum += img.at(x, y, c);
                EXPECT_NEAR(img.at(x, y, c), 0.5, 0.04) << "pixel " << x << "," << y << " channel " << c;
            }
        EXPECT_NEAR(sum / n, 0.5, 0.003) << "channel " << c;
    }
}

} // namespace
