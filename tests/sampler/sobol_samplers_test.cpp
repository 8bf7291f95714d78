// The Sobol-based samplers: stratification of each pixel's samples, zsobol's shared nets over
// blocks of pixels (the source of its blue-noise error), independence of distant pixels, the
// global Sobol sampler's pixel enumeration and integration error against the independent sampler.
#include "sampler/independent_sampler.h"
#include "sampler/padded_sobol_sampler.h"
#include "sampler/sobol_sampler.h"
#include "sampler/sobol_sequence.h"
#include "sampler/zsobol_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>
#include <utility>
#include <vector>

using namespace caustica;

namespace {

constexpr Randomization AllRandomizations[] = {Randomization::None, Randomization::PermuteDigits,
                                               Randomization::FastOwen, Randomization::Owen};

// The 2D samples at `dimension` of the given (pixel, index) pairs.
std::vector<Vec2f> points_2d(Sampler &s, const std::vector<std::pair<Vec2i, int>> &samples,
                             int dimension) {
    std::vector<Vec2f> p;
    for (auto [pixel, index] : samples) {
        s.start_pixel_sample(pixel, index, dimension);
        p.push_back(s.get_2d());
    }
    return p;
}

std::vector<std::pair<Vec2i, int>> pixel_samples(Vec2i pixel, int first, int count) {
    std::vector<std::pair<Vec2i, int>> v;
    for (int i = first; i < first + count; ++i) v.push_back({pixel, i});
    return v;
}

// Exactly one point in every elementary interval [i 2^-a, (i+1) 2^-a) x [j 2^-b, (j+1) 2^-b)
// with a + b = m, for every a from 0 to m: a (0,m,2)-net. Samples are multiples of 2^-24, so
// the products below are exact.
bool is_02_net(const std::vector<Vec2f> &p, int m) {
    if (p.size() != (size_t(1) << m)) return false;
    for (int a = 0; a <= m; ++a) {
        const int b = m - a;
        std::vector<int> count(size_t(1) << m, 0);
        for (Vec2f u : p) {
            size_t cx = size_t(std::ldexp(double(u.x), a)), cy = size_t(std::ldexp(double(u.y), b));
            if (++count[(cx << b) | cy] > 1) return false;
        }
    }
    return true;
}

// Gaussian bump centred at (0.4, 0.6), width 0.15, and its integral over the unit square in
// closed form (a product of two error-function differences).
double bump(Vec2f u) {
    const double s = 0.15;
    double dx = u.x - 0.4, dy = u.y - 0.6;
    return std::exp(-(dx * dx + dy * dy) / (2 * s * s));
}

double bump_integral() {
    const double s = 0.15, k = s * std::sqrt(M_PI / 2);
    auto axis = [&](double mu) {
        return k * (std::erf((1 - mu) / (s * std::sqrt(2.0))) - std::erf(-mu / (s * std::sqrt(2.0))));
    };
    return axis(0.4) * axis(0.6);
}

// Mean squared error of n-sample estimates of the integral of f over the unit square, taken
// from dimensions (3, 4) of pixels in a width x height block.
double integration_mse(Sampler &s, const std::function<double(Vec2f)> &f, double integral, int n,
                       int width, int height) {
    double sum_sq = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0;
            for (int i = 0; i < n; ++i) {
                s.start_pixel_sample({x, y}, i, 3);
                sum += f(s.get_2d());
            }
            double error = sum / n - integral;
            sum_sq += error * error;
        }
    return sum_sq / (width * height);
}

// Correlation coefficient, over pixels and four dimension pairs (independently scrambled),
// of the n-sample integration errors of a pixel and the pixel `offset` away.
double error_correlation(Sampler &s, Vec2i offset, int n, int width, int height) {
    auto error = [&](Vec2i pixel, int dimension) {
        double sum = 0;
        for (int i = 0; i < n; ++i) {
            s.start_pixel_sample(pixel, i, dimension);
            sum += bump(s.get_2d());
        }
        return sum / n - bump_integral();
    };
    double sab = 0, saa = 0, sbb = 0;
    for (int dimension : {5, 9, 13, 17})
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                double a = error({x, y}, dimension), b = error({x + offset.x, y + offset.y}, dimension);
                sab += a * b;
                saa += a * a;
                sbb += b * b;
            }
    return sab / std::sqrt(saa * sbb);
}

} // namespace

