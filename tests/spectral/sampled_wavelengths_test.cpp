// Hero-wavelength sampling: the film's estimator is unbiased, with and without secondary
// termination, and the visible-wavelength sampler inverts its density's CDF.
#include "spectral/sampled_wavelengths.h"
#include "core/rng.h"
#include "spectral/cie.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <vector>

using namespace caustica;

namespace {

// A smooth test spectrum.
float smooth_spectrum(float lambda) { return 1.0f + 0.5f * std::sin(lambda / 40.0f); }

// Reference value of the integral of xbar(l) S(l) over [LambdaMin, LambdaMax], by the midpoint
// rule at 0.01 nm: cie_x() is a step function of 1 nm steps, so this is exact to ~1e-6.
double reference_integral() {
    double sum = 0;
    const double h = 0.01;
    for (double l = LambdaMin + h / 2; l < LambdaMax; l += h)
        sum += double(cie_x()(float(l))) * smooth_spectrum(float(l)) * h;
    return sum;
}

struct Estimate {
    double mean, standard_error;
};

// N film estimates (1/n) sum_j f(l_j) / pdf_j, with zero-pdf lanes contributing nothing.
template <typename Sampler>
Estimate estimate(Sampler make_wavelengths, int n) {
    Rng rng(7, 1234);
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        SampledWavelengths w = make_wavelengths(rng.uniform());
        SampledSpectrum f;
        for (int j = 0; j < NumWavelengths; ++j) f[j] = cie_x()(w[j]) * smooth_spectrum(w[j]);
        double e = safe_div(f, w.pdf()).average();
        sum += e;
        sum2 += e * e;
    }
    double mean = sum / n;
    double variance = (sum2 / n - mean * mean) * n / (n - 1);
    return {mean, std::sqrt(variance / n)};
}

} // namespace

// The mean of N independent estimates is within 4 standard errors of the integral with
// probability > 99.99% for an unbiased estimator (CLT); the seed is fixed, so the outcome is
// deterministic. The standard error is estimated from the same samples.
TEST(SampledWavelengths, HeroEstimatorIsUnbiased) {
    double reference = reference_integral();
    Estimate e = estimate([](float u) { return SampledWavelengths::sample_visible(u); }, 200000);
    EXPECT_NEAR(e.mean, reference, 4 * e.standard_error) << "reference " << reference;
    EXPECT_LT(e.standard_error, 0.01 * reference);  // the estimate is informative
}

TEST(SampledWavelengths, TerminatedSecondariesStayUnbiased) {
    double reference = reference_integral();
    Estimate e = estimate(
        [](float u) {
            SampledWavelengths w = SampledWavelengths::sample_visible(u);
            w.terminate_secondary();
            return w;
        },
        200000);
    EXPECT_NEAR(e.mean, reference, 4 * e.standard_error) << "reference " << reference;
}

TEST(SampledWavelengths, UniformAndSingleSamplingAreUnbiased) {
    double reference = reference_integral();
    Estimate uniform =
        estimate([](float u) { return SampledWavelengths::sample_uniform(u); }, 200000);
    EXPECT_NEAR(uniform.mean, reference, 4 * uniform.standard_error);
    Estimate single =
        estimate([](float u) { return SampledWavelengths::sample_single(u); }, 200000);
    EXPECT_NEAR(single.mean, reference, 4 * single.standard_error);
}

TEST(SampledWavelengths, UniformSamplingOfARangeStaysInIt) {
    // A spectral film's range: the hero uniform in it, the others a quarter of the range apart
    // (wrapped), each with density 1 / (range).
    for (float u : {0.f, 0.3f, 0.99f}) {
        const SampledWavelengths s = SampledWavelengths::sample_uniform(u, 400, 700);
        EXPECT_FLOAT_EQ(s[0], 400 + 300 * u);
        for (int i = 0; i < NumWavelengths; ++i) {
            EXPECT_GE(s[i], 400);
            EXPECT_LE(s[i], 700);
            EXPECT_FLOAT_EQ(s.pdf()[i], 1.f / 300);
            EXPECT_NEAR(std::fmod(s[i] - s[0] + 300, 300.f), 75.f * i, 1e-3f);
        }
    }
}

