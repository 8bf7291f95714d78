// The pmj02bn sequence and sampler: every power-of-two prefix is a (0,2)-net whose points keep
// their distance, each pixel's positions are a net tiled as pbrt-v4 tiles them, 1D values are
// stratified, the per-pixel offsets are hierarchically stratified across pixels, and smooth
// integrands converge far faster than with independent samples.
#include "sampler/independent_sampler.h"
#include "sampler/pmj02bn_sampler.h"
#include "sampler/pmj02bn_sequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>
#include <vector>

using namespace caustica;

namespace {

// One point in every elementary interval of area 2^-m (a (0,m,2)-net in base 2), for the
// first 2^m points, read in fixed point.
bool prefix_is_02_net(const std::vector<FixedPoint2> &p, int m) {
    const size_t n = size_t(1) << m;
    if (p.size() < n) return false;
    for (int a = 0; a <= m; ++a) {
        const int b = m - a;
        std::vector<uint8_t> seen(n, 0);
        for (size_t i = 0; i < n; ++i) {
            const size_t cx = a ? p[i].x >> (32 - a) : 0, cy = b ? p[i].y >> (32 - b) : 0;
            if (seen[(cx << b) | cy]++) return false;
        }
    }
    return true;
}

// Mean distance from each of the first n points to its nearest neighbour on the torus, in units
// of 1/sqrt(n) (the spacing of a square grid of n points).
double mean_nearest_distance(const std::vector<Vec2f> &p, size_t n) {
    double sum = 0;
    for (size_t i = 0; i < n; ++i) {
        double nearest = 1e9;
        for (size_t j = 0; j < n; ++j) {
            if (j == i) continue;
            double dx = std::abs(p[i].x - p[j].x), dy = std::abs(p[i].y - p[j].y);
            dx = std::min(dx, 1 - dx);
            dy = std::min(dy, 1 - dy);
            nearest = std::min(nearest, dx * dx + dy * dy);
        }
        sum += std::sqrt(nearest);
    }
    return sum / n * std::sqrt(double(n));
}

std::vector<Vec2f> as_floats(const std::vector<FixedPoint2> &p) {
    std::vector<Vec2f> v;
    for (FixedPoint2 q : p) v.push_back({q.x * 0x1p-32f, q.y * 0x1p-32f});
    return v;
}

} // namespace

TEST(Pmj02bnSequence, EveryPowerOfTwoPrefixIsA02Net) {
    // Checked exhaustively on a whole set of pbrt-v4's size, and on another seed.
    const std::vector<FixedPoint2> &set = pmj02bn_set(0);
    ASSERT_EQ(set.size(), size_t(Pmj02bnSampler::SetSize));
    for (int m = 0; m <= 16; ++m) EXPECT_TRUE(prefix_is_02_net(set, m)) << m;
    const std::vector<FixedPoint2> other = generate_pmj02bn(4096, 17);
    for (int m = 0; m <= 12; ++m) EXPECT_TRUE(prefix_is_02_net(other, m)) << m;
    // Different seeds give different points; the same seed the same.
    EXPECT_NE(other[5].x, generate_pmj02bn(8, 18)[5].x);
    EXPECT_EQ(other[5].x, generate_pmj02bn(8, 17)[5].x);
    // The check fails when one point moves to the next x stratum of the finest grid.
    std::vector<FixedPoint2> moved(set.begin(), set.begin() + 1024);
    EXPECT_TRUE(prefix_is_02_net(moved, 10));
    moved[700].x += 1u << 22;
    EXPECT_FALSE(prefix_is_02_net(moved, 10));
}

TEST(Pmj02bnSequence, PointsKeepTheirDistance) {
    // Mean distance from each of the first 1024 points to its nearest neighbour, in grid
    // spacings: 0.65-0.69 for sets 0-4 (Owen-scrambled Sobol nets: 0.63-0.68), against 0.49-0.51
    // for independent points (seeds 1-5; 0.5 in expectation for a Poisson process, with a
    // standard deviation of about 0.008 at this size). The bound lies between.
    for (int s = 0; s < Pmj02bnSampler::SetCount; ++s)
        EXPECT_GT(mean_nearest_distance(as_floats(pmj02bn_set(s)), 1024), 0.6) << s;
    for (int seed = 1; seed <= 5; ++seed) {
        IndependentSampler independent(1, seed);
        std::vector<Vec2f> p;
        for (int i = 0; i < 1024; ++i) {
            independent.start_pixel_sample({0, 0}, i);
            p.push_back(independent.get_2d());
        }
        EXPECT_LT(mean_nearest_distance(p, 1024), 0.6) << seed;
    }
}

namespace {

// A (0,m,2)-net of 2^m float points (multiples of 2^-24, so the scaling is exact).
bool is_02_net(const std::vector<Vec2f> &p, int m) {
    std::vector<FixedPoint2> fixed;
    for (Vec2f u : p) fixed.push_back({uint32_t(std::ldexp(double(u.x), 32)), uint32_t(std::ldexp(double(u.y), 32))});
    return fixed.size() == (size_t(1) << m) && prefix_is_02_net(fixed, m);
}

std::vector<Vec2f> pixel_positions(Sampler &s, Vec2i pixel, int first, int count) {
    std::vector<Vec2f> p;
    for (int i = first; i < first + count; ++i) {
        s.start_pixel_sample(pixel, i, 1);
        p.push_back(s.get_pixel_2d());
    }
    return p;
}

// The coordinates in a row, for comparisons.
std::vector<float> coordinates(const std::vector<Vec2f> &p) {
    std::vector<float> v;
    for (Vec2f u : p) v.insert(v.end(), {u.x, u.y});
    return v;
}

} // namespace

