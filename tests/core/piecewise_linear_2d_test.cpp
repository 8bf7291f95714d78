// PiecewiseLinear2D (Dupuy and Jakob 2018's warp, core/piecewise_linear_2d.h): the density
// integrates to 1, sample() and invert() are inverses with the same density, samples follow the
// density (Pearson's chi-square over a grid of bins), and parameters blend the slices'
// normalised densities linearly.
#include "core/piecewise_linear_2d.h"
#include "core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace caustica {
namespace {

using Kind = PiecewiseLinear2D::Kind;

// A lumpy positive function, different for each slice.
std::vector<float> lumpy_table(int nx, int ny, int slices) {
    std::vector<float> v;
    for (int s = 0; s < slices; ++s)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x)
                v.push_back(0.05f + std::pow(std::sin(0.9f * x + 0.4f * y + s), 2.f) * (1 + s) +
                            (x == 2 && y == 1 ? 3.f : 0.f));
    return v;
}

// The integral of evaluate() over [x0, x1] x [y0, y1] by the midpoint rule on an n x n grid.
double integrate(const PiecewiseLinear2D &d, std::span<const float> params, double x0, double x1, double y0,
                 double y1, int n) {
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            sum += d.evaluate({float(x0 + (x1 - x0) * (i + 0.5) / n), float(y0 + (y1 - y0) * (j + 0.5) / n)}, params);
    return sum * (x1 - x0) * (y1 - y0) / (double(n) * n);
}

TEST(PiecewiseLinear2D, DensityIntegratesToOneForEveryParameter) {
    const PiecewiseLinear2D d(lumpy_table(7, 5, 6), 7, 5, {{0.f, 1.f, 3.f}, {-1.f, 2.f}}, Kind::Density);
    for (float a : {-0.5f, 0.f, 0.4f, 2.f, 3.f, 7.f})
        for (float b : {-1.f, 0.3f, 2.f}) {
            const float params[2] = {a, b};
            EXPECT_NEAR(integrate(d, params, 0, 1, 0, 1, 600), 1.0, 2e-4) << a << " " << b;
        }
}

TEST(PiecewiseLinear2D, InvertUndoesSampleWithTheSameDensity) {
    const PiecewiseLinear2D d(lumpy_table(9, 6, 4), 9, 6, {{0.f, 1.f}, {0.f, 0.5f}}, Kind::Density);
    Rng rng(3, 1);
    for (int i = 0; i < 5000; ++i) {
        const float params[2] = {rng.uniform(), rng.uniform() * 0.5f};
        const Vec2f u = rng.uniform2();
        const PiecewiseLinear2D::Sample s = d.sample(u, params);
        ASSERT_GE(s.p.x, 0.f);
        ASSERT_LE(s.p.x, 1.f);
        ASSERT_GE(s.p.y, 0.f);
        ASSERT_LE(s.p.y, 1.f);
        EXPECT_NEAR(s.pdf, d.evaluate(s.p, params), 1e-4f * s.pdf);
        const PiecewiseLinear2D::Sample back = d.invert(s.p, params);
        EXPECT_NEAR(back.p.x, u.x, 2e-4f);
        EXPECT_NEAR(back.p.y, u.y, 2e-4f);
        EXPECT_NEAR(back.pdf, s.pdf, 1e-4f * s.pdf);
    }
}

// Pearson's statistic of `count` samples over a bins x bins grid against the integral of the
// density over each bin. With 63 degrees of freedom, the statistic's mean is 63 and its standard
// deviation 11.2; the bound 130 is 6 standard deviations above the mean (measured: 61 to 66).
// Negative control: samples drawn at a parameter 0.02 from the one the density is evaluated at
// (about 1% of the density moved) give 241.
double chi_square(const PiecewiseLinear2D &d, std::span<const float> sample_params, std::span<const float> pdf_params,
                  int count) {
    const int bins = 8;
    std::vector<double> observed(bins * bins, 0);
    Rng rng(11, 2);
    for (int i = 0; i < count; ++i) {
        const Vec2f p = d.sample(rng.uniform2(), sample_params).p;
        observed[std::min(int(p.y * bins), bins - 1) * bins + std::min(int(p.x * bins), bins - 1)] += 1;
    }
    double statistic = 0;
    for (int by = 0; by < bins; ++by)
        for (int bx = 0; bx < bins; ++bx) {
            const double expected =
                count * integrate(d, pdf_params, double(bx) / bins, double(bx + 1) / bins, double(by) / bins,
                                  double(by + 1) / bins, 40);
            statistic += sqr(observed[by * bins + bx] - expected) / expected;
        }
    return statistic;
}

