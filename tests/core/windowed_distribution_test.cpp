// The windowed piecewise-constant distribution: window integrals against sums over cells,
// samples against the density by a chi-square test, and the density's normalisation.
#include "core/rng.h"
#include "core/windowed_distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace caustica;

namespace {

// A 7x5 function with a zero row and one bright cell.
std::vector<float> test_function(int nx, int ny) {
    std::vector<float> f(size_t(nx) * ny);
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) f[size_t(y) * nx + x] = y == 2 ? 0.f : 0.5f + float(x * y % 4) + (x == 5 && y == 3 ? 9 : 0);
    return f;
}

// The integral of the piecewise-constant f over a window, cell by cell with the overlaps.
double brute_integral(const std::vector<float> &f, int nx, int ny, const UVWindow &w) {
    double sum = 0;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            const double ox = std::max(0.0, std::min<double>(w.max.x, (x + 1.0) / nx) - std::max<double>(w.min.x, double(x) / nx));
            const double oy = std::max(0.0, std::min<double>(w.max.y, (y + 1.0) / ny) - std::max<double>(w.min.y, double(y) / ny));
            sum += f[size_t(y) * nx + x] * ox * oy;
        }
    return sum;
}

const UVWindow kWindows[] = {{{0, 0}, {1, 1}}, {{0.13f, 0.21f}, {0.77f, 0.9f}}, {{0.5f, 0.1f}, {0.52f, 0.95f}},
                             {{0.3f, 0.35f}, {0.9f, 0.59f}}};

TEST(WindowedDistribution2D, WindowIntegralsAreExact) {
    const int nx = 7, ny = 5;
    const std::vector<float> f = test_function(nx, ny);
    const WindowedDistribution2D d(f, nx, ny);
    for (const UVWindow &w : kWindows) EXPECT_NEAR(d.integral(w), brute_integral(f, nx, ny, w), 1e-9);
}

// Samples fall into a grid of bins over the window (each bin a sub-rectangle of it) with the
// probabilities the density gives them: Pearson's chi-square over the bins with expected counts
// of at least 5, against the 1e-4 quantile of its distribution (Wilson-Hilferty).
TEST(WindowedDistribution2D, SamplesFollowTheDensityInTheWindow) {
    const int nx = 7, ny = 5;
    const std::vector<float> f = test_function(nx, ny);
    const WindowedDistribution2D d(f, nx, ny);
    Rng rng(7, 1);
    for (const UVWindow &w : kWindows) {
        const int bins = 12, n = 200000;
        std::vector<double> observed(bins * bins, 0), expected(bins * bins);
        const float bw = (w.max.x - w.min.x) / bins, bh = (w.max.y - w.min.y) / bins;
        const double total = d.integral(w);
        for (int j = 0; j < bins; ++j)
            for (int i = 0; i < bins; ++i) {
                const UVWindow bin{{w.min.x + i * bw, w.min.y + j * bh}, {w.min.x + (i + 1) * bw, w.min.y + (j + 1) * bh}};
                expected[j * bins + i] = n * d.integral(bin) / total;
            }
        for (int s = 0; s < n; ++s) {
            float pdf;
            std::optional<Vec2f> p = d.sample({rng.uniform(), rng.uniform()}, w, &pdf);
            ASSERT_TRUE(p);
            ASSERT_TRUE(w.contains(*p));
            EXPECT_NEAR(pdf, d.pdf(*p, w), 1e-4f * pdf);
            const int i = std::min(bins - 1, int((p->x - w.min.x) / bw)), j = std::min(bins - 1, int((p->y - w.min.y) / bh));
            observed[j * bins + i] += 1;
        }
        double chi2 = 0;
        int dof = -1;
        for (int k = 0; k < bins * bins; ++k) {
            if (expected[k] < 5) {
                EXPECT_LT(observed[k], 30) << "a bin of (nearly) zero density got samples";
                continue;
            }
            chi2 += (observed[k] - expected[k]) * (observed[k] - expected[k]) / expected[k];
            ++dof;
        }
        const double z = 3.719;  // the 1e-4 upper quantile of the standard normal
        const double a = 2.0 / (9 * dof), limit = dof * std::pow(1 - a + z * std::sqrt(a), 3);
        EXPECT_LT(chi2, limit) << "window " << w.min.x << " " << w.min.y << " dof " << dof;
    }
}

TEST(WindowedDistribution2D, DensityIntegratesToOneOverTheWindow) {
    const int nx = 7, ny = 5;
    const WindowedDistribution2D d(test_function(nx, ny), nx, ny);
    for (const UVWindow &w : kWindows) {
        const int m = 400;
        double sum = 0;
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i)
                sum += d.pdf({w.min.x + (w.max.x - w.min.x) * (i + 0.5f) / m, w.min.y + (w.max.y - w.min.y) * (j + 0.5f) / m}, w);
        EXPECT_NEAR(sum * (w.max.x - w.min.x) * (w.max.y - w.min.y) / (m * m), 1, 5e-3);
    }
    float pdf;
    EXPECT_FALSE(d.sample({0.5f, 0.5f}, {{0, 0.41f}, {1, 0.59f}}, &pdf)) << "the window holds only the zero row";
}

} // namespace
