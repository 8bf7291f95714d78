// Every integrator against a high-sample reference on the scenes where the radiance/importance
// asymmetry matters (scenes/transport: the pool seen from the air and from under water, a
// diffuse sphere inside a glass cube, a rough glass slab, a dispersive prism), and the
// negative control: with the 1/eta^2 factor deliberately misapplied (CAUSTICA_TEST_FAULT, see
// src/materials/radiance_scaling.h) the same check fails on the under-water scenes.
//
// References: scripts/make-references.sh, the path tracer at 8192 spp with a per-pixel variance
// layer (tests/data/renderer/transport/*.pt-8192spp.exr). The path tracer reaches every path of
// these scenes (their lights are large area lights), without bias.
//
// fog-block and medium-glass-block add participating media (issue #5), fluorescent-stage
// fluorescent surfaces.
//
// The check, for one integrator on one scene: two renders A and B with different seeds.
//   1. The image mean (all pixels and channels of (A + B) / 2) within 1% of the reference's.
//   2. Every 16x16 block and channel: z = (block mean of (A + B) / 2 - reference block mean) /
//      sqrt(var + var_ref) with |z| < 6. var_ref sums the reference's variance layer over the
//      block. var, the variance of the block mean, is k times its estimate from independent
//      pixels, sum over the block of (A - B)^2 / 4 / n^2: splats (light tracing, connections to
//      the lens) and merges (photons shared by neighbouring pixels, wavelength groups shared
//      across the image) correlate neighbouring pixels' errors, which that estimate ignores. k
//      is measured as the average over the 48 block-channels of (block mean of A - B)^2 / 4
//      over the per-pixel estimate: each term is k times a one-degree-of-freedom chi-square
//      over its mean, so the average is within about 20% of k (sqrt(2 / 48)). With k off by
//      30%, |z| < 6 still bounds the true |z| by 5, whose two-sided odds are 6e-7 per
//      block-channel, about 1e-3 over the ~1300 block-channels of the whole test; the bound
//      leaves room for the photon-mapping integrators' small, vanishing radius bias.
// What fails it: a wrong 1/eta^2 (the negative control: the pool floor by a factor 1.77),
// weights that do not sum to one (the light or the caustic twice or not at all), a lost
// strategy (the caustics through the glass go dark), a wrong photon normalisation.
#include "render_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace caustica::testing;

