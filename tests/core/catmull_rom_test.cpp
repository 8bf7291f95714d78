// Catmull-Rom splines (core/catmull_rom.h): the weights interpolate the nodes and reproduce the
// polynomials their finite differences are exact for, the integral is the spline's, the inversion
// inverts it, and the 2D sampler's samples sit where the blended spline's CDF equals u.
#include "core/catmull_rom.h"
#include "core/vecmath.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace caustica {
namespace {

// Non-uniform nodes, denser at the start, as the subsurface tables' radii are.
const std::vector<float> Nodes = {0.f, 0.1f, 0.25f, 0.5f, 0.9f, 1.5f, 2.4f, 3.f};

std::vector<float> tabulate(const std::vector<float> &nodes, const std::function<float(float)> &f) {
    std::vector<float> v;
    for (float x : nodes) v.push_back(f(x));
    return v;
}

// The spline through `values` at x, through the weights.
double spline(const std::vector<float> &nodes, const std::vector<float> &values, float x) {
    std::optional<CatmullRomWeights> w = catmull_rom_weights(nodes, x);
    if (!w) return NAN;
    double v = 0;
    for (int k = 0; k < 4; ++k)
        if (w->weights[k] != 0) v += double(w->weights[k]) * values[w->offset + k];
    return v;
}

// int_a^b of the spline by Simpson's rule on each node interval cut in `pieces`: exact for the
// spline's cubics up to rounding, and independent of integrate_catmull_rom's closed form.
double spline_integral(const std::vector<float> &nodes, const std::function<double(float)> &s,
                       double b, int pieces = 4) {
    double sum = 0;
    for (size_t i = 0; i + 1 < nodes.size() && nodes[i] < b; ++i) {
        double x0 = nodes[i], x1 = std::min<double>(nodes[i + 1], b), h = (x1 - x0) / pieces;
        for (int p = 0; p < pieces; ++p) {
            double a = x0 + p * h;
            sum += h / 6 * (s(float(a)) + 4 * s(float(a + h / 2)) + s(float(a + h)));
        }
    }
    return sum;
}

TEST(CatmullRom, WeightsInterpolateTheNodesAndSumToOne) {
    std::vector<float> values = tabulate(Nodes, [](float x) { return std::sin(3 * x) + 2; });
    for (size_t i = 0; i < Nodes.size(); ++i)
        EXPECT_NEAR(spline(Nodes, values, Nodes[i]), values[i], 1e-6) << "node " << i;
    for (float x = 0; x <= 3; x += 0.01f) {
        std::optional<CatmullRomWeights> w = catmull_rom_weights(Nodes, x);
        ASSERT_TRUE(w);
        EXPECT_NEAR(w->weights[0] + w->weights[1] + w->weights[2] + w->weights[3], 1, 1e-6) << x;
    }
    EXPECT_FALSE(catmull_rom_weights(Nodes, -1e-3f));
    EXPECT_FALSE(catmull_rom_weights(Nodes, 3.001f));
    EXPECT_FALSE(catmull_rom_weights(Nodes, NAN));
}

TEST(CatmullRom, WeightsReproduceLinearDataOnAnyNodes) {
    // Every finite difference of a line is its slope, so each Hermite cubic is the line itself.
    // Float weights of magnitude <= 1.2 times values <= 10: rounding stays below 1e-5.
    std::vector<float> values = tabulate(Nodes, [](float x) { return 3 * x - 2; });
    for (float x = 0; x <= 3; x += 0.0137f)
        EXPECT_NEAR(spline(Nodes, values, x), 3 * x - 2, 1e-5) << x;
}

TEST(CatmullRom, WeightsReproduceQuadraticsOnlyAwayFromTheEndsOfUniformNodes) {
    // On uniform nodes the central difference of a quadratic is its exact derivative, so the
    // interior intervals reproduce x^2; the end intervals' one-sided differences are not exact
    // (measured 0.037 at most, for h = 0.5), which the test also checks
    // so that it could tell the two apart.
    std::vector<float> nodes = {0.f, 0.5f, 1.f, 1.5f, 2.f, 2.5f, 3.f};
    std::vector<float> values = tabulate(nodes, [](float x) { return x * x; });
    double end_error = 0;
    for (float x = 0; x <= 3; x += 0.01f) {
        double error = std::abs(spline(nodes, values, x) - double(x) * x);
        if (x > 0.5f && x < 2.5f)
            EXPECT_LT(error, 1e-5) << x;
        else
            end_error = std::max(end_error, error);
    }
    EXPECT_GT(end_error, 0.02);
}

TEST(CatmullRom, IntegralIsTheSplinesAndConvergesToTheFunctions) {
    std::vector<float> values = tabulate(Nodes, [](float x) { return std::exp(-x) * (1 + x); });
    std::vector<float> cdf(Nodes.size());
    float total = integrate_catmull_rom(Nodes, values, cdf);
    auto s = [&](float x) { return spline(Nodes, values, x); };
    EXPECT_EQ(cdf[0], 0.f);
    EXPECT_EQ(cdf.back(), total);
    // Float sums of values <= 1 against a double rule (measured 3.6e-8 at most).
    for (size_t i = 1; i < Nodes.size(); ++i)
        EXPECT_NEAR(cdf[i], spline_integral(Nodes, s, Nodes[i]), 1e-6) << "node " << i;

    // A known integral: int_0^pi sin = 2. Catmull-Rom is third-order accurate, so on 65 uniform
    // nodes the error is at most ~h^3 ~ 1e-4 (measured -4.8e-7: the end intervals' errors nearly
    // cancel by symmetry); float rounding of the sum is ~1e-6.
    std::vector<float> nodes;
    for (int i = 0; i <= 64; ++i) nodes.push_back(Pi * i / 64);
    std::vector<float> sine = tabulate(nodes, [](float x) { return std::sin(x); });
    std::vector<float> sine_cdf(nodes.size());
    EXPECT_NEAR(integrate_catmull_rom(nodes, sine, sine_cdf), 2.0, 1e-5);
}

TEST(CatmullRom, InvertFindsWhereTheSplineTakesTheValue) {
    std::vector<float> values = tabulate(Nodes, [](float x) { return x * x * x + x; });
    for (float y = 0.001f; y < 29.9f; y += 0.173f) {
        float x = invert_catmull_rom(Nodes, values, y);
        // Newton-bisection stops at |spline - y| < 1e-6 or a bracket of 1e-6 of an interval
        // (slope <= 30 per unit x there): 5e-5 covers both (measured 5.8e-6 at most).
        EXPECT_NEAR(spline(Nodes, values, x), y, 5e-5) << y;
    }
    EXPECT_EQ(invert_catmull_rom(Nodes, values, -1.f), 0.f);
    EXPECT_EQ(invert_catmull_rom(Nodes, values, 0.f), 0.f);
    EXPECT_EQ(invert_catmull_rom(Nodes, values, 31.f), 3.f);
}

TEST(CatmullRom, Sample2DPlacesSamplesWhereTheBlendedCdfIsU) {
    // Rows f(a, x) = (x + 0.2) e^{-a x} for a in nodes1; a sample for alpha between rows must lie
    // where the integral of the blended spline, computed here from the weights alone, reaches u
    // times the total. The sampler's Newton iteration stops within 1e-6 per unit interval of the
    // target, i.e. 1e-6 x width (<= 0.9) of integral, and the smallest total (alpha = 5) is 0.08:
    // 2e-5 of the total (measured 2.7e-6 at most). Negative control: adding 0.01 (d0 - d1) to the
    // quartic coefficient of the segment's integral moves samples by up to 2.0e-3 of the total.
    std::vector<float> nodes1 = {0.f, 0.5f, 1.5f, 3.f, 5.f};
    std::vector<float> values, cdf(nodes1.size() * Nodes.size());
    for (float a : nodes1)
        for (float x : Nodes) values.push_back((x + 0.2f) * std::exp(-a * x));
    const int n2 = int(Nodes.size());
    for (size_t i = 0; i < nodes1.size(); ++i)
        integrate_catmull_rom(Nodes, std::span(values).subspan(i * n2, n2),
                              std::span(cdf).subspan(i * n2, n2));
    for (float alpha : {0.f, 0.3f, 1.f, 2.2f, 5.f}) {
        auto blended = [&](float x) {
            std::optional<CatmullRomWeights> w = catmull_rom_weights(nodes1, alpha);
            double v = 0;
            for (int k = 0; k < 4; ++k)
                if (w->weights[k] != 0) {
                    std::vector<float> row(values.begin() + (w->offset + k) * n2,
                                           values.begin() + (w->offset + k + 1) * n2);
                    v += w->weights[k] * spline(Nodes, row, x);
                }
            return v;
        };
        const double total = spline_integral(Nodes, blended, 3.0);
        float previous = 0;
        for (float u = 0; u < 1; u += 0.0371f) {
            float x = sample_catmull_rom_2d(nodes1, Nodes, values, cdf, alpha, u);
            EXPECT_NEAR(spline_integral(Nodes, blended, x, 8) / total, u, 2e-5)
                << "alpha " << alpha << " u " << u;
            EXPECT_GE(x, previous);
            previous = x;
        }
    }
    EXPECT_EQ(sample_catmull_rom_2d(nodes1, Nodes, values, cdf, 5.5f, 0.5f), 0.f);
}

} // namespace
} // namespace caustica
