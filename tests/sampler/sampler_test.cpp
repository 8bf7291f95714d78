#include "sampler/halton_sampler.h"
#include "sampler/independent_sampler.h"
#include "sampler/padded_sobol_sampler.h"
#include "sampler/pmj02bn_sampler.h"
#include "sampler/sample_hash.h"
#include "sampler/sampler_factory.h"
#include "sampler/sobol_sampler.h"
#include "sampler/sobol_sequence.h"
#include "sampler/stratified_sampler.h"
#include "sampler/zsobol_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

using namespace caustica;

namespace {

ParsedParameter integer_param(const std::string &name, int v) {
    ParsedParameter p;
    p.type = "integer";
    p.name = name;
    p.numbers = {double(v)};
    return p;
}

ParsedParameter bool_param(const std::string &name, bool v) {
    ParsedParameter p;
    p.type = "bool";
    p.name = name;
    p.bools = {v};
    return p;
}

ParsedParameter string_param(const std::string &name, const std::string &v) {
    ParsedParameter p;
    p.type = "string";
    p.name = name;
    p.strings = {v};
    return p;
}

ParameterDictionary dict(std::vector<ParsedParameter> params) {
    return ParameterDictionary(std::move(params), SourceLocation{"scene.pbrt", 3, 1}, nullptr, ".");
}

// The first n values (mixing 1D and 2D requests) of one pixel sample.
std::vector<float> sequence(Sampler &s, Vec2i pixel, int index, int n, int dimension = 0) {
    s.start_pixel_sample(pixel, index, dimension);
    std::vector<float> v;
    while (int(v.size()) < n) {
        if (v.size() % 3 == 0) {
            v.push_back(s.get_1d());
        } else {
            Vec2f u = s.get_2d();
            v.push_back(u.x);
            v.push_back(u.y);
        }
    }
    return v;
}

std::vector<std::unique_ptr<Sampler>> all_samplers(int seed) {
    std::vector<std::unique_ptr<Sampler>> s;
    s.push_back(std::make_unique<IndependentSampler>(16, seed));
    s.push_back(std::make_unique<StratifiedSampler>(4, 4, true, seed));
    s.push_back(std::make_unique<StratifiedSampler>(3, 5, false, seed));
    for (Randomization r : {Randomization::Owen, Randomization::FastOwen,
                            Randomization::PermuteDigits, Randomization::None}) {
        s.push_back(std::make_unique<ZSobolSampler>(16, seed, r));
        s.push_back(std::make_unique<PaddedSobolSampler>(16, seed, r));
    }
    s.push_back(std::make_unique<ZSobolSampler>(8, seed, Randomization::Owen));
    s.push_back(std::make_unique<ZSobolSampler>(5, seed, Randomization::Owen));
    s.push_back(std::make_unique<PaddedSobolSampler>(7, seed, Randomization::Owen));
    // Without randomisation the global Sobol sampler ignores the seed, which the tests vary.
    s.push_back(std::make_unique<SobolSampler>(16, seed, Randomization::FastOwen));
    s.push_back(std::make_unique<SobolSampler>(16, seed, Randomization::Owen));
    s.push_back(std::make_unique<HaltonSampler>(16, Vec2i{64, 48}, seed, Randomization::PermuteDigits));
    s.push_back(std::make_unique<HaltonSampler>(8, Vec2i{300, 200}, seed, Randomization::Owen));
    s.push_back(std::make_unique<Pmj02bnSampler>(16, seed));
    s.push_back(std::make_unique<Pmj02bnSampler>(8, seed));
    return s;
}

} // namespace

TEST(Sampler, DeterministicPerPixelSampleAndSeed) {
    auto a = all_samplers(7), b = all_samplers(7), c = all_samplers(8);
    for (size_t k = 0; k < a.size(); ++k) {
        // The same (pixel, index, seed) gives the same values, whatever was drawn before and
        // whichever copy draws them; another seed gives other values.
        std::vector<float> first = sequence(*a[k], {5, 9}, 3, 30);
        sequence(*a[k], {1, 1}, 0, 17);
        EXPECT_EQ(first, sequence(*a[k], {5, 9}, 3, 30));
        EXPECT_EQ(first, sequence(*b[k], {5, 9}, 3, 30));
        auto copy = a[k]->clone();
        EXPECT_EQ(first, sequence(*copy, {5, 9}, 3, 30));
        EXPECT_NE(first, sequence(*c[k], {5, 9}, 3, 30));
        EXPECT_NE(first, sequence(*a[k], {5, 9}, 4, 30));
        EXPECT_NE(first, sequence(*a[k], {9, 5}, 3, 30));
    }
}

