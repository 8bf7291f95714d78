// The light tracer (lt) on the Cornell box: against the path tracer's high-sample reference (the
// two estimate the same image by independent methods: light paths splatted through camera
// connections versus camera paths with next-event estimation), for determinism across thread
// counts, and on the command line.
#include "render_test_support.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

using namespace caustica::testing;

namespace {

const std::string kScene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt";

RgbImage render(const std::string &dir, const std::string &name, const std::string &args) {
    std::string out = dir + "/" + name + ".exr";
    EXPECT_EQ(run_caustica("render " + kScene + " --quiet -o " + out + " " + args), 0);
    return read_rgb(out);
}

// Block test against the stored path-tracer reference (scripts/make-references.sh: pt, 4096 spp).
//
// A light path splats into every pixel within the filter's radius of each of its camera
// connections, so neighbouring pixels' errors are positively correlated, and the per-pixel
// variance estimate of a block mean (as cornell_box_test.cpp uses for the path tracer, whose
// pixels are independent) is too small by a factor k, the same for every block up to noise
// (it is set by the filter's footprint). k is estimated as the average over all 192 blocks and
// channels of variance_from_blocks / variance_from_pixels: each term is k times a chi-square
// variable with one degree of freedom divided by its mean, so the average has a relative
// standard error near sqrt(2 / 192) = 10%. The lt variance of a block is then k times its
// per-pixel estimate, estimated from 256 pixels rather than from one difference.
//
// The reference's own noise comes from two independent 16-spp path-tracer renders (pixels
// independent), scaled by 32 / 4096. z = (block mean - reference block mean) / sqrt(var_lt +
// var_ref) is then close to standard normal; |z| < 5 over 192 block-channels has false-failure
// odds near 1e-4 (even with k underestimated by 30%, |z| < 5 still means |z_true| < 4.2, odds
// near 5e-3). A 2% bias in a block is several sigma here; a missing t = 1 connection of the light
// vertex removes the light seen directly (its blocks go black), a missing shading-normal or
// importance factor changes every block.
TEST(LightTracerCornellBox, AgreesWithPathTracerReferenceOverBlocks) {
    std::string dir = scratch_dir("lt-cornell-blocks");
    RgbImage a = render(dir, "a", "--integrator lt --spp 32 --seed 1");
    RgbImage b = render(dir, "b", "--integrator lt --spp 32 --seed 2");
    RgbImage pt_a = render(dir, "pt-a", "--integrator pt --spp 16 --seed 3");
    RgbImage pt_b = render(dir, "pt-b", "--integrator pt --spp 16 --seed 4");
    RgbImage ref = read_rgb(data_path("renderer/cornell-box.pt-4096spp.exr"));
    ASSERT_EQ(a.width, ref.width);
    ASSERT_EQ(a.height, ref.height);
    const int block = 16;
    std::vector<BlockEstimate> lt = block_estimates(a, b, block);
    std::vector<BlockEstimate> pt = block_estimates(pt_a, pt_b, block);

    double ratio_sum = 0;
    int ratio_count = 0;
    for (const BlockEstimate &e : lt)
        if (e.variance_from_pixels > 0) {
            ratio_sum += e.variance_from_blocks / e.variance_from_pixels;
            ++ratio_count;
        }
    ASSERT_GT(ratio_count, 100);
    const double k = ratio_sum / ratio_count;
    // The filter (pbrt's default Gaussian, radius 1.5) spreads a splat over at most 3x3 pixels:
    // the correlation must show, and the footprint alone inflates a block's variance by less
    // than 9 (several vertices of one path landing in one block add little on top).
    EXPECT_GT(k, 1.2);
    EXPECT_LT(k, 9.0);

    double worst = 0;
    size_t i = 0;
    for (int by = 0; by + block <= a.height; by += block)
        for (int bx = 0; bx + block <= a.width; bx += block)
            for (int c = 0; c < 3; ++c, ++i) {
                double var = k * lt[i].variance_from_pixels;
                double var_ref = pt[i].variance_from_pixels * 32.0 / 4096;
                double ref_mean = block_mean(ref, bx, by, block, c);
                double z = (lt[i].mean - ref_mean) / std::sqrt(var + var_ref + 1e-30);
                worst = std::max(worst, std::abs(z));
                EXPECT_LT(std::abs(z), 5.0) << "block " << bx << "," << by << " channel " << c
                                            << ": mean " << lt[i].mean << " reference " << ref_mean;
            }
    std::printf("correlation factor k: %.2f, largest |z| over blocks: %.2f\n", k, worst);

    // The image means: 16384 pixels of 64 light paths' worth each; their noise is a few 0.01%
    // (the block test above bounds it), so 1% is a bias bound.
    for (int c = 0; c < 3; ++c) {
        double sum = 0, ref_sum = 0;
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x) {
                sum += (a.at(x, y, c) + b.at(x, y, c)) / 2;
                ref_sum += ref.at(x, y, c);
            }
        std::printf("channel %d: image mean ratio lt / pt reference %.5f\n", c, sum / ref_sum);
        EXPECT_NEAR(sum / ref_sum, 1.0, 0.01) << "channel " << c;
    }
}

