// The hard-transport suite: every integrator that can render a scene's pixels, on scenes where
// light is hard (the camera and the lights inside fog, a volumetric caustic, a light inside
// glass, a point light seen from under water, chromatic fog, a light emitting one narrow
// spectral line, near-specular dispersive glass, milky glass, a near-specular coat over a
// diffuse base, skin behind a magnifying glass, a ball of dense scattering material under rough
// glass), against pbrt-v4's image of the same file: an
// outside witness, so that a bias shared by all of Caustica's integrators fails too.
//
// References: scripts/make-pbrt-references.sh renders each scenes/hard file twice with pbrt-v4
// (volpath in media, bdpt or path on surfaces; its lightpath ignores media, and its bdpt
// disagrees with its volpath in media) and stores the mean and half the difference
// (tests/data/pbrt-v4/hard). The test needs no pbrt-v4.
//
// The check, for one integrator on one scene: two renders A and B with different seeds, and the
// reference's two halves R1 = mean + difference and R2 = mean - difference.
//   1. The image mean (all pixels and channels of (A + B) / 2) within 1% of the reference's.
//   2. Every 16x16 block and channel: z = (block mean of (A + B) / 2 - reference block mean) /
//      sqrt(var + var_ref), |z| < 5. Each variance is k times its estimate from independent
//      pixels (sum over the block of (A - B)^2 / 4 / n^2), where k >= 1 is measured per image
//      pair as the average over the 48 block-channels of the block-level estimate (block mean of
//      A - B)^2 / 4 over the per-pixel one: splats and merges correlate neighbouring pixels,
//      which the per-pixel estimate ignores. That average of 48 one-degree-of-freedom terms is
//      within about 20% of the true k (sqrt(2 / 48)), so |z| < 5 bounds the true |z| by about
//      4.5, whose two-sided odds are 7e-6 per block-channel, about 1e-2 over the ~3000
//      block-channels of the suite. The sample counts put the image mean's standard error
//      near a quarter of the 1% bound, so check 1 fails a bias of 3% with near certainty.
// Power: CAUSTICA_TEST_FAULT=bias-NAME (src/cli/render_session.cpp) makes one integrator 3% too
// bright; HardTransportPower shows that the check then fails for each integrator.
#include "render_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace caustica::testing;

