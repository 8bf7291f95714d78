// Free-flight sampling over a whole subpath (integrators/common/path_segment.h, SpectralMIS):
// walks of many scattering events in an infinite medium whose four wavelengths have very
// different extinctions, the case where long random walks in bright, saturated subsurface
// volumes fell short (docs/media.md).
#include "integrators/common/path_segment.h"
#include "media/homogeneous_medium.h"
#include "sampler/independent_sampler.h"

#include <gtest/gtest.h>

#include <cmath>

namespace caustica {
namespace {

// In an infinite homogeneous medium every segment ends in a scattering event, and a walk of N
// events has f_i = prod sigma_s,i T_i(t_j); integrated over the N distances, alpha_i^N with
// alpha_i = sigma_s,i / sigma_t,i. So per wavelength:
//   - the walk's weight (the product of its segments' weights) has mean alpha_i^N;
//   - it never exceeds NumWavelengths alpha_i^N, the balance heuristic's bound f_i / mean_k p_k
//     <= NumWavelengths f_i / p_i (spectral_mis.h).
// The extinctions (40 60 80 97) and albedos (0.9 to 0.998) are those of a saturated colour's
// random walk at scatter distance 0.01 (docs/media.md). Means are checked within 5 standard
// errors of 20,000 walks, which the bound makes reliable (a bounded weight's mean is close to
// normal). Weighing each event on its own, with a fresh wavelength per event, as Caustica did
// before, has no such bound; emulated with these parameters and counts (a short Python script,
// not kept), its worst walks were 13 to 1666 times alpha_i^N and wavelength 0's mean 0.68 of
// alpha_0^N, failing both checks.
TEST(SpectralMIS, LongChromaticWalksAreUnbiasedAndBounded) {
    const SampledSpectrum sigma_t(40, 60, 80, 97);
    const SampledSpectrum albedo(0.9f, 0.95f, 0.99f, 0.998f);
    const SampledHomogeneousMedium medium(sigma_t * (SampledSpectrum(1.f) - albedo), sigma_t * albedo, 0, nullptr);
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.35f);
    constexpr int Events = 60, Walks = 20000;
    IndependentSampler sampler(Walks, 7);
    double sum[NumWavelengths] = {}, sum2[NumWavelengths] = {};
    float worst[NumWavelengths] = {};
    int lanes[NumWavelengths] = {};
    for (int w = 0; w < Walks; ++w) {
        sampler.start_pixel_sample({0, 0}, w);
        SpectralMIS mis;
        SampledSpectrum weight(1.f);
        for (int e = 0; e < Events; ++e) {
            const PathSegment segment = traverse_segment(&medium, nullptr, Ray{}, Infinity, lambda, sampler, mis);
            ASSERT_TRUE(segment.scattered);
            weight *= segment.weight;
        }
        ++lanes[mis.lane(lambda, sampler)];
        for (int i = 0; i < NumWavelengths; ++i) {
            sum[i] += weight[i];
            sum2[i] += double(weight[i]) * weight[i];
            worst[i] = std::max(worst[i], float(weight[i] / std::pow(double(albedo[i]), Events)));
        }
    }
    for (int i = 0; i < NumWavelengths; ++i) {
        const double expected = std::pow(double(albedo[i]), Events);
        const double mean = sum[i] / Walks;
        const double standard_error = std::sqrt(std::max(0.0, sum2[i] / Walks - mean * mean) / Walks);
        EXPECT_NEAR(mean, expected, 5 * standard_error + 1e-6 * expected) << "wavelength " << i;
        EXPECT_LE(worst[i], NumWavelengths * (1 + 1e-3f)) << "wavelength " << i;
        // Every wavelength samples about a quarter of the walks.
        EXPECT_NEAR(lanes[i], Walks / NumWavelengths, 0.05 * Walks) << "lane " << i;
    }
}

} // namespace
} // namespace caustica
