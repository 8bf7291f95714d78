// The statistics of `caustica compare` on synthetic renders with known noise and bias: the
// error estimated from two renders (cli/two_run_noise.h) and the agreement test between two
// integrators (cli/render_agreement.h). The suites are named Compare* so that the compare tests
// run together (--gtest_filter='*Compare*').
#include "cli/render_agreement.h"
#include "cli/two_run_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>

using caustica::Agreement;
using caustica::Image;
using caustica::TwoRuns;

namespace {

constexpr int kSize = 64; // 8x8-pixel blocks then (64 of them)
constexpr int kFilterRadius = 2, kFilterWidth = 2 * kFilterRadius + 1;

// Standard normal numbers from a generator whose sequence the C++ standard fixes (mt19937_64)
// through Box-Muller, so every run of the tests sees the same numbers.
class Normal {
  public:
    explicit Normal(uint64_t seed) : engine_(seed) {}
    double operator()() {
        const double u1 = (double(engine_() >> 11) + 0.5) * 0x1p-53, u2 = double(engine_() >> 11) * 0x1p-53;
        return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
    }

  private:
    std::mt19937_64 engine_;
};

// The expected image: a ramp from 0.5 to 1.5 across, a different level per channel.
double expected(int x, int, int c) { return 0.5 + double(x) / kSize + 0.1 * c; }

// One synthetic render of the expected image times `gain`, with noise correlated like a
// render's: white noise of standard deviation `sigma` (a part shared by the three channels, as
// they share their paths) spread over 5x5 pixels by a box filter, as a pixel filter spreads a
// sample. Per pixel the noise is then sigma / 5, but the image mean's noise is sigma / sqrt(n):
// an estimate that ignored the correlation would make z several times too large.
Image synthetic_render(uint64_t seed, double sigma, double gain = 1) {
    Normal normal(seed);
    const size_t n = size_t(kSize) * kSize * 3;
    std::vector<double> noise(n), rows(n);
    for (size_t p = 0; p < n / 3; ++p) {
        const double shared = normal();
        for (int c = 0; c < 3; ++c) noise[p * 3 + c] = sigma * (0.8 * shared + 0.6 * normal());
    }
    // The box filter, separably: along rows, then along columns. Periodic at the edges, so every
    // pixel has the same noise.
    auto at = [](int x, int y, int c) { return (size_t((y + kSize) % kSize) * kSize + (x + kSize) % kSize) * 3 + c; };
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (int d = -kFilterRadius; d <= kFilterRadius; ++d) sum += noise[at(x + d, y, c)];
                rows[at(x, y, c)] = sum / kFilterWidth;
            }
    Image image(kSize, kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (int d = -kFilterRadius; d <= kFilterRadius; ++d) sum += rows[at(x, y + d, c)];
                image.at(x, y, c) = float(gain * expected(x, y, c) + sum / kFilterWidth);
            }
    return image;
}

TwoRuns synthetic_runs(uint64_t seed, double sigma, double gain = 1) {
    return TwoRuns(synthetic_render(2 * seed, sigma, gain), synthetic_render(2 * seed + 1, sigma, gain));
}

// The estimate from two renders matches the known error of their average: with noise of
// variance v per pixel channel in each render, the average's is v / 2, so its RMSE is
// sqrt(v / 2) and its relative MSE the mean of (v / 2) / (r^2 + 0.01). 4096 pixels give the
// estimate a spread of about 4% (neighbours are correlated), its square root 2%; 12% and 5% bound them.
TEST(CompareNoiseEstimate, MatchesTheKnownErrorOfTheAverage) {
    const double sigma = 0.3;
    // Per channel: sigma^2 (0.8^2 + 0.6^2) = sigma^2 before the box filter, / 25 after it.
    const double variance_of_mean = sigma * sigma / (kFilterWidth * kFilterWidth) / 2;
    double relative_mse = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c = 0; c < 3; ++c) {
                const double r = expected(x, y, c);
                relative_mse += variance_of_mean / (r * r + 0.01);
            }
    relative_mse /= kSize * kSize * 3;

    const caustica::RenderError estimate = caustica::estimated_error(synthetic_runs(1, sigma));
    EXPECT_NEAR(estimate.rmse, std::sqrt(variance_of_mean), 0.05 * std::sqrt(variance_of_mean));
    EXPECT_NEAR(estimate.relative_mse, relative_mse, 0.12 * relative_mse);
}