TEST(Pmj02bnSampler, PixelPositionsAreANetTiledAsInPbrt) {
    // 16 samples: a tile of 64 x 64 pixels shares set 0, each pixel's 16 points a (0,4,2)-net;
    // 64 samples: 32 x 32 pixels, (0,6,2)-nets.
    for (auto [spp, m, tile] : {std::tuple{16, 4, 64}, std::tuple{64, 6, 32}}) {
        Pmj02bnSampler s(spp, 3);
        for (Vec2i pixel : {Vec2i{0, 0}, Vec2i{5, 9}, Vec2i{63, 17}}) {
            const std::vector<Vec2f> p = pixel_positions(s, pixel, 0, spp);
            EXPECT_TRUE(is_02_net(p, m)) << spp << " " << pixel.x << "," << pixel.y;
            EXPECT_EQ(coordinates(p), coordinates(pixel_positions(s, {pixel.x + tile, pixel.y + 2 * tile}, 0, spp)));
            EXPECT_NE(coordinates(p), coordinates(pixel_positions(s, {pixel.x + 1, pixel.y}, 0, spp)));
            // Later rounds are other randomisations of the same points, no longer copies.
            EXPECT_NE(coordinates(p), coordinates(pixel_positions(s, pixel, spp, spp)));
        }
    }
}

TEST(Pmj02bnSampler, OneDimensionalValuesAreStratified) {
    // Each of a pixel's 16 samples takes its own sixteenth of [0, 1) in every dimension.
    Pmj02bnSampler s(16, 5);
    for (int dimension : {0, 5, 12, 40}) {
        std::set<int> strata;
        for (int i = 0; i < 16; ++i) {
            s.start_pixel_sample({7, 3}, i, dimension);
            strata.insert(int(s.get_1d() * 16));
        }
        EXPECT_EQ(strata.size(), 16u) << dimension;
    }
}

TEST(Pmj02bnSampler, PixelOffsetsAreHierarchicallyStratified) {
    // With one sample per pixel, a 1D value is the pixel's blue-noise offset itself: the 4^j
    // pixels of every aligned 2^j x 2^j block take 4^j different strata of [0, 1). Independent
    // values fail this (four values fall in four different quarters with probability 3/32).
    auto stratified = [](Sampler &s, int dimension) {
        for (int j = 1; j <= 3; ++j) {
            const int block = 1 << j, strata = block * block;
            for (int by = 0; by < 16; by += block)
                for (int bx = 0; bx < 16; bx += block) {
                    std::set<int> seen;
                    for (int y = by; y < by + block; ++y)
                        for (int x = bx; x < bx + block; ++x) {
                            s.start_pixel_sample({x, y}, 0, dimension);
                            seen.insert(int(s.get_1d() * strata));
                        }
                    if (int(seen.size()) != strata) return false;
                }
        }
        return true;
    };
    Pmj02bnSampler pmj(1, 2);
    for (int dimension : {0, 3, 11}) EXPECT_TRUE(stratified(pmj, dimension)) << dimension;
    IndependentSampler independent(1, 2);
    EXPECT_FALSE(stratified(independent, 0));
}

TEST(Pmj02bnSampler, IntegratesSmoothFunctionsFarBetterThanIndependentSamples) {
    // A Gaussian bump (centre (0.4, 0.6), width 0.15) and (x + y)^2 over the unit square, 256
    // samples per pixel over 20 x 20 pixels, from the 2D dimensions of sets 1 and 2 (rotated by
    // the pixel's offsets) and of a permuted set (dimension 20). MSE / MSE(independent) over
    // seeds 1-11: bump 1.5e-3 to 5.9e-3, (x + y)^2 1.1e-2 to 1.8e-2 (the rotation breaks the
    // nets' elementary intervals, which costs a non-periodic integrand more). Bounds 0.02 and
    // 0.05, about 3x the worst seed; independent sampling is 1 by definition.
    const int n = 256, width = 20, height = 20;
    auto bump = [](Vec2f u) {
        const double dx = u.x - 0.4, dy = u.y - 0.6;
        return std::exp(-(dx * dx + dy * dy) / (2 * 0.15 * 0.15));
    };
    auto square = [](Vec2f u) { return double(u.x + u.y) * double(u.x + u.y); };
    const double k = 0.15 * std::sqrt(M_PI / 2);
    auto axis = [&](double mu) {
        return k * (std::erf((1 - mu) / (0.15 * std::sqrt(2.0))) - std::erf(-mu / (0.15 * std::sqrt(2.0))));
    };
    const double bump_integral = axis(0.4) * axis(0.6);
    auto mse = [&](Sampler &s, auto f, double integral, int dimension) {
        double sum_sq = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                double sum = 0;
                for (int i = 0; i < n; ++i) {
                    s.start_pixel_sample({x, y}, i, dimension);
                    sum += f(s.get_2d());
                }
                sum_sq += (sum / n - integral) * (sum / n - integral);
            }
        return sum_sq / (width * height);
    };
    Pmj02bnSampler pmj(n, 1);
    IndependentSampler independent(n, 1);
    for (int dimension : {3, 5, 20}) {
        const double bump_ratio =
            mse(pmj, bump, bump_integral, dimension) / mse(independent, bump, bump_integral, dimension);
        const double square_ratio =
            mse(pmj, square, 7.0 / 6.0, dimension) / mse(independent, square, 7.0 / 6.0, dimension);
        EXPECT_LT(bump_ratio, 0.02) << dimension;
        EXPECT_LT(square_ratio, 0.05) << dimension;
    }
}