TEST(SampledWavelengths, TerminateKeepsOnlyTheHero) {
    SampledWavelengths w = SampledWavelengths::sample_visible(0.3f);
    EXPECT_FALSE(w.secondary_terminated());
    float hero = w[0];
    w.terminate_secondary();
    EXPECT_TRUE(w.secondary_terminated());
    EXPECT_EQ(w[0], hero);
    EXPECT_FLOAT_EQ(w.pdf()[0], visible_wavelengths_pdf(hero) / NumWavelengths);
    for (int i = 1; i < NumWavelengths; ++i) EXPECT_EQ(w.pdf()[i], 0);
}

namespace {

// CDF of visible_wavelengths_pdf by the trapezoid rule on a 0.01 nm grid.
struct NumericCdf {
    std::vector<double> cdf;
    NumericCdf() {
        cdf.push_back(0);
        for (double l = LambdaMin; l < LambdaMax - 1e-9; l += 0.01)
            cdf.push_back(cdf.back() + 0.005 * (visible_wavelengths_pdf(float(l)) +
                                                visible_wavelengths_pdf(float(l + 0.01))));
    }
    double operator()(double lambda) const {
        double x = (lambda - LambdaMin) / 0.01;
        int i = std::clamp(int(x), 0, int(cdf.size()) - 2);
        return cdf[i] + (x - i) * (cdf[i + 1] - cdf[i]);
    }
};

} // namespace

TEST(SampledWavelengths, VisiblePdfIsNormalised) {
    NumericCdf cdf;
    EXPECT_NEAR(cdf.cdf.back(), 1.0, 1e-4);
}

// Inversion: CDF(sample(u)) = u at every u, to float precision of the closed form.
TEST(SampledWavelengths, VisibleSamplerInvertsTheCdf) {
    NumericCdf cdf;
    for (float u = 0.005f; u < 1; u += 0.01f)
        EXPECT_NEAR(cdf(sample_visible_wavelengths(u)), u, 2e-4) << u;
}

// Every member of a hero set is the visible density's inverse CDF at a rotated primary sample,
// so its CDF value is the rotation of u by i/n, and its pdf is the visible density there.
TEST(SampledWavelengths, MembersAreRotationsInSampleSpace) {
    NumericCdf cdf;
    for (float u = 0.005f; u < 1; u += 0.01f) {
        SampledWavelengths w = SampledWavelengths::sample_visible(u);
        for (int i = 0; i < NumWavelengths; ++i) {
            double rotated = std::fmod(double(u) + double(i) / NumWavelengths, 1.0);
            EXPECT_NEAR(cdf(w[i]), rotated, 2e-4) << "u " << u << " member " << i;
            EXPECT_FLOAT_EQ(w.pdf()[i], visible_wavelengths_pdf(w[i]));
        }
    }
}

// Kolmogorov-Smirnov: N samples from uniform u; the sup distance between the empirical CDF and
// the numeric CDF is below 1.63 / sqrt(N) with 99% probability for a correct sampler.
TEST(SampledWavelengths, VisibleSamplerPassesKolmogorovSmirnov) {
    const int n = 100000;
    Rng rng(3, 99);
    std::vector<double> samples(n);
    for (double &s : samples) s = sample_visible_wavelengths(rng.uniform());
    std::sort(samples.begin(), samples.end());
    NumericCdf cdf;
    double d = 0;
    for (int i = 0; i < n; ++i) {
        double f = cdf(samples[i]);
        d = std::max({d, f - double(i) / n, double(i + 1) / n - f});
    }
    EXPECT_LT(d, 1.63 / std::sqrt(double(n)));
    EXPECT_GE(samples.front(), LambdaMin);
    EXPECT_LE(samples.back(), LambdaMax);
}
