// pbrt-v4's MIP map (src/textures/mipmap.h) against closed forms: the pyramid's levels, the
// resampling of sides that are not powers of two, and each filter's value for footprints whose
// answer is known.
#include "textures/checkerboard_texture.h"
#include "textures/mipmap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace caustica;

namespace {

std::shared_ptr<const TexelImage> image(int w, int h, const std::function<float(int, int)> &value) {
    std::vector<float> texels;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) texels.push_back(value(x, y));
    return std::make_shared<TexelImage>(w, h, 1, std::move(texels));
}

float lookup(const MIPMap &m, Vec2f st, Vec2f dst0 = {0, 0}, Vec2f dst1 = {0, 0}) {
    float v = 0;
    m.filter(st, dst0, dst1, &v);
    return v;
}

// Each level is the 2x2 mean of the one below; a side of 1 stays 1; the top is the mean.
TEST(MIPMap, PyramidAveragesTwoByTwo) {
    const MIPMap m(image(4, 2, [](int x, int y) { return float(x + 4 * y); }), ImageWrap::Repeat, MIPFilter::Bilinear, 8);
    ASSERT_EQ(m.levels(), 3);
    EXPECT_EQ(m.level(1).width(), 2);
    EXPECT_EQ(m.level(1).height(), 1);
    EXPECT_FLOAT_EQ(m.level(1).texel(0, 0, 0, ImageWrap::Clamp), (0 + 1 + 4 + 5) / 4.f);
    EXPECT_FLOAT_EQ(m.level(1).texel(1, 0, 0, ImageWrap::Clamp), (2 + 3 + 6 + 7) / 4.f);
    EXPECT_FLOAT_EQ(m.level(2).texel(0, 0, 0, ImageWrap::Clamp), 3.5f);
}

// Sides that are not powers of two are resampled up with normalised weights: a constant stays
// that constant, and a ramp stays a ramp of the same slope per unit of s inside the image.
TEST(MIPMap, ResamplesOtherSidesUpToPowersOfTwo) {
    const MIPMap constant(image(3, 5, [](int, int) { return 0.7f; }), ImageWrap::Clamp, MIPFilter::Bilinear, 8);
    EXPECT_EQ(constant.level(0).width(), 4);
    EXPECT_EQ(constant.level(0).height(), 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 4; ++x) EXPECT_NEAR(constant.level(0).texel(x, y, 0, ImageWrap::Clamp), 0.7f, 1e-6f);
    // A ramp in x over 24 texels: its middle, resampled to 32, follows the ramp at the same s
    // (a windowed sinc reproduces a ramp only nearly; a shift of half a texel would be 0.375).
    const MIPMap ramp(image(24, 1, [](int x, int) { return float(x); }), ImageWrap::Clamp, MIPFilter::Bilinear, 8);
    for (float s : {0.3f, 0.45f, 0.6f}) EXPECT_NEAR(lookup(ramp, {s, 0.5f}), s * 24 - 0.5f, 0.05f);
}

// A checker of 2x2 blocks of texels 0 and 2: levels 0 and 1 are checkers, every level above is
// 1. Trilinear lookups blend the two levels around the footprint's level, except below level 1,
// where pbrt-v4 reads level 0 alone; bilinear and point lookups use the lower level.
TEST(MIPMap, TrilinearBlendsTheTwoNearestLevels) {
    const auto checker = image(8, 8, [](int x, int y) { return (x / 2 + y / 2) % 2 ? 0.f : 2.f; });
    const MIPMap tri(checker, ImageWrap::Repeat, MIPFilter::Trilinear, 8);
    const MIPMap bi(checker, ImageWrap::Repeat, MIPFilter::Bilinear, 8);
    const MIPMap point(checker, ImageWrap::Repeat, MIPFilter::Point, 8);
    const Vec2f centre{1.f / 8, 1.f / 8}; // level 1's texel (0, 0), value 2; a corner of level 0's
    EXPECT_FLOAT_EQ(lookup(tri, {0.5f / 8, 0.5f / 8}), 2.f);
    // level = (levels - 1) + log2(width), width = 2 max|d|, levels - 1 = 3.
    const auto footprint = [](float level) { return std::exp2(level - 3) / 2; };
    const float d05 = footprint(0.5f), d15 = footprint(1.5f), d25 = footprint(2.5f);
    EXPECT_NEAR(lookup(tri, {0.5f / 8, 0.5f / 8}, {d05, 0}, {0, d05}), 2.f, 1e-5f);
    EXPECT_NEAR(lookup(tri, centre, {d15, 0}, {0, d15}), 0.5f * 2 + 0.5f * 1, 1e-5f);
    EXPECT_NEAR(lookup(bi, centre, {d15, 0}, {0, d15}), 2.f, 1e-5f);
    EXPECT_NEAR(lookup(point, centre, {d15, 0}, {0, d15}), 2.f, 1e-5f);
    EXPECT_NEAR(lookup(tri, centre, {d25, 0}, {0, d25}), 1.f, 1e-5f);
    EXPECT_NEAR(lookup(tri, centre, {4, 0}, {0, 4}), 1.f, 1e-5f); // past the top: its one texel
}

