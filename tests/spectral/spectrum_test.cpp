// Spectrum representations, blackbody emission and the Y inner product.
#include "spectral/spectrum.h"
#include "spectral/cie.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace caustica;

TEST(PiecewiseLinearSpectrum, InterpolatesAndIsZeroOutside) {
    const float lambdas[] = {400, 500, 600};
    const float values[] = {1, 3, 2};
    PiecewiseLinearSpectrum s(lambdas, values);
    EXPECT_FLOAT_EQ(s(400), 1);
    EXPECT_FLOAT_EQ(s(450), 2);
    EXPECT_FLOAT_EQ(s(575), 2.25f);
    EXPECT_FLOAT_EQ(s(600), 2);
    EXPECT_EQ(s(399.9f), 0);
    EXPECT_EQ(s(600.1f), 0);
    EXPECT_FLOAT_EQ(s.max_value(), 3);
    const float unsorted[] = {500, 400, 600};
    EXPECT_THROW(PiecewiseLinearSpectrum(unsorted, values), std::invalid_argument);
}

TEST(PiecewiseLinearSpectrum, InterleavedNormalisationGivesUnitLuminance) {
    const float pairs[] = {350, 2, 850, 2};
    auto raw = PiecewiseLinearSpectrum::from_interleaved(pairs, false);
    EXPECT_FLOAT_EQ((*raw)(600), 2);
    auto normalized = PiecewiseLinearSpectrum::from_interleaved(pairs, true);
    // A constant c has Y integral c * sum(ybar), so normalising makes it CIE_Y_integral.
    EXPECT_NEAR(inner_product_y(*normalized), CIE_Y_integral, 1e-4f * CIE_Y_integral);
    const float odd[] = {400, 1, 500};
    EXPECT_THROW(PiecewiseLinearSpectrum::from_interleaved(odd, false), std::invalid_argument);
}

TEST(DenselySampledSpectrum, NearestNanometre) {
    const float lambdas[] = {360, 830};
    const float values[] = {0, 470};
    DenselySampledSpectrum s{PiecewiseLinearSpectrum(lambdas, values)};  // s(l) = l - 360
    EXPECT_FLOAT_EQ(s(500), 140);
    EXPECT_FLOAT_EQ(s(500.4f), 140);
    EXPECT_FLOAT_EQ(s(500.6f), 141);
    EXPECT_EQ(s(359), 0);
    EXPECT_EQ(s(831), 0);
    EXPECT_FLOAT_EQ(s.max_value(), 470);
    SampledSpectrum v = s.sample(SampledWavelengths::fixed(600));
    EXPECT_FLOAT_EQ(v[0], 240);
}

// Stefan-Boltzmann: pi times the integral of Planck's spectral radiance over wavelength is the
// emitted flux sigma T^4. A units slip (nm vs m, per sr) shows up as a factor of 1e9 or pi.
TEST(Blackbody, IntegratesToStefanBoltzmann) {
    const double sigma = 5.670374419e-8;  // W m^-2 K^-4 (CODATA 2018)
    for (float t : {1000.f, 3000.f, 6500.f}) {
        // Trapezoid on a log-spaced grid from 10 nm to 1 mm; the integrand is smooth there and
        // negligible outside, so the quadrature error is far below the 0.1% bound.
        double integral = 0, prev_l = 10, prev_b = blackbody(10, t);
        for (double l = 10; l < 1e6;) {
            double next = l * 1.001;
            double b = blackbody(float(next), t);
            integral += 0.5 * (b + prev_b) * (next - prev_l) * 1e-9;  // dl in metres
            prev_l = next;
            prev_b = b;
            l = next;
        }
        double expected = sigma * std::pow(double(t), 4);
        EXPECT_NEAR(3.14159265358979 * integral, expected, 1e-3 * expected) << t;
    }
    EXPECT_EQ(blackbody(500, 0), 0);
}

TEST(Blackbody, NormalisedPeakAtWienWavelength) {
    for (float t : {3000.f, 5000.f, 6500.f}) {
        BlackbodySpectrum b(t);
        float peak = 2.8977721e-3f / t * 1e9f;
        EXPECT_NEAR(b(peak), 1.f, 1e-5f);
        // The unnormalised law rises up to Wien's wavelength and falls after it: checked at
        // 1 nm steps (finer steps are below float resolution of the flat peak).
        for (float l = peak - 30; l < peak - 1; l += 1)
            EXPECT_LT(blackbody(l, t), blackbody(l + 1, t));
        for (float l = peak + 1; l < peak + 30; l += 1)
            EXPECT_GT(blackbody(l, t), blackbody(l + 1, t));
        EXPECT_LE(b(peak - 20), 1.f);
        EXPECT_LE(b(peak + 20), 1.f);
    }
    EXPECT_EQ(BlackbodySpectrum(0)(500), 0);
}

TEST(InnerProduct, ConstantSpectrumGivesSumOfYBar) {
    float sum = 0;
    for (float l = LambdaMin; l <= LambdaMax; ++l) sum += cie_y()(l);
    EXPECT_NEAR(inner_product_y(ConstantSpectrum(2)), 2 * sum, 1e-5f * sum);
}