// Splats from every thread land on the film in fixed point, and each light path's random numbers
// depend only on (pixel, iteration, seed): the image does not depend on the number of threads.
TEST(LightTracerCornellBox, OneAndTwoThreadsGiveBitIdenticalImages) {
    std::string dir = scratch_dir("lt-cornell-threads");
    RgbImage a = render(dir, "one", "--integrator lt --spp 4 --seed 11 --threads 1");
    RgbImage b = render(dir, "two", "--integrator lt --spp 4 --seed 11 --threads 2");
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    for (size_t i = 0; i < a.rgb.size(); ++i) ASSERT_EQ(a.rgb[i], b.rgb[i]) << "value " << i;
    // And a different seed does change it (the comparison above is not vacuous).
    RgbImage c = render(dir, "other", "--integrator lt --spp 4 --seed 12 --threads 2");
    size_t differing = 0;
    for (size_t i = 0; i < a.rgb.size(); ++i) differing += a.rgb[i] != c.rgb[i];
    EXPECT_GT(differing, a.rgb.size() / 2);
}

// With a crop window, one light path per rendered pixel is traced per iteration while the camera's
// importance is normalised over the whole frame: splats are scaled by N_full / (N_crop * spp)
// (1/spp alone would make this crop, a quarter of the frame, four times too dark). The crop's
// mean must match the same region of the reference. Its noise at 32 iterations is below 1% (the
// region receives a quarter of the splats of 4096 * 32 paths; the block test above bounds the
// per-block noise), so 4% is a bias bound that a factor of 4 (or 1/4) cannot pass.
TEST(LightTracerCornellBox, CropWindowKeepsTheImageScale) {
    std::string dir = scratch_dir("lt-cornell-crop");
    std::string text = read_text(kScene);
    const std::string film_name = "\"string filename\" \"cornell-box.exr\"";
    size_t at = text.find(film_name);
    ASSERT_NE(at, std::string::npos);
    text.insert(at + film_name.size(), " \"float cropwindow\" [ 0.25 0.75 0.5 1 ]");
    std::string scene = dir + "/crop.pbrt";
    std::FILE *f = std::fopen(scene.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);

    std::string out = dir + "/crop.exr";
    ASSERT_EQ(run_caustica("render " + scene + " --quiet --integrator lt --spp 32 --seed 21 -o " + out), 0);
    RgbImage crop = read_rgb(out);
    RgbImage ref = read_rgb(data_path("renderer/cornell-box.pt-4096spp.exr"));
    ASSERT_EQ(crop.width, ref.width / 2);
    ASSERT_EQ(crop.height, ref.height / 2);
    for (int c = 0; c < 3; ++c) {
        double sum = 0, ref_sum = 0;
        for (int y = 0; y < crop.height; ++y)
            for (int x = 0; x < crop.width; ++x) {
                sum += crop.at(x, y, c);
                ref_sum += ref.at(x + ref.width / 4, y + ref.height / 2, c);
            }
        EXPECT_NEAR(sum / ref_sum, 1.0, 0.04) << "channel " << c;
    }
}

std::string integrator_metadata(const std::string &path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return {};
    return in->spec().get_string_attribute("caustica:integrator");
}

// `--integrator lt` and pbrt's name for it, `lightpath`, are accepted and recorded in the image.
TEST(LightTracerCommandLine, IntegratorNamesAreAccepted) {
    std::string dir = scratch_dir("lt-cli");
    for (const std::string name : {"lt", "lightpath"}) {
        std::string out = dir + "/" + name + ".exr";
        ASSERT_EQ(run_caustica("render " + kScene + " --quiet --spp 1 --resolution 32x32 --integrator " +
                               name + " -o " + out),
                  0)
            << name;
        EXPECT_EQ(integrator_metadata(out), "lt") << name;
        RgbImage img = read_rgb(out);
        double sum = 0;
        for (float v : img.rgb) {
            ASSERT_TRUE(std::isfinite(v));
            sum += v;
        }
        EXPECT_GT(sum, 0) << name;
    }
}

} // namespace