// EWA's weights fall off symmetrically about the lookup point, so on a linear ramp it returns
// the ramp's value there, to within the asymmetry of the texel grid about the point (a fraction
// of a texel; a shift of half a texel would be 0.5), whatever the ellipse (isotropic, long along
// the ramp, across it, or clamped to the maximum anisotropy), on every level, since averaging
// keeps a ramp a ramp.
TEST(MIPMap, EwaReturnsARampsValue) {
    const MIPMap ewa(image(64, 64, [](int x, int y) { return float(x) + 0.5f * float(y); }), ImageWrap::Clamp,
                     MIPFilter::EWA, 8);
    const Vec2f st{0.42f, 0.55f};
    const float expected = (st.x * 64 - 0.5f) + 0.5f * (st.y * 64 - 0.5f);
    EXPECT_NEAR(lookup(ewa, st), expected, 1e-3f); // no footprint: bilinear
    for (const auto &[d0, d1] : {std::pair{Vec2f{0.01f, 0}, Vec2f{0, 0.01f}}, {Vec2f{0.04f, 0.01f}, Vec2f{-0.002f, 0.008f}},
                                 {Vec2f{0, 0.05f}, Vec2f{0.003f, 0}}, {Vec2f{0.1f, 0.1f}, Vec2f{0.0001f, -0.0001f}}})
        EXPECT_NEAR(lookup(ewa, st, d0, d1), expected, 0.15f) << d0.x << " " << d0.y << " " << d1.x << " " << d1.y;
}

// A constant image filters to that constant, however wide or thin the ellipse.
TEST(MIPMap, EwaKeepsAConstant) {
    const MIPMap ewa(image(16, 16, [](int, int) { return 0.3f; }), ImageWrap::Repeat, MIPFilter::EWA, 8);
    EXPECT_NEAR(lookup(ewa, {0.1f, 0.9f}, {0.3f, 0}, {0, 1e-4f}), 0.3f, 1e-6f);
    EXPECT_NEAR(lookup(ewa, {0.1f, 0.9f}, {5, 5}, {-5, 5}), 0.3f, 1e-6f);
    EXPECT_NEAR(lookup(ewa, {0.1f, 0.9f}, {NAN, 0}, {0, 0}), 0.3f, 1e-6f); // a broken footprint: none
}

// A repeating image is looked up the same any whole number of repeats away, however far.
TEST(MIPMap, RepeatsFarAway) {
    const MIPMap ewa(image(16, 16, [](int x, int y) { return float(x * 16 + y); }), ImageWrap::Repeat, MIPFilter::EWA, 8);
    const Vec2f st{0.37f, 0.61f}, d0{0.02f, 0.01f}, d1{-0.004f, 0.01f};
    EXPECT_FLOAT_EQ(lookup(ewa, {st.x + 3, st.y - 7}, d0, d1), lookup(ewa, st, d0, d1));
    EXPECT_TRUE(std::isfinite(lookup(ewa, {3e9f, -5e8f}, d0, d1)));
    const MIPMap clamped(image(16, 16, [](int x, int) { return float(x); }), ImageWrap::Clamp, MIPFilter::Trilinear, 8);
    EXPECT_FLOAT_EQ(lookup(clamped, {4e9f, 0.5f}), 15.f);
}

// pbrt-v4's filtered checkerboard: the sharp pattern without a footprint, the even mix at a
// cell edge, and the mean when the footprint spans many cells.
TEST(CheckerboardFilter, BlendsByTheFootprint) {
    TexCoord2D c;
    c.st = {0.5f, 0.5f};
    EXPECT_FLOAT_EQ(checkerboard_weight(c), 0.f);
    c.st = {1.5f, 0.5f};
    EXPECT_FLOAT_EQ(checkerboard_weight(c), 1.f);
    c.st = {1.0f, 0.5f};
    c.dsdx = c.dtdy = 0.1f;
    EXPECT_NEAR(checkerboard_weight(c), 0.5f, 1e-5f);
    c.st = {0.37f, 0.81f};
    c.dsdx = c.dtdy = 40.f;
    EXPECT_NEAR(checkerboard_weight(c), 0.5f, 1e-3f);
}

} // namespace