TEST(SobolSamplers, NetCheckRejectsIndependentPoints) {
    // The check below is not vacuous: 256 independent points are never a (0,8,2)-net.
    IndependentSampler s(256, 5);
    EXPECT_FALSE(is_02_net(points_2d(s, pixel_samples({1, 1}, 0, 256), 3), 8));
    EXPECT_FALSE(is_02_net(points_2d(s, pixel_samples({1, 1}, 0, 16), 3), 4));
}

TEST(ZSobolSampler, EachPixelsSamplesAreA02Net) {
    // For 2^k samples per pixel, any dimension pair of a pixel's samples is a (0,k,2)-net and
    // any single dimension has one sample in each interval of length 2^-k; so is every later
    // round of 2^k sample indices.
    for (Randomization r : AllRandomizations)
        for (int k = 0; k <= 8; ++k) {
            ZSobolSampler s(1 << k, 9, r);
            for (Vec2i pixel : {Vec2i{0, 0}, Vec2i{13, 7}, Vec2i{1000, 3}})
                for (int dimension : {0, 3, 11})
                    for (int round : {0, 1, 5}) {
                        auto samples = pixel_samples(pixel, round << k, 1 << k);
                        EXPECT_TRUE(is_02_net(points_2d(s, samples, dimension), k))
                            << "k=" << k << " dimension=" << dimension << " round=" << round;
                        std::set<int> strata;
                        for (auto [p, i] : samples) {
                            s.start_pixel_sample(p, i, dimension);
                            strata.insert(int(std::ldexp(double(s.get_1d()), k)));
                        }
                        EXPECT_EQ(int(strata.size()), 1 << k);
                    }
        }
}

TEST(ZSobolSampler, AlignedPixelBlocksShareA02Net) {
    // Ahmed and Wonka's construction: the samples of an aligned 2^j x 2^j block of pixels are
    // one aligned block of the sequence, so together they form a (0, 2j + k, 2)-net. The 2x2
    // quads are why neighbouring pixels' errors cancel (blue noise).
    for (int k : {0, 1, 2, 3, 4})
        for (int j : {1, 2, 3}) {
            ZSobolSampler s(1 << k, 4, Randomization::Owen);
            const int size = 1 << j;
            for (Vec2i corner : {Vec2i{0, 0}, Vec2i{5 * size, 3 * size}, Vec2i{40 * size, 7 * size}})
                for (int dimension : {0, 7}) {
                    std::vector<std::pair<Vec2i, int>> samples;
                    for (int y = 0; y < size; ++y)
                        for (int x = 0; x < size; ++x)
                            for (auto sample : pixel_samples({corner.x + x, corner.y + y}, 0, 1 << k))
                                samples.push_back(sample);
                    EXPECT_TRUE(is_02_net(points_2d(s, samples, dimension), 2 * j + k))
                        << "k=" << k << " j=" << j << " corner " << corner.x << "," << corner.y;
                }
        }
    // 16 x 16 pixels at 16 samples: 4096 points, one in each of the 4096 cells of every shape.
    ZSobolSampler s(16, 1, Randomization::Owen);
    std::vector<std::pair<Vec2i, int>> samples;
    for (int y = 32; y < 48; ++y)
        for (int x = 16; x < 32; ++x)
            for (auto sample : pixel_samples({x, y}, 0, 16)) samples.push_back(sample);
    EXPECT_TRUE(is_02_net(points_2d(s, samples, 3), 12));
}

TEST(ZSobolSampler, NeighboursAnticorrelateAndDistantPixelsAreIndependent) {
    // Adjacent pixels share a net, so their errors are negatively correlated: measured for 4
    // samples of a Gaussian bump over 64 x 64 pixels and one dimension pair, -0.12 on average
    // over 20 seeds, between -0.20 and -0.04 (the scramble is shared by the whole image, so
    // it varies with the seed); pooling four pairs narrows that. Pixels 100 apart lie in
    // different quadtree blocks with independent permutations: their correlation is 0 within
    // sampling noise (standard deviation 1/sqrt(4 x 4096) = 0.008; bound 0.05).
    for (Randomization r : {Randomization::FastOwen, Randomization::Owen}) {
        ZSobolSampler s(4, 2, r);
        EXPECT_LT(error_correlation(s, {1, 0}, 4, 64, 64), -0.05);
        EXPECT_LT(error_correlation(s, {0, 1}, 4, 64, 64), -0.05);
        EXPECT_NEAR(error_correlation(s, {100, 37}, 4, 64, 64), 0.0, 0.05);
    }
}

