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

// Alpha cut-outs ("alpha" on shapes), scenes/textures/alpha-cutouts.pbrt, in every integrator:
// checkerboard cut-outs in a triangle mesh, a cylinder and the emitting lamp itself, a sphere
// with constant alpha 0.5 (stochastic transparency), and leaves in object instances, cut by the
// alpha channel of an RGBA image whose RGB colours them.
// Every ray, camera, light or shadow, must meet the same mask, and light paths must start only
// where the lamp is there. Negative controls (one run each, then undone):
// - the lamp emitting over its cut squares too: pt, lt and bdpt 78% too bright (|z| 126 to 218);
// - a cut-out analytic shape letting rays on past its first hit only, not to its far side (the
//   sphere's inside unseen): pt 2.3% off (|z| 24), bdpt 2.5% (|z| 27), vcm 2.4% (|z| 40);
// - bdpt skipping next-event estimation when its light subpath did not start (the lamp's cut
//   squares): 22% too dark (|z| 67);
// - photon density on the sphere (alpha 0.5) not divided by its coverage: sppm 1.3% and bpm
//   1.6% too dark (|z| 9 and 5.7 on the sphere);
// - the leaves' float texture reading the mean of R, G and B rather than the alpha channel:
//   pt |z| 7.2. (Colours multiplied by alpha, as OpenImageIO reads PNGs by default, stay within
//   the bounds here, |z| 3.0: the soft edge is a few pixels; image_texture_test.cpp tests it.)
INSTANTIATE_TEST_SUITE_P(AlphaCutouts, PbrtWitness,
                         ::testing::Values(RenderCase{"textures/alpha-cutouts", "pt", 256},
                                           RenderCase{"textures/alpha-cutouts", "lt", 256},
                                           RenderCase{"textures/alpha-cutouts", "bdpt", 128},
                                           RenderCase{"textures/alpha-cutouts", "sppm", 256},
                                           RenderCase{"textures/alpha-cutouts", "bpm", 256},
                                           RenderCase{"textures/alpha-cutouts", "vcm", 256}),
                         witness_case_name);

// pbrt-v4's MIP-map filters ("point", "bilinear", "trilinear", "ewa") over the footprint of a
// pixel (ray differentials at the camera's first hit, the camera's approximate footprint at every
// other vertex), scenes/textures/mip-filtering.pbrt: a checker of texels 0 and 2 whose albedo
// is clamped at 1, so that each pixel shows how many texels the lookups averaged, on strips of
// ground receding to the horizon under a white sky. Camera subpaths take the camera ray's
// footprint at their first surface, light subpaths (and later vertices) the approximate one.
// In every integrator but lt, which cannot see the sky (a light tracer reaches the camera only
// from surfaces; with a wide emitter in the sky's place instead, its few light paths per
// near-ground pixel leave the test without power). lt sees the ground through the approximate
// footprint only, as pbrt-v4's lightpath does.
// Negative controls (one run each, then undone):
// - no footprint (every lookup at the finest level): pt, bdpt and vcm 2.4% dark, |z| 95 to 101;
// - the approximate footprint at the camera's first hit too: pt and bdpt 0.9% dark, |z| 71 and 74.
INSTANTIATE_TEST_SUITE_P(MIPFiltering, PbrtWitness,
                         ::testing::Values(RenderCase{"textures/mip-filtering", "pt", 64},
                                           RenderCase{"textures/mip-filtering", "bdpt", 64},
                                           RenderCase{"textures/mip-filtering", "sppm", 64},
                                           RenderCase{"textures/mip-filtering", "bpm", 64},
                                           RenderCase{"textures/mip-filtering", "vcm", 64}),
                         witness_case_name);

} // namespace