TEST(Sampler, StartingAtADimensionContinuesTheSequence) {
    for (auto &s : all_samplers(3)) {
        s->start_pixel_sample({2, 3}, 5);
        std::vector<float> v;
        for (int i = 0; i < 10; ++i) v.push_back(s->get_1d());
        s->start_pixel_sample({2, 3}, 5, 6);
        for (int i = 6; i < 10; ++i) EXPECT_EQ(v[i], s->get_1d());
        // A 2D request takes two consecutive dimensions.
        s->start_pixel_sample({2, 3}, 5, 2);
        s->get_2d();
        EXPECT_EQ(v[4], s->get_1d());
    }
}

TEST(Sampler, ValuesLieInTheUnitInterval) {
    // Every dimension, past the 64 of the Sobol table too, and sample indices past spp.
    for (auto &s : all_samplers(11)) {
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                for (int i = 0; i < 40; ++i) {
                    s->start_pixel_sample({x, y}, i);
                    for (int d = 0; d < 25; ++d) {
                        float u = s->get_1d();
                        EXPECT_GE(u, 0.f);
                        EXPECT_LT(u, 1.f);
                        Vec2f u2 = s->get_pixel_2d();
                        EXPECT_GE(u2.x, 0.f);
                        EXPECT_LT(u2.x, 1.f);
                        EXPECT_GE(u2.y, 0.f);
                        EXPECT_LT(u2.y, 1.f);
                    }
                }
    }
}

TEST(Sampler, IndependentSamplerIsUniformAndUncorrelated) {
    IndependentSampler s(1, 42);
    const int n = 200000;
    double sum = 0, sum_sq = 0, sum_xy = 0;
    int bins[10] = {};
    for (int i = 0; i < n; ++i) {
        s.start_pixel_sample({i % 512, i / 512}, i % 7);
        float a = s.get_1d(), b = s.get_1d();
        sum += a;
        sum_sq += a * a;
        sum_xy += (a - 0.5) * (b - 0.5);
        ++bins[int(a * 10)];
    }
    // Uniform on [0,1): mean 1/2, E[u^2] = 1/3, covariance 0. Standard errors for n = 2e5 are
    // 0.29/sqrt(n) = 6.5e-4 (mean), 0.30/sqrt(n) = 6.7e-4 (E[u^2]) and (1/12)/sqrt(n) = 1.9e-4
    // (covariance); the bounds are > 5 standard errors.
    EXPECT_NEAR(sum / n, 0.5, 4e-3);
    EXPECT_NEAR(sum_sq / n, 1.0 / 3, 4e-3);
    EXPECT_NEAR(sum_xy / n, 0.0, 1.5e-3);
    // Each tenth holds n/10 = 20000 values, binomial standard deviation 134: bound ~5 sigma.
    for (int b : bins) EXPECT_NEAR(b, n / 10, 700);
}

TEST(Sampler, StratifiedSamplerHitsEveryStratumOncePerRound) {
    for (bool jitter : {true, false}) {
        StratifiedSampler s(4, 3, jitter, 5);
        const int spp = s.samples_per_pixel();
        ASSERT_EQ(spp, 12);
        for (Vec2i pixel : {Vec2i{0, 0}, Vec2i{17, 3}, Vec2i{-1, 400}}) {
            for (int round = 0; round < 3; ++round) {
                // Several dimensions; within each, the spp samples of a round occupy distinct
                // strata, so every stratum exactly once.
                std::vector<std::set<int>> strata_1d(4), strata_2d(4);
                for (int i = round * spp; i < (round + 1) * spp; ++i) {
                    s.start_pixel_sample(pixel, i);
                    for (int d = 0; d < 4; ++d) {
                        float u = s.get_1d();
                        strata_1d[d].insert(int(u * spp));
                        if (!jitter) {
                            EXPECT_FLOAT_EQ(u * spp - int(u * spp), 0.5f);
                        }
                        Vec2f u2 = s.get_2d();
                        strata_2d[d].insert(int(u2.y * 3) * 4 + int(u2.x * 4));
                    }
                }
                for (int d = 0; d < 4; ++d) {
                    EXPECT_EQ(int(strata_1d[d].size()), spp);
                    EXPECT_EQ(int(strata_2d[d].size()), spp);
                }
            }
        }
    }
}

