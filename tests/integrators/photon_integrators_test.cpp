// The photon-mapping integrators (sppm, bpm, vcm) beyond the agreement scenes: determinism
// across thread counts (splats are summed in fixed point, photons are gathered in path order),
// and their parameters on the command line.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

const std::string kScene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/transport/glass-block.pbrt";

class PhotonIntegrator : public ::testing::TestWithParam<const char *> {};

TEST_P(PhotonIntegrator, OneAndTwoThreadsGiveBitIdenticalImages) {
    const std::string dir = scratch_dir(std::string("photon-threads-") + GetParam());
    for (int threads : {1, 2}) {
        const std::string out = dir + "/t" + std::to_string(threads) + ".exr";
        ASSERT_EQ(run_caustica("render " + kScene + " --quiet --integrator " + GetParam() +
                               " --spp 4 --seed 5 --threads " + std::to_string(threads) + " -o " + out),
                  0);
    }
    RgbImage one = read_rgb(dir + "/t1.exr"), two = read_rgb(dir + "/t2.exr");
    ASSERT_EQ(one.rgb.size(), two.rgb.size());
    size_t differing = 0;
    double sum = 0;
    for (size_t i = 0; i < one.rgb.size(); ++i) {
        differing += one.rgb[i] != two.rgb[i];
        sum += one.rgb[i];
    }
    EXPECT_EQ(differing, 0u);
    EXPECT_GT(sum, 0); // the images are not trivially equal
}

INSTANTIATE_TEST_SUITE_P(Integrators, PhotonIntegrator, ::testing::Values("sppm", "bpm", "vcm"));

// Parameters are checked where they are read: an out-of-range value is an error at its location
// in the scene file (exit status 2, nothing written).
TEST(PhotonIntegratorParameters, OutOfRangeValuesAreErrorsAtTheirLocation) {
    const std::string dir = scratch_dir("photon-parameters");
    const std::string cases[][2] = {
        {"\"vcm\" \"float alpha\" [ 1.5 ]", "alpha"},
        {"\"vcm\" \"integer wavelengthgroups\" [ 0 ]", "wavelengthgroups"},
        {"\"bpm\" \"float radius\" [ -1 ]", "radius"},
        {"\"sppm\" \"string photonsearch\" [ \"octree\" ]", "photonsearch"},
        {"\"sppm\" \"integer photonsperiteration\" [ 0 ]", "photonsperiteration"},
    };
    for (const auto &c : cases) {
        const std::string scene = dir + "/scene.pbrt";
        std::string text = read_text(kScene);
        const size_t at = text.find("Integrator \"path\"");
        ASSERT_NE(at, std::string::npos);
        text.replace(at, text.find('\n', at) - at, "Integrator " + c[0]);
        text.replace(text.find("Include \"stage.pbrt\""), 20,
                     "Include \"" + std::string(CAUSTICA_SOURCE_DIR) + "/scenes/transport/stage.pbrt\"");
        std::FILE *f = std::fopen(scene.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fwrite(text.data(), 1, text.size(), f);
        std::fclose(f);
        const std::string err = dir + "/err.txt", out = dir + "/out.exr";
        EXPECT_EQ(run_caustica("render " + scene + " --quiet --spp 1 -o " + out, err), 2) << c[0];
        const std::string message = read_text(err);
        EXPECT_NE(message.find("scene.pbrt:"), std::string::npos) << message;
        EXPECT_NE(message.find(c[1]), std::string::npos) << message;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
}

} // namespace