TEST(PiecewiseLinear2D, SamplesFollowTheDensity) {
    const PiecewiseLinear2D d(lumpy_table(6, 7, 3), 6, 7, {{0.f, 0.5f, 1.f}}, Kind::Density);
    for (float a : {0.f, 0.3f, 0.75f}) {
        const float params[1] = {a};
        EXPECT_LT(chi_square(d, params, params, 200000), 130) << a;
    }
    const float sampled[1] = {0.32f}, evaluated[1] = {0.3f};
    EXPECT_GT(chi_square(d, sampled, evaluated, 200000), 130);
}

TEST(PiecewiseLinear2D, ParametersBlendTheNormalisedSlices) {
    // Two slices: a constant, and a ramp in x; at parameter 0.25 the density is 3/4 of the one
    // and 1/4 of the other, each normalised.
    std::vector<float> table;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) table.push_back(5);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) table.push_back(float(x));
    const PiecewiseLinear2D d(table, 3, 3, {{0.f, 1.f}}, Kind::Density);
    const float quarter[1] = {0.25f};
    for (float x : {0.f, 0.3f, 0.8f, 1.f}) EXPECT_NEAR(d.evaluate({x, 0.6f}, quarter), 0.75f * 1 + 0.25f * 2 * x, 1e-5f);
    // Parameters outside the table take its nearest slice.
    const float below[1] = {-3.f}, above[1] = {9.f};
    EXPECT_NEAR(d.evaluate({0.8f, 0.1f}, below), 1.f, 1e-6f);
    EXPECT_NEAR(d.evaluate({0.8f, 0.1f}, above), 1.6f, 1e-6f);
}

TEST(PiecewiseLinear2D, InterpolantsReturnTheValuesAsGiven) {
    // Values x + 10 y on a 3 x 2 grid, whose bilinear interpolation is exact.
    const std::vector<float> table{0, 1, 2, 10, 11, 12};
    const PiecewiseLinear2D d(table, 3, 2, {}, Kind::Interpolant);
    EXPECT_NEAR(d.evaluate({0.25f, 0.5f}), 0.5f + 5, 1e-5f);
    EXPECT_NEAR(d.evaluate({1.f, 1.f}), 12.f, 1e-5f);
}

TEST(PiecewiseLinear2D, RejectsTablesItCannotSample) {
    std::vector<float> zero(9, 0.f), negative(9, 1.f), nan(9, 1.f);
    negative[4] = -1;
    nan[2] = std::nanf("");
    EXPECT_THROW(PiecewiseLinear2D(zero, 3, 3, {}, Kind::Density), std::invalid_argument);
    EXPECT_THROW(PiecewiseLinear2D(negative, 3, 3, {}, Kind::Density), std::invalid_argument);
    EXPECT_THROW(PiecewiseLinear2D(nan, 3, 3, {}, Kind::Density), std::invalid_argument);
    EXPECT_THROW(PiecewiseLinear2D(negative, 3, 2, {}, Kind::Density), std::invalid_argument);  // wrong size
    EXPECT_THROW(PiecewiseLinear2D(std::vector<float>(18, 1.f), 3, 3, {{1.f, 0.f}}, Kind::Density),
                 std::invalid_argument);  // parameter values not increasing
    EXPECT_NO_THROW(PiecewiseLinear2D(negative, 3, 3, {}, Kind::Interpolant));
}

} // namespace
} // namespace caustica