TEST(Sampler, StratumOrderDiffersBetweenDimensionsAndPixels) {
    // Were the order shared, dimensions would be perfectly correlated. Over 64 samples the
    // chance that two independent permutations agree is 1/64!, so any agreement is a bug.
    StratifiedSampler s(8, 8, false, 1);
    std::vector<int> d0, d1, other_pixel;
    for (int i = 0; i < 64; ++i) {
        s.start_pixel_sample({3, 4}, i);
        d0.push_back(int(s.get_1d() * 64));
        d1.push_back(int(s.get_1d() * 64));
        s.start_pixel_sample({4, 3}, i);
        other_pixel.push_back(int(s.get_1d() * 64));
    }
    EXPECT_NE(d0, d1);
    EXPECT_NE(d0, other_pixel);
}

TEST(Sampler, PermutationIsABijection) {
    for (uint32_t n : {1u, 2u, 3u, 7u, 16u, 17u, 100u, 1023u, 1024u, 1025u}) {
        for (uint64_t seed : {0ull, 1ull, 0xdeadbeefull}) {
            std::vector<bool> seen(n, false);
            for (uint32_t i = 0; i < n; ++i) {
                uint32_t p = permutation_element(i, n, seed);
                ASSERT_LT(p, n);
                EXPECT_FALSE(seen[p]);
                seen[p] = true;
            }
        }
    }
}

TEST(Sampler, StratifiedGridMatchesPbrtsFactorisation) {
    EXPECT_EQ(stratified_grid(16), (Vec2i{4, 4}));
    EXPECT_EQ(stratified_grid(8), (Vec2i{4, 2}));
    EXPECT_EQ(stratified_grid(7), (Vec2i{7, 1}));
    EXPECT_EQ(stratified_grid(1), (Vec2i{1, 1}));
    EXPECT_EQ(stratified_grid(12), (Vec2i{4, 3}));
}

TEST(SamplerFactory, CreatesPbrtSamplers) {
    set_warnings_enabled(false);
    SourceLocation loc{"scene.pbrt", 3, 1};
    EXPECT_EQ(create_sampler("independent", dict({}), loc, 0)->samples_per_pixel(), 4);
    EXPECT_EQ(create_sampler("independent", dict({integer_param("pixelsamples", 9)}), loc, 0)
                  ->samples_per_pixel(),
              9);
    EXPECT_EQ(create_sampler("stratified", dict({}), loc, 0)->samples_per_pixel(), 16);
    auto s = create_sampler("stratified",
                            dict({integer_param("xsamples", 2), integer_param("ysamples", 3),
                                  bool_param("jitter", false)}),
                            loc, 0);
    EXPECT_EQ(s->samples_per_pixel(), 6);
    s->start_pixel_sample({0, 0}, 0);
    float u = s->get_1d();
    EXPECT_FLOAT_EQ(u * 6 - int(u * 6), 0.5f);  // no jitter: stratum centres
    // The low-discrepancy samplers: pbrt's default of 16 samples.
    auto is_a = [](const std::unique_ptr<Sampler> &p, auto *type) {
        return dynamic_cast<std::remove_pointer_t<decltype(type)> *>(p.get()) != nullptr;
    };
    for (const char *name : {"halton", "sobol", "paddedsobol", "zsobol", "pmj02bn"}) {
        EXPECT_EQ(create_sampler(name, dict({}), loc, 0)->samples_per_pixel(), 16);
        EXPECT_EQ(create_sampler(name, dict({integer_param("pixelsamples", 8)}), loc, 0)
                      ->samples_per_pixel(),
                  8);
    }
    EXPECT_TRUE(is_a(create_sampler("zsobol", dict({}), loc, 0), (ZSobolSampler *)nullptr));
    EXPECT_TRUE(is_a(create_sampler("halton", dict({}), loc, 0), (HaltonSampler *)nullptr));
    EXPECT_TRUE(is_a(create_sampler("pmj02bn", dict({}), loc, 0), (Pmj02bnSampler *)nullptr));
    EXPECT_TRUE(is_a(create_sampler("paddedsobol", dict({}), loc, 0), (PaddedSobolSampler *)nullptr));
    EXPECT_TRUE(is_a(create_sampler("sobol", dict({}), loc, 0), (SobolSampler *)nullptr));
    EXPECT_TRUE(is_a(create_default_sampler(0), (ZSobolSampler *)nullptr));
    EXPECT_EQ(create_default_sampler(0)->samples_per_pixel(), 16);
    // The command line's sample count wins.
    EXPECT_EQ(create_sampler("stratified", dict({}), loc, 0, 10)->samples_per_pixel(), 10);
    EXPECT_EQ(create_sampler("zsobol", dict({}), loc, 0, 3)->samples_per_pixel(), 3);
    EXPECT_EQ(create_default_sampler(0, 5)->samples_per_pixel(), 5);
    set_warnings_enabled(true);
}