namespace {

using AgreementCase = RenderCase;

struct Agreement {
    double mean_relative_error = 0;
    double worst_z = 0;
    double k = 0;
};

std::string scene_path(const std::string &scene) {
    return std::string(CAUSTICA_SOURCE_DIR) + "/scenes/transport/" + scene + ".pbrt";
}

std::string reference_path(const std::string &scene) {
    return data_path("renderer/transport/" + scene + ".pt-8192spp.exr");
}

Agreement check_agreement(const AgreementCase &c, const std::string &fault = "") {
    const std::string dir = scratch_dir(std::string("agreement-") + c.scene + "-" + c.integrator +
                                        (fault.empty() ? "" : "-" + fault));
    const std::string environment = fault.empty() ? "" : "CAUSTICA_TEST_FAULT=" + fault;
    const RenderPair pair = render_pair(scene_path(c.scene), c.integrator, c.spp, 11, dir, environment);
    const RgbImage(&runs)[2] = pair.runs;
    const RgbImage reference = read_rgb(reference_path(c.scene));
    const RgbImage reference_variance = read_layer(reference_path(c.scene), "variance");
    EXPECT_EQ(runs[0].width, reference.width);
    EXPECT_EQ(runs[0].height, reference.height);

    Agreement result;
    double sum = 0, reference_sum = 0;
    for (size_t i = 0; i < reference.rgb.size(); ++i) {
        sum += (runs[0].rgb[i] + runs[1].rgb[i]) / 2;
        reference_sum += reference.rgb[i];
    }
    result.mean_relative_error = std::abs(sum - reference_sum) / reference_sum;

    const int block = 16;
    const std::vector<BlockEstimate> blocks = block_estimates(runs[0], runs[1], block);
    result.k = correlation_factor(blocks);
    size_t i = 0;
    for (int by = 0; by + block <= reference.height; by += block)
        for (int bx = 0; bx + block <= reference.width; bx += block)
            for (int channel = 0; channel < 3; ++channel, ++i) {
                double var_ref = 0;
                for (int y = by; y < by + block; ++y)
                    for (int x = bx; x < bx + block; ++x) var_ref += reference_variance.at(x, y, channel);
                var_ref /= double(block * block) * (block * block);
                const double var = result.k * blocks[i].variance_from_pixels;
                const double z = (blocks[i].mean - block_mean(reference, bx, by, block, channel)) /
                                 std::sqrt(var + var_ref + 1e-30);
                result.worst_z = std::max(result.worst_z, std::abs(z));
            }
    std::printf("%s %s%s: mean error %.3f%%, correlation factor k %.2f, largest |z| %.2f\n", c.scene,
                c.integrator, fault.empty() ? "" : (" with fault " + fault).c_str(),
                100 * result.mean_relative_error, result.k, result.worst_z);
    return result;
}

class TransportAgreement : public ::testing::TestWithParam<AgreementCase> {};

TEST_P(TransportAgreement, MatchesPathTracerReference) {
    Agreement a = check_agreement(GetParam());
    EXPECT_LT(a.mean_relative_error, 0.01);
    EXPECT_LT(a.worst_z, 6.0);
}

// Sample counts (iterations for lt, sppm, bpm, vcm) give each render one to five seconds and
// keep the image mean's noise near a quarter of the 1% bound. The
// light tracer is left out where the camera sees diffuse surfaces only through a smooth
// dielectric (the pool from the air, the sphere in the glass, the floor behind the prism):
// a light vertex there cannot be connected to the lens through the interface, so light tracing
// alone does not render those pixels (it is exercised in the other integrators' strategies).
const AgreementCase kCases[] = {
    {"pool-air", "pt", 64},          {"pool-air", "bdpt", 64},         {"pool-air", "sppm", 256},
    {"pool-air", "bpm", 512},         {"pool-air", "vcm", 64},
    {"pool-underwater", "pt", 64},   {"pool-underwater", "lt", 256},    {"pool-underwater", "bdpt", 64},
    {"pool-underwater", "sppm", 256}, {"pool-underwater", "bpm", 128},   {"pool-underwater", "vcm", 64},
    {"glass-block", "pt", 64},       {"glass-block", "bdpt", 32},      {"glass-block", "sppm", 512},
    {"glass-block", "bpm", 128},      {"glass-block", "vcm", 64},
    {"rough-glass-slab", "pt", 64},  {"rough-glass-slab", "lt", 256},   {"rough-glass-slab", "bdpt", 32},
    {"rough-glass-slab", "sppm", 256},{"rough-glass-slab", "bpm", 256},  {"rough-glass-slab", "vcm", 64},
    {"prism", "pt", 64},             {"prism", "bdpt", 32},            {"prism", "sppm", 256},
    {"prism", "bpm", 128},            {"prism", "vcm", 64},
    // Participating media: camera and light paths scatter in fog around a diffuse sphere, and
    // inside a glass cube (photons deposited inside a refractive medium, merged with a 3D
    // kernel). lt is left out of the cube for the reason above.
    {"fog-block", "pt", 64},          {"fog-block", "lt", 256},          {"fog-block", "bdpt", 32},
    {"fog-block", "sppm", 256},       {"fog-block", "bpm", 128},          {"fog-block", "vcm", 64},
    {"medium-glass-block", "pt", 64}, {"medium-glass-block", "bdpt", 64}, {"medium-glass-block", "sppm", 256},
    {"medium-glass-block", "bpm", 128},{"medium-glass-block", "vcm", 64},
    // Fluorescence: light re-radiated once or twice, which only camera subpaths carry (light
    // subpaths cannot meet them at a wavelength they drew themselves; path_tracing.h), beside
    // the elastic light that every strategy carries. The path tracer, the reference, meets the
    // closed form of a fluorescent plane (fluorescence_test.cpp). The photon integrators need
    // more iterations here: their wavelength groups share the film's wavelengths across the
    // image, and the light's lines pull half of those into the ultraviolet (wavelength_density.h),
    // so their colour noise is image-wide, which the block estimates do not see.
    {"fluorescent-stage", "pt", 64},  {"fluorescent-stage", "lt", 256},  {"fluorescent-stage", "bdpt", 32},
    {"fluorescent-stage", "sppm", 2048},{"fluorescent-stage", "bpm", 1024}, {"fluorescent-stage", "vcm", 1024},
};

INSTANTIATE_TEST_SUITE_P(Scenes, TransportAgreement, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<AgreementCase> &info) { return case_name(info.param); });

// The negative control. Under water, light crosses the surface once: dropping 1/eta^2 from
// radiance leaves the path tracer's floor 1.77 times too dark, and applying it to importance
// too leaves photons and light-traced paths 1.77 times too weak. Either error is tens of
// standard errors, so the check must fail. (From the air the camera path's two crossings
// cancel, which is why the under-water scene is the one that catches a dropped factor.)
bool agrees(const Agreement &a) { return a.mean_relative_error < 0.01 && a.worst_z < 6.0; }

TEST(TransportAgreementNegativeControl, RadianceWithoutEtaFactorFailsUnderWater) {
    EXPECT_FALSE(agrees(check_agreement({"pool-underwater", "pt", 64}, "eta-drop")));
}

TEST(TransportAgreementNegativeControl, ImportanceWithEtaFactorFailsUnderWater) {
    EXPECT_FALSE(agrees(check_agreement({"pool-underwater", "sppm", 256}, "eta-importance")));
    EXPECT_FALSE(agrees(check_agreement({"pool-underwater", "lt", 256}, "eta-importance")));
}

} // namespace