TEST(ZSobolSampler, ScramblesDifferBetweenDimensionsAndSeeds) {
    // Same pixel, same indices: other dimension pairs and other seeds give other point sets
    // (the chance that two independent scrambles of 16 points coincide is nil).
    ZSobolSampler a(16, 1, Randomization::Owen), b(16, 2, Randomization::Owen);
    auto samples = pixel_samples({3, 4}, 0, 16);
    auto first = points_2d(a, samples, 3);
    auto same = points_2d(a, samples, 3);
    auto other_dimension = points_2d(a, samples, 5);
    auto other_seed = points_2d(b, samples, 3);
    auto key = [](const std::vector<Vec2f> &p) {
        std::vector<std::pair<float, float>> v;
        for (Vec2f u : p) v.push_back({u.x, u.y});
        return v;
    };
    EXPECT_EQ(key(first), key(same));
    EXPECT_NE(key(first), key(other_dimension));
    EXPECT_NE(key(first), key(other_seed));
}

TEST(PaddedSobolSampler, RoundsContinueTheSequence) {
    // Each round of spp = 4 samples is a (0,2,2)-net, and the first 2^m samples over several
    // rounds are the first 2^m points of one scrambled (0,2)-sequence: a (0,m,2)-net.
    for (Randomization r : AllRandomizations) {
        PaddedSobolSampler s(4, 3, r);
        for (Vec2i pixel : {Vec2i{0, 0}, Vec2i{17, 29}})
            for (int dimension : {0, 3, 30}) {
                for (int round = 0; round < 4; ++round)
                    EXPECT_TRUE(is_02_net(points_2d(s, pixel_samples(pixel, 4 * round, 4), dimension), 2));
                for (int m = 2; m <= 8; ++m)
                    EXPECT_TRUE(is_02_net(points_2d(s, pixel_samples(pixel, 0, 1 << m), dimension), m))
                        << "m=" << m;
            }
    }
    // Seven samples are seven of the first eight points: at most one per eighth in 1D.
    PaddedSobolSampler seven(7, 3, Randomization::Owen);
    std::set<int> strata;
    for (int i = 0; i < 7; ++i) {
        seven.start_pixel_sample({2, 2}, i, 4);
        strata.insert(int(seven.get_1d() * 8));
    }
    EXPECT_EQ(strata.size(), 7u);
}

TEST(PaddedSobolSampler, PixelsAreIndependent) {
    // Each pixel has its own permutations and scrambles: even adjacent pixels' errors are
    // uncorrelated (standard deviation 1/sqrt(4 x 4096) = 0.008; bound 0.05).
    PaddedSobolSampler s(4, 2, Randomization::FastOwen);
    EXPECT_NEAR(error_correlation(s, {1, 0}, 4, 64, 64), 0.0, 0.05);
    EXPECT_NEAR(error_correlation(s, {0, 1}, 4, 64, 64), 0.0, 0.05);
}

TEST(SobolSampler, PixelSamplesAreTheSequencePointsInThePixel) {
    // Sample i of a pixel is the point of block i (indices i 2^32 ... (i+1) 2^32 - 1) whose
    // first two coordinates' leading 16 digits are the pixel's coordinates.
    SobolSampler s(16, 0, Randomization::None);
    for (Vec2i pixel : {Vec2i{0, 0}, Vec2i{1, 0}, Vec2i{0, 1}, Vec2i{639, 479}, Vec2i{65535, 12}})
        for (int i : {0, 1, 2, 15, 16, 1000, 123456}) {
            uint64_t index = s.sequence_index(pixel, i);
            EXPECT_EQ(index >> 32, uint64_t(i));
            EXPECT_EQ(sobol_bits(index, 0) >> 16, uint32_t(pixel.x));
            EXPECT_EQ(sobol_bits(index, 1) >> 16, uint32_t(pixel.y));
        }
    // Without randomisation, sample dimension d reads Sobol dimension d + 2 of that point, and
    // the pixel position is the digits after the pixel's.
    s.start_pixel_sample({7, 9}, 5);
    uint64_t index = s.sequence_index({7, 9}, 5);
    EXPECT_EQ(s.get_1d(), bits_to_unit_float(sobol_bits(index, 2)));
    EXPECT_EQ(s.get_pixel_2d().x, bits_to_unit_float(sobol_bits(index, 0) << 16));
    Vec2f lens = s.get_2d();
    EXPECT_EQ(lens.x, bits_to_unit_float(sobol_bits(index, 5)));
    EXPECT_EQ(lens.y, bits_to_unit_float(sobol_bits(index, 6)));
}

