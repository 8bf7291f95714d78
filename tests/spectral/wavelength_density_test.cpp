// The wavelength density fitted to a scene's emission (spectral/wavelength_density.h): half the
// visible density, half the visible density times the emitted power, tabulated per nanometre.
#include "spectral/wavelength_density.h"

#include "core/vecmath.h"
#include "spectral/sampled_wavelengths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace caustica {
namespace {

// The integral of the density over [a, b], by the midpoint rule at 0.01 nm.
double integral(const WavelengthDensity &d, float a, float b) {
    double sum = 0;
    for (double lambda = a + 0.005; lambda < b; lambda += 0.01) sum += d.pdf(float(lambda)) * 0.01;
    return sum;
}

double visible_integral(float a, float b) {
    double sum = 0;
    for (double lambda = a + 0.005; lambda < b; lambda += 0.01) sum += visible_wavelengths_pdf(float(lambda)) * 0.01;
    return sum;
}

// pbrt-v4's sodium-like lamp, "spectrum L" [585 0 589 10 593 0].
float sodium_line(float lambda) { return std::max(0.f, 10 - 2.5f * std::abs(lambda - 589)); }

TEST(WavelengthDensity, FlatOrNoEmissionGivesTheVisibleDensity) {
    // Both halves are the visible density when the power is flat; without visible power there is
    // only the visible half. Per 1-nm bin the table holds the bin's mean.
    for (const WavelengthDensity &d : {WavelengthDensity([](float) { return 3.f; }),
                                       WavelengthDensity([](float) { return 0.f; }),
                                       WavelengthDensity([](float lambda) { return lambda < 300 ? 1.f : 0.f; })}) {
        for (float lambda = LambdaMin; lambda < LambdaMax; lambda += 0.5f)
            EXPECT_NEAR(d.pdf(lambda), visible_integral(std::floor(lambda), std::floor(lambda) + 1), 1e-6f)
                << lambda;
        EXPECT_NEAR(integral(d, LambdaMin, LambdaMax), 1, 1e-4);
    }
}

TEST(WavelengthDensity, HalfTheWavelengthsFallInANarrowLine) {
    const WavelengthDensity d(sodium_line);
    EXPECT_NEAR(integral(d, LambdaMin, LambdaMax), 1, 1e-4);
    // Half of the density is the line's own (all of its emission lies in 585-593 nm), plus the
    // visible half's share of those 8 nm.
    EXPECT_NEAR(integral(d, 585, 593), 0.5 + 0.5 * visible_integral(585, 593), 2e-4);
    // Outside the line, exactly half the visible density: no weight grows by more than 2.
    EXPECT_NEAR(d.pdf(450.5f), 0.5 * visible_integral(450, 451), 1e-6);
    EXPECT_EQ(d.pdf(LambdaMin - 1), 0);
    EXPECT_EQ(d.pdf(LambdaMax + 1), 0);
}

TEST(WavelengthDensity, SamplingInvertsTheCumulativeDistribution) {
    // Stratified uniforms put the fraction of samples in any interval within 1/N of the density's
    // integral over it, and the sampled wavelengths rise with u.
    const WavelengthDensity d([](float lambda) { return sodium_line(lambda) + 0.3f * (lambda > 700); });
    constexpr int N = 100000;
    std::vector<float> samples;
    for (int i = 0; i < N; ++i) samples.push_back(d.sample((i + 0.5f) / N));
    EXPECT_TRUE(std::is_sorted(samples.begin(), samples.end()));
    EXPECT_GE(samples.front(), LambdaMin);
    EXPECT_LE(samples.back(), LambdaMax);
    for (auto [a, b] : {std::pair{360.f, 500.f}, {585.f, 589.f}, {589.f, 593.f}, {700.f, 830.f}, {586.3f, 586.7f}}) {
        const double fraction = double(std::count_if(samples.begin(), samples.end(),
                                                     [&](float l) { return l >= a && l < b; })) / N;
        EXPECT_NEAR(fraction, integral(d, a, b), 2.0 / N + 1e-4) << a << "-" << b;
    }
    for (float u : {0.f, 0.25f, 0.5f, 0.999f, OneMinusEpsilon}) EXPECT_GT(d.pdf(d.sample(u)), 0) << u;
}

TEST(WavelengthDensity, HeroSetsRotateInSampleSpace) {
    // Member i is the density's inverse at u + i/n (mod 1), so every member has the density itself.
    const WavelengthDensity d(sodium_line);
    const float u = 0.83f;
    const SampledWavelengths lambda = SampledWavelengths::sample(d, u);
    for (int i = 0; i < NumWavelengths; ++i) {
        const float rotated = std::fmod(u + float(i) / NumWavelengths, 1.f);
        EXPECT_FLOAT_EQ(lambda[i], d.sample(rotated));
        EXPECT_FLOAT_EQ(lambda.pdf()[i], d.pdf(lambda[i]));
    }
    // The line holds just over half of sample space, so at least two of the four members, at
    // any u.
    for (float v = 0; v < 1; v += 0.01f) {
        const SampledWavelengths set = SampledWavelengths::sample(d, v);
        int in_line = 0;
        for (int i = 0; i < NumWavelengths; ++i) in_line += set[i] > 585 && set[i] < 593;
        EXPECT_GE(in_line, 2) << v;
    }
    const SampledWavelengths single = SampledWavelengths::sample_single(d, u);
    EXPECT_TRUE(single.secondary_terminated());
    EXPECT_FLOAT_EQ(single.pdf()[0], d.pdf(single[0]) / NumWavelengths);
}

} // namespace
} // namespace caustica
