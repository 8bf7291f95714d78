// The EXR's "variance" layer (--variance) estimates each pixel's variance of its mean.
#include "../integrators/render_test_support.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

using namespace caustica::testing;

namespace {

std::vector<float> read_channels(const std::string &path, const std::string &prefix) {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << path;
    const OIIO::ImageSpec &spec = in->spec();
    std::vector<float> all(size_t(spec.width) * spec.height * spec.nchannels);
    in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data());
    std::vector<float> out;
    for (int c = 0; c < spec.nchannels; ++c) {
        if (spec.channelnames[c].rfind(prefix, 0) != 0) continue;
        for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i) out.push_back(all[i * spec.nchannels + c]);
    }
    return out;
}

// Two independent renders A and B (different seeds) of the Cornell box at 16 spp: for every
// pixel (A - B)^2 / 2 is an unbiased estimate of the variance of one render's pixel mean, so its
// average over the 49152 pixel values must match the average of A's variance layer. Both
// averages carry relative errors of about 1% (tens of thousands of values, fat-tailed near the
// light); 10% separates a correct estimate from one off by the sample count (a factor 16) or
// computed from the wrong moments.
TEST(VarianceLayer, MatchesTheSpreadBetweenIndependentRenders) {
    std::string dir = scratch_dir("variance");
    std::string scene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt";
    ASSERT_EQ(run_caustica("render " + scene + " --quiet --variance --spp 16 --seed 1 -o " + dir + "/a.exr"), 0);
    ASSERT_EQ(run_caustica("render " + scene + " --quiet --spp 16 --seed 2 -o " + dir + "/b.exr"), 0);
    std::vector<float> variance = read_channels(dir + "/a.exr", "variance.");
    RgbImage a = read_rgb(dir + "/a.exr"), b = read_rgb(dir + "/b.exr");
    ASSERT_EQ(variance.size(), a.rgb.size());
    double estimated = 0, observed = 0;
    for (float v : variance) estimated += v;
    for (size_t i = 0; i < a.rgb.size(); ++i) observed += 0.5 * double(a.rgb[i] - b.rgb[i]) * (a.rgb[i] - b.rgb[i]);
    EXPECT_NEAR(estimated / observed, 1.0, 0.1);
    // Without the flag there is no such layer.
    EXPECT_TRUE(read_channels(dir + "/b.exr", "variance.").empty());
}

} // namespace