TEST(SobolSampler, PositionsWithinAPixelAreA02Net) {
    // The pixel's share of each block of 2^(32 + k) points is an elementary square of the
    // (0,2)-sequence, so its 2^k positions form a (0,k,2)-net, in later blocks too.
    SobolSampler s(16, 0, Randomization::FastOwen);
    for (Vec2i pixel : {Vec2i{0, 0}, Vec2i{300, 200}})
        for (int k = 0; k <= 8; ++k)
            for (int first : {0, 1 << k, 7 << k}) {
                std::vector<Vec2f> p;
                for (int i = first; i < first + (1 << k); ++i) {
                    s.start_pixel_sample(pixel, i);
                    s.get_1d();
                    p.push_back(s.get_pixel_2d());
                }
                EXPECT_TRUE(is_02_net(p, k)) << "k=" << k << " first=" << first;
            }
}

TEST(SobolSampler, DimensionsPastTheTableAreNotCopies) {
    // Sobol dimension 64 (sample dimension 62) reuses dimension 2 (sample dimension 0) under an
    // extra nested scramble, which maps intervals of length 1/16 onto intervals of length 1/16:
    // the same number of strata is occupied, by other values.
    SobolSampler s(16, 0, Randomization::None);
    std::set<int> strata, reused_strata;
    int equal = 0;
    for (int i = 0; i < 16; ++i) {
        s.start_pixel_sample({3, 3}, i, 0);
        float first = s.get_1d();
        s.start_pixel_sample({3, 3}, i, 62);
        float reused = s.get_1d();
        equal += first == reused;
        strata.insert(int(first * 16));
        reused_strata.insert(int(reused * 16));
    }
    EXPECT_LT(equal, 4);
    EXPECT_EQ(strata.size(), reused_strata.size());
}

TEST(SobolSamplers, IntegrateSmoothFunctionsFarBetterThanIndependentSamples) {
    // 256 samples per pixel over 400 pixels: mean squared error of a Gaussian bump and of
    // (x + y)^2 against their closed-form integrals (the bump's is a product of erf
    // differences, (x + y)^2 integrates to 7/6). Independent sampling's MSE is variance / 256;
    // scrambled (0,8,2)-nets converge as n^-3 for smooth integrands (Owen 1997, "Scrambled net
    // variance for integrals of smooth functions").
    //
    // Measured MSE / MSE(independent), bump and (x+y)^2, median and worst over seeds 0-29 (the
    // zsobol and sobol scrambles are shared by all pixels, so the ratio varies with the seed):
    //   zsobol fastowen   1.9e-3 (worst 7.6e-3)   4.3e-5 (1.3e-4)
    //   zsobol owen       1.5e-3 (worst 5.9e-3)   4.5e-5 (1.5e-4)
    //   paddedsobol       2.0e-3 (worst 2.4e-3)   4.3e-5 (5.4e-5)
    //   sobol fastowen    6.4e-3 (worst 0.18)     1.1e-4 (1.6e-3)
    // The global Sobol sampler's pixel samples are a subsequence whose higher dimensions are
    // less evenly spread than a net, hence its looser bound. The bounds are 2.5x (sobol 1.7x)
    // above the worst seed.
    const int n = 256, width = 20, height = 20;
    auto square = [](Vec2f u) { return double(u.x + u.y) * double(u.x + u.y); };
    struct Case {
        std::unique_ptr<Sampler> sampler;
        double bound;  // on MSE / MSE(independent), for both integrands
    };
    std::vector<Case> cases;
    cases.push_back({std::make_unique<ZSobolSampler>(n, 1, Randomization::FastOwen), 0.02});
    cases.push_back({std::make_unique<ZSobolSampler>(n, 1, Randomization::Owen), 0.02});
    cases.push_back({std::make_unique<PaddedSobolSampler>(n, 1, Randomization::FastOwen), 0.02});
    cases.push_back({std::make_unique<SobolSampler>(n, 1, Randomization::FastOwen), 0.3});
    IndependentSampler independent(n, 1);
    const double bump_mse = integration_mse(independent, bump, bump_integral(), n, width, height);
    const double square_mse = integration_mse(independent, square, 7.0 / 6.0, n, width, height);
    for (Case &c : cases) {
        EXPECT_LT(integration_mse(*c.sampler, bump, bump_integral(), n, width, height) / bump_mse, c.bound);
        EXPECT_LT(integration_mse(*c.sampler, square, 7.0 / 6.0, n, width, height) / square_mse, c.bound);
    }
}