namespace {

using HardCase = RenderCase;

// A case of the suite against its reference in tests/data/pbrt-v4/hard.
PbrtAgreement check(const HardCase &c, const std::string &fault = "") {
    return pbrt_agreement(std::string("hard/") + c.scene, c.integrator, c.spp, fault);
}

class HardTransport : public ::testing::TestWithParam<HardCase> {};

TEST_P(HardTransport, MatchesPbrtV4) {
    const PbrtAgreement a = check(GetParam());
    EXPECT_LT(a.mean_relative_error, 0.01);
    EXPECT_LT(a.worst_z, 5.0);
}

// Left out, and why:
// - pt where only light paths reach the lit pixels: a point light seen through smooth water
//   (underwater-point);
// - lt where the camera sees the pixels only through a smooth dielectric or sees an environment
//   light directly (light-in-glass, milky-glass, near-specular-glass), which light tracing does
//   not render (README);
// - estimators of infinite variance, whose image mean converges too erratically for a 1% bound
//   at any affordable sample count (their sample variance, and so the stated standard error,
//   means nothing): lt wherever the camera sits in a scattering medium (a light vertex at
//   distance d from the lens contributes as 1/d^2, and the light paths' vertices fill the volume
//   around the lens, so the second moment, the integral of 1/d^4 over that volume, diverges:
//   every fog-* scene but fog-box-spot, and chromatic-fog), and pt on fog-point (next-event
//   estimation towards a point light from vertices that fall near it; the light is out of view,
//   so only vertices after a first scattering event come near it). bdpt, sppm and vcm bound
//   both through their other strategies, or merge;
// - bpm where pure merging with the default radius needs more than ten thousand iterations at
//   64x64 for a standard error of 0.3% (fog-point, fog-small-area and chromatic-fog: small
//   lights in fog); vcm merges in the same way and is in the suite there;
// - lt on skin-lens: the lens and its reflections are seen only through specular surfaces; bpm
//   there: merging alone, inside a volume whose merge radius is a tenth of a mean free path;
// - pt on skin-lens: the lamp's caustic on the skin is seen by pt only when a direction sampled
//   from the skin happens to pass through the lens onto the lamp, and its image mean stays about
//   1.3% below pbrt-v4's at 1024 samples (two seeds; the skin blocks' |z| up to 4), and 0.5%
//   below at 4096 (four seeds, standard error 0.24%): a deficit that shrinks as the samples
//   grow, as a heavy tail's does, at a cost (two minutes a render) the suite cannot pay. Its former
//   rim block (3% low at the lens's edge) was a leak, now mended: entries within 15
//   micrometres of the thin rim were offset past the other face (geometry/ray.h);
// - lt on dense-ball: it reaches the lens only from vertices on the ball's boundary, whose
//   splats are strongly correlated (k about 4); eight renders of 8192 iterations (seeds 1-8)
//   spread by 3.7% of the image mean, so a standard error of 0.3% would take about 100000
//   iterations (twenty minutes); their mean is 1.1% below pbrt-v4's, within its standard error
//   of 1.3%;
//   bpm there: merging alone needs 8192 iterations (two minutes of the suite) for a standard
//   error of 0.3% (it then agrees within 0.4%); vcm merges in the same way and is in the suite;
// - pt, lt and sppm on coated-low-roughness, whose near-specular coat (alpha 0.01) mirrors the
//   small light onto the wall and the wall into the floor: pt finds that caustic only when a
//   bounce off the wall happens to reflect into the light, and lt and sppm meet the coat's spike
//   at light vertices or visible points (the coat's diffuse base makes its BSDF a visible point,
//   as in pbrt-v4) only when a light path happens to arrive within it. These estimators are
//   heavy-tailed there: their image means are within 0.3% of pbrt-v4's, but single blocks fall
//   outside |z| < 5 (pt: 7.0 at 1024 spp, on a block whose mean another seed puts within 0.1%;
//   sppm: 8.5 at 2048 iterations and lt: 11 at 64, both on the near floor's mirror image, which
//   lt has 4% low at 64 iterations and 10% high at 1024 with another seed), the per-pixel
//   variance estimate missing the rare large samples.
const HardCase kCases[] = {
#include "hard_transport_cases.inc"
};

INSTANTIATE_TEST_SUITE_P(Scenes, HardTransport, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<HardCase> &info) { return case_name(info.param); });

// The power of the suite: a 3% bias injected into one integrator fails its check. One case per
// integrator, on a scene where its render is in the suite.
class HardTransportPower : public ::testing::TestWithParam<HardCase> {};

TEST_P(HardTransportPower, ThreePercentBiasFails) {
    const HardCase &c = GetParam();
    ASSERT_GT(c.spp, 0) << c.scene << " " << c.integrator << " is not in the suite";
    EXPECT_FALSE(check(c, std::string("bias-") + c.integrator).passes());
}

const HardCase kPowerCases[] = {
    {"fog-small-area", "pt", 0},  {"fog-box-spot", "lt", 0},    {"fog-small-area", "bdpt", 0},
    {"fog-small-area", "sppm", 0}, {"fog-large-area", "bpm", 0}, {"fog-small-area", "vcm", 0},
};

// The power cases run with the sample count of the same scene and integrator in kCases.
HardCase with_suite_spp(HardCase c) {
    for (const HardCase &s : kCases)
        if (std::string(s.scene) == c.scene && std::string(s.integrator) == c.integrator) c.spp = s.spp;
    return c;
}

INSTANTIATE_TEST_SUITE_P(Integrators, HardTransportPower,
                         ::testing::Values(with_suite_spp(kPowerCases[0]), with_suite_spp(kPowerCases[1]),
                                           with_suite_spp(kPowerCases[2]), with_suite_spp(kPowerCases[3]),
                                           with_suite_spp(kPowerCases[4]), with_suite_spp(kPowerCases[5])),
                         [](const ::testing::TestParamInfo<HardCase> &info) { return std::string(info.param.integrator); });

} // namespace