// A negative control: renders of the same expected image agree. Over 400 pairs of pairs of
// renders the image-mean z has the spread of a standard normal variable: its standard deviation
// is 0.99 here, within [0.85, 1.12] (sampling alone spreads it by 0.035); leaving out the
// covariance of neighbouring blocks gives 1.17, ignoring the pixels' correlation altogether
// about 4. At a false-alarm rate of 1e-4 per test, none of the 400 is reported as disagreeing.
TEST(CompareAgreement, RendersOfTheSameImageAgree) {
    double sum = 0, squares = 0;
    int disagreements = 0;
    const int pairs = 400;
    for (int i = 0; i < pairs; ++i) {
        const Agreement a = caustica::check_agreement("pt", synthetic_runs(4 * i, 0.3), "bdpt",
                                                      synthetic_runs(4 * i + 2, 0.3));
        sum += a.z;
        squares += a.z * a.z;
        disagreements += !a.agree;
        EXPECT_EQ(a.block_size, 8);
        EXPECT_EQ(a.blocks, 64);
    }
    const double mean = sum / pairs, deviation = std::sqrt(squares / pairs - mean * mean);
    EXPECT_GT(deviation, 0.85);
    EXPECT_LT(deviation, 1.12);
    EXPECT_EQ(disagreements, 0);
}

// A 3% bias of one integrator, the size of the renderer's test fault (CAUSTICA_TEST_FAULT=
// bias-NAME), is reported as a disagreement in the image mean: with this noise the difference's
// standard error is about 0.33%, so the difference is 9 of them; with the variance estimated
// from 64 blocks that is a normal-equivalent z of about -5, beyond the threshold of 3.89.
TEST(CompareAgreement, AThreePercentBiasDisagrees) {
    const Agreement a = caustica::check_agreement("pt", synthetic_runs(1, 0.3), "vcm", synthetic_runs(2, 0.3, 1.03));
    EXPECT_FALSE(a.agree);
    EXPECT_NEAR(a.relative_difference, -0.03, 0.005);
    EXPECT_LT(a.z, -a.threshold);
    const std::string sentence = caustica::agreement_sentence(a);
    EXPECT_EQ(sentence.rfind("DISAGREE: pt and vcm differ by ", 0), 0u) << sentence;
    EXPECT_NE(sentence.find("% in image mean (z = -"), std::string::npos) << sentence;

    const Agreement same = caustica::check_agreement("pt", synthetic_runs(1, 0.3), "vcm", synthetic_runs(2, 0.3));
    EXPECT_TRUE(same.agree);
    EXPECT_EQ(caustica::agreement_sentence(same).rfind("agree: pt and vcm differ by ", 0), 0u);
}

// A local bias, one 8x8 block 40% brighter in one integrator (a caustic the other misses), moves
// the image mean by only 0.8%, under its threshold, but its block stands out: 17 standard errors,
// a normal-equivalent z of about -6 (the block's variance is estimated from few independent
// values), beyond the Bonferroni threshold for 64 blocks (4.8), and it is the block reported.
TEST(CompareAgreement, ALocalBiasIsFoundInItsBlock) {
    TwoRuns biased = synthetic_runs(2, 0.3);
    for (int y = 24; y < 32; ++y)
        for (int x = 40; x < 48; ++x)
            for (int c = 0; c < 3; ++c) biased.mean.at(x, y, c) += float(0.4 * expected(x, y, c));
    const Agreement a = caustica::check_agreement("pt", synthetic_runs(1, 0.3), "bdpt", biased);
    EXPECT_FALSE(a.agree);
    EXPECT_LE(std::abs(a.z), a.threshold);
    EXPECT_LT(a.worst_block_z, -a.block_threshold);
    EXPECT_EQ(a.worst_block_x, 40);
    EXPECT_EQ(a.worst_block_y, 24);
}

// The quantile inverts the normal tail: P(|Z| > 1.96) = 0.05, P(|Z| > 3.891) = 1e-4.
TEST(CompareAgreement, TwoSidedNormalQuantile) {
    EXPECT_NEAR(caustica::two_sided_normal_quantile(0.05), 1.959964, 1e-6);
    EXPECT_NEAR(caustica::two_sided_normal_quantile(1e-4), 3.890592, 1e-6);
    EXPECT_NEAR(caustica::two_sided_normal_quantile(1), 0, 1e-9);
}

} // namespace