TEST(SamplerFactory, SeedParameterOverridesTheDefault) {
    SourceLocation loc{"scene.pbrt", 3, 1};
    auto a = create_sampler("independent", dict({integer_param("seed", 5)}), loc, 1);
    auto b = create_sampler("independent", dict({}), loc, 5);
    auto c = create_sampler("independent", dict({}), loc, 1);
    EXPECT_EQ(sequence(*a, {1, 2}, 0, 6), sequence(*b, {1, 2}, 0, 6));
    EXPECT_NE(sequence(*a, {1, 2}, 0, 6), sequence(*c, {1, 2}, 0, 6));
}

TEST(SamplerFactory, RandomizationParameterSelectsTheScramble) {
    set_warnings_enabled(false);
    SourceLocation loc{"scene.pbrt", 3, 1};
    for (const char *type : {"zsobol", "paddedsobol", "sobol", "halton"}) {
        // Each name builds the sampler with that randomisation.
        for (auto [name, r] : {std::pair{"owen", Randomization::Owen},
                               std::pair{"fastowen", Randomization::FastOwen},
                               std::pair{"permutedigits", Randomization::PermuteDigits},
                               std::pair{"none", Randomization::None}}) {
            auto params = dict({string_param("randomization", name)});
            if (std::string(type) == "halton" && r == Randomization::FastOwen) {
                // As in pbrt-v4, which has no fast Owen scrambling for Halton points.
                EXPECT_THROW(create_sampler(type, params, loc, 3), InputError);
                continue;
            }
            auto made = create_sampler(type, params, loc, 3);
            std::unique_ptr<Sampler> expected;
            if (std::string(type) == "paddedsobol")
                expected = std::make_unique<PaddedSobolSampler>(16, 3, r);
            else if (std::string(type) == "sobol")
                expected = std::make_unique<SobolSampler>(16, 3, r);
            else if (std::string(type) == "halton")
                expected = std::make_unique<HaltonSampler>(16, Vec2i{1280, 720}, 3, r);
            else
                expected = std::make_unique<ZSobolSampler>(16, 3, r);
            EXPECT_EQ(sequence(*made, {4, 7}, 2, 12), sequence(*expected, {4, 7}, 2, 12)) << type << name;
        }
        EXPECT_THROW(create_sampler(type, dict({string_param("randomization", "scrambled")}), loc, 0),
                     InputError);
    }
    // pbrt-v4's defaults: permutedigits for halton, fastowen everywhere else, also for the
    // default sampler.
    EXPECT_EQ(sequence(*create_sampler("halton", dict({}), loc, 3), {1, 2}, 0, 9),
              sequence(*std::make_unique<HaltonSampler>(16, Vec2i{1280, 720}, 3, Randomization::PermuteDigits),
                       {1, 2}, 0, 9));
    EXPECT_EQ(sequence(*create_sampler("zsobol", dict({}), loc, 3), {1, 2}, 0, 9),
              sequence(*std::make_unique<ZSobolSampler>(16, 3, Randomization::FastOwen), {1, 2}, 0, 9));
    EXPECT_EQ(sequence(*create_sampler("paddedsobol", dict({}), loc, 3), {1, 2}, 0, 9),
              sequence(*std::make_unique<PaddedSobolSampler>(16, 3, Randomization::FastOwen), {1, 2}, 0, 9));
    EXPECT_EQ(sequence(*create_sampler("sobol", dict({}), loc, 3), {1, 2}, 0, 9),
              sequence(*std::make_unique<SobolSampler>(16, 3, Randomization::FastOwen), {1, 2}, 0, 9));
    EXPECT_EQ(sequence(*create_default_sampler(3), {1, 2}, 0, 9),
              sequence(*std::make_unique<ZSobolSampler>(16, 3, Randomization::FastOwen), {1, 2}, 0, 9));
    set_warnings_enabled(true);
}

