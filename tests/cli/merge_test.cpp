// Crop windows and `caustica merge`, as a render farm uses them: a frame rendered as two halves
// (--cropwindow, --pixelbounds) and merged is the frame rendered whole, pixel for pixel (each
// sample lands in its own pixel, and a pixel's samples depend only on the pixel, the sample
// index and the seed); renders of one frame with different seeds and sample counts merge into
// their sample-weighted mean.
#include "../integrators/render_test_support.h"
#include "cli/merge_command.h"
#include "core/error.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

const std::string kCornell = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt";

TEST(Merge, HalvesOfAFrameMergeIntoTheWholeFrame) {
    const std::string dir = scratch_dir("merge-halves");
    const std::string common = "render " + kCornell + " --quiet --integrator pt --spp 4 --seed 3 --resolution 40x30 ";
    ASSERT_EQ(run_caustica(common + "-o " + dir + "/whole.exr"), 0);
    ASSERT_EQ(run_caustica(common + "--cropwindow 0 1 0 0.5 -o " + dir + "/top.exr"), 0);
    ASSERT_EQ(run_caustica(common + "--pixelbounds 0 40 15 30 -o " + dir + "/bottom.exr"), 0);
    const RgbImage top = read_rgb(dir + "/top.exr");
    EXPECT_EQ(top.width, 40);
    EXPECT_EQ(top.height, 15);
    ASSERT_EQ(run_caustica("merge " + dir + "/top.exr " + dir + "/bottom.exr -o " + dir + "/merged.exr"), 0);
    const RgbImage whole = read_rgb(dir + "/whole.exr"), merged = read_rgb(dir + "/merged.exr");
    ASSERT_EQ(merged.width, 40);
    ASSERT_EQ(merged.height, 30);
    for (size_t i = 0; i < whole.rgb.size(); ++i) ASSERT_EQ(merged.rgb[i], whole.rgb[i]) << i;
}

TEST(Merge, RendersWithDifferentSeedsAverageBySampleCount) {
    using caustica::Image;
    using caustica::MergeInput;
    Image a(2, 1), b(2, 1);
    a.rgb = {1, 1, 1, 4, 4, 4};
    b.rgb = {3, 3, 3, 0, 0, 0};
    a.layers.push_back({"variance", {0.5f, 0.5f, 0.5f, 1, 1, 1}});
    b.layers.push_back({"variance", {0.25f, 0.25f, 0.25f, 2, 2, 2}});
    caustica::MergeResult r = caustica::merge_images({MergeInput{a, 16, "a"}, MergeInput{b, 48, "b"}});
    // (16 * 1 + 48 * 3) / 64 = 2.5 and (16 * 4) / 64 = 1.
    EXPECT_FLOAT_EQ(r.image.rgb[0], 2.5f);
    EXPECT_FLOAT_EQ(r.image.rgb[3], 1.f);
    // Variance of the weighted mean: (16^2 0.5 + 48^2 0.25) / 64^2.
    ASSERT_EQ(r.image.layers.size(), 1u);
    EXPECT_FLOAT_EQ(r.image.layers[0].rgb[0], (256 * 0.5f + 2304 * 0.25f) / 4096);
    EXPECT_EQ(r.min_samples, 64);
    // Inputs of different frames, or without a sample count, are refused.
    Image other(3, 1);
    EXPECT_THROW(caustica::merge_images({MergeInput{a, 16, "a"}, MergeInput{other, 16, "other"}}), caustica::InputError);
    EXPECT_THROW(caustica::merge_images({MergeInput{a, 0, "a"}}), caustica::InputError);
}

TEST(Merge, TwoSeedsOfTheWholeFrameThroughTheCommand) {
    const std::string dir = scratch_dir("merge-seeds");
    const std::string common = "render " + kCornell + " --quiet --integrator pt --resolution 16x16 ";
    ASSERT_EQ(run_caustica(common + "--spp 4 --seed 1 -o " + dir + "/a.exr"), 0);
    ASSERT_EQ(run_caustica(common + "--spp 12 --seed 2 -o " + dir + "/b.exr"), 0);
    ASSERT_EQ(run_caustica("merge " + dir + "/a.exr " + dir + "/b.exr -o " + dir + "/m.exr"), 0);
    const RgbImage a = read_rgb(dir + "/a.exr"), b = read_rgb(dir + "/b.exr"), m = read_rgb(dir + "/m.exr");
    for (size_t i = 0; i < m.rgb.size(); ++i) EXPECT_NEAR(m.rgb[i], (4 * a.rgb[i] + 12 * b.rgb[i]) / 16, 1e-6f);
    // An image without a sample count (not from caustica render) is an error, exit status 2.
    ASSERT_EQ(run_caustica("merge " + dir + "/a.exr " + data_path("pbrt-v4/hard/fog-point.exr") + " -o " + dir +
                           "/bad.exr"),
              2);
    EXPECT_FALSE(std::filesystem::exists(dir + "/bad.exr"));
}

} // namespace
