// Textures and shading-normal perturbations against pbrt-v4's own images of the same files, with
// the hard-transport suite's check (render_test_support.h: image mean within 1%, every 16x16
// block and channel within |z| < 5 of the reference).
//
// pbrt-v4's procedural textures (fbm, wrinkled, windy, marble, dots), scenes/textures/
// noise-textures.pbrt: diffuse panels under a uniform white environment,
// where each pixel is the texture's albedo averaged over the pixel. With 64 samples per pixel the image mean's standard
// error is far below the 1% bound, and a block's z measures the pattern itself. Negative
// controls (one run each, then undone): turbulence without its 0.2 allowance for the clamped
// octave (the wrinkled panel 1.4% darker) fails with |z| 10; octaves at 2x rather than 1.99x
// the frequency fail with |z| 67.
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

TEST(ProceduralTextures, NoiseTexturesMatchPbrtV4) {
    expect_agreement_with_pbrt("textures/noise-textures", "pt", 64);
}

// Bump mapping ("displacement") and normal mapping ("normalmap") on flat squares under a slanting
// distant light, scenes/textures/bump-and-normal-map.pbrt: the shading normal's tilt decides
// every pixel. Negative controls (one run each, then undone): the bump gradient's sign flipped
// along u fails with |z| 37; the normal map read upside down (v for 1 - v) with |z| 325.
TEST(ShadingNormals, BumpAndNormalMapsMatchPbrtV4) {
    expect_agreement_with_pbrt("textures/bump-and-normal-map", "pt", 64);
}

} // namespace