TEST(SamplerFactory, WarnsAboutCountsThatStratifyBadly) {
    SourceLocation loc{"scene.pbrt", 3, 1};
    auto warnings_of = [&](const std::string &type, std::vector<ParsedParameter> params, int spp) {
        testing::internal::CaptureStderr();
        create_sampler(type, dict(std::move(params)), loc, 0, spp);
        return testing::internal::GetCapturedStderr();
    };
    // pmj02bn, as in pbrt-v4, for counts that are not powers of 4.
    EXPECT_EQ(warnings_of("pmj02bn", {}, 0), "");
    EXPECT_EQ(warnings_of("pmj02bn", {integer_param("pixelsamples", 64)}, 0), "");
    std::string pmj = warnings_of("pmj02bn", {integer_param("pixelsamples", 8)}, 0);
    EXPECT_NE(pmj.find("scene.pbrt:3:1: warning"), std::string::npos) << pmj;
    EXPECT_NE(pmj.find("power-of-4"), std::string::npos) << pmj;
    EXPECT_NE(warnings_of("pmj02bn", {}, 32).find("power-of-4"), std::string::npos);
    EXPECT_EQ(warnings_of("halton", {integer_param("pixelsamples", 12)}, 0), "");
    EXPECT_EQ(warnings_of("zsobol", {}, 0), "");
    EXPECT_EQ(warnings_of("zsobol", {integer_param("pixelsamples", 64)}, 0), "");
    EXPECT_NE(warnings_of("zsobol", {integer_param("pixelsamples", 12)}, 0).find("power-of-two"),
              std::string::npos);
    EXPECT_NE(warnings_of("zsobol", {}, 12).find("power-of-two"), std::string::npos);
    EXPECT_EQ(warnings_of("paddedsobol", {integer_param("pixelsamples", 12)}, 0), "");
}

TEST(SamplerFactory, RejectsBadInput) {
    SourceLocation loc{"scene.pbrt", 3, 1};
    EXPECT_THROW(create_sampler("metropolis", dict({}), loc, 0), InputError);
    EXPECT_THROW(create_sampler("independent", dict({integer_param("pixelsamples", 0)}), loc, 0),
                 InputError);
    EXPECT_THROW(create_sampler("stratified", dict({integer_param("xsamples", -2)}), loc, 0),
                 InputError);
}

// pbrt-v4's Halton sampler gives each pixel of the tile its own subsequence: a pixel's
// consecutive samples step the base-2 index by an odd number and the base-3 index by a power of
// two, so n consecutive samples fall in n different strata of x (n a power of two) and of y
// (n a power of three) within the pixel.
TEST(HaltonSampler, PixelSamplesAreStratifiedWithinThePixel) {
    for (Randomization r : {Randomization::PermuteDigits, Randomization::Owen, Randomization::None}) {
        HaltonSampler s(16, Vec2i{20, 12}, 5, r);
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 20; ++x) {
                std::set<int> x_strata, y_strata;
                for (int i = 0; i < 4; ++i) {
                    s.start_pixel_sample({x, y}, i);
                    s.get_1d();
                    x_strata.insert(int(s.get_pixel_2d().x * 4));
                }
                for (int i = 0; i < 9; ++i) {
                    s.start_pixel_sample({x, y}, i);
                    s.get_1d();
                    y_strata.insert(int(s.get_pixel_2d().y * 9));
                }
                EXPECT_EQ(x_strata.size(), 4u);
                EXPECT_EQ(y_strata.size(), 9u);
            }
    }
}

// Every dimension is uniform: its values' mean and their fraction below 1/2 match a uniform
// variable's within 4 standard errors (of independent samples; stratification only lowers the
// error), and consecutive dimensions are uncorrelated.
TEST(HaltonSampler, DimensionsAreUniformAndUncorrelated) {
    HaltonSampler s(16, Vec2i{8, 8}, 9, Randomization::PermuteDigits);
    const int n = 4096;
    for (int d = 0; d < 40; d += 3) {
        double sum = 0, below = 0, product = 0;
        for (int i = 0; i < n; ++i) {
            s.start_pixel_sample({i % 8, (i / 8) % 8}, i / 64, d);
            float a = s.get_1d(), b = s.get_1d();
            sum += a;
            below += a < 0.5f;
            product += (a - 0.5) * (b - 0.5);
        }
        EXPECT_NEAR(sum / n, 0.5, 4 * std::sqrt(1.0 / 12 / n)) << d;
        EXPECT_NEAR(below / n, 0.5, 4 * 0.5 / std::sqrt(double(n))) << d;
        EXPECT_NEAR(product / n, 0, 4 * (1.0 / 12) / std::sqrt(double(n))) << d;
    }
}
