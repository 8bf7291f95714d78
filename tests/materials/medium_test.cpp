// Homogeneous media and the Henyey-Greenstein phase function: closed forms, normalisation,
// sampling against the densities, and the unbiasedness and bounds of the wavelength-mixture
// free-flight sampling described in media/medium.h.
//
// Monte Carlo checks use fixed seeds and a bound of 4.5 standard errors (estimated from the
// samples themselves): a correct implementation exceeds it with probability below 1e-5 per check,
// while the errors these checks exist to catch (a wrong density, a missing term of the mixture)
// are biases of several percent, tens of standard errors at these sample counts.
#include "chi_square.h"
#include "medium_test_support.h"
#include "param_helpers.h"

#include "core/error.h"
#include "core/rng.h"
#include "media/homogeneous_medium.h"
#include "media/medium_factory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace caustica {
namespace {

using testing::expect_mean;
using testing::LinearSpectrum;
using testing::RunningMean;

TEST(HenyeyGreenstein, IntegratesToOneAndIsSymmetric) {
    for (float g : {-0.9f, -0.4f, 0.f, 0.3f, 0.8f, 0.95f}) {
        HenyeyGreenstein phase(g);
        const Vec3f wo = normalize(Vec3f(0.3f, -0.2f, 0.9f));
        Vec3f s, t;
        coordinate_system(-wo, &s, &t);
        // Midpoint rule in cos(theta) about -wo, with 2e5 intervals: the integrand's curvature is
        // largest at g = 0.95 near theta = 0, where the rule's relative error is below 1e-4.
        const int n = 200000;
        double integral = 0;
        for (int i = 0; i < n; ++i) {
            double mu = -1 + (i + 0.5) * 2.0 / n;
            Vec3f wi = s * float(std::sqrt(1 - mu * mu)) + (-wo) * float(mu);
            integral += phase.p(wo, wi) * 2 * Pi * (2.0 / n);
        }
        EXPECT_NEAR(integral, 1.0, 2e-3) << "g = " << g;
        Rng rng(3, 5);
        for (int i = 0; i < 100; ++i) {
            Vec3f a = normalize(Vec3f(rng.uniform() - .5f, rng.uniform() - .5f, rng.uniform() - .5f));
            Vec3f b = normalize(Vec3f(rng.uniform() - .5f, rng.uniform() - .5f, rng.uniform() - .5f));
            EXPECT_NEAR(phase.p(a, b), phase.p(b, a), 1e-6f * phase.p(a, b));
        }
    }
}

TEST(HenyeyGreenstein, SamplingMatchesTheDensity) {
    // Chi-square at level 1e-3 per case (see chi_square.h); the chart is centred on the forward
    // direction -wo and magnifies it for the narrow lobes.
    const Vec3f wo = normalize(Vec3f(0.2f, 0.5f, -0.8f));
    uint64_t seed = 11;
    for (float g : {-0.7f, 0.f, 0.5f, 0.9f}) {
        HenyeyGreenstein phase(g);
        auto sample = [&](float, Vec2f u, Vec3f *w) {
            PhaseSample ps = phase.sample_p(wo, u);
            EXPECT_NEAR(ps.p, phase.pdf(wo, ps.wi), 1e-3f * ps.p);
            *w = ps.wi;
            return true;
        };
        auto pdf = [&](Vec3f wi) { return double(phase.pdf(wo, wi)); };
        testing::SphereChart chart{-wo, g > 0.8f ? 2.f : 1.f};
        auto result = testing::chi_square_test(sample, pdf, chart, 100000, seed++);
        EXPECT_GT(result.p_value, 1e-3) << "g = " << g << "\n" << result.details;
    }
}

TEST(HenyeyGreenstein, MeanCosineIsG) {
    // E[cos] = g is the definition of the asymmetry parameter; cos is bounded by 1, so the
    // standard error with 2e5 samples is below 2.3e-3.
    const Vec3f wo = normalize(Vec3f(1, 2, 3));
    for (float g : {-0.5f, 0.f, 0.2f, 0.85f}) {
        HenyeyGreenstein phase(g);
        Rng rng(9, 2);
        RunningMean m;
        for (int i = 0; i < 200000; ++i) m.add(dot(-wo, phase.sample_p(wo, rng.uniform2()).wi));
        expect_mean(m, g, "mean cosine");
    }
}

TEST(HomogeneousMedium, TransmittanceIsBeerLambert) {
    HomogeneousMedium medium(std::make_shared<ConstantSpectrum>(0.3f), std::make_shared<ConstantSpectrum>(0.5f), 2, 0);
    SampledWavelengths lambda = SampledWavelengths::sample_visible(0.4f);
    for (float d : {0.f, 0.01f, 1.f, 7.5f}) {
        SampledSpectrum T = medium.transmittance(Ray{}, d, lambda);
        for (int i = 0; i < NumWavelengths; ++i) EXPECT_NEAR(T[i], std::exp(-1.6 * d), 1e-6) << d;
    }
    SampledSpectrum far = medium.transmittance(Ray{}, Infinity, lambda);
    EXPECT_EQ(far.max_value(), 0.f);
    HomogeneousMedium clear(std::make_shared<ConstantSpectrum>(0.f), std::make_shared<ConstantSpectrum>(0.f), 1, 0);
    EXPECT_EQ(clear.transmittance(Ray{}, Infinity, lambda).average(), 1.f) << "a clear medium over infinity is 0 * inf";
}

// The event's f and densities, with the lane drawn uniformly and the balance heuristic over
// the lanes, f / mean_k density_k (the weight of a subpath's first event, path_segment.h), is
// unbiased per wavelength: E[weight; passed] = T(t_max) and E[weight; scattered] = integral of
// sigma_s T(t) over [0, t_max] = sigma_s / sigma_t (1 - T(t_max)). Wrong densities or a
// distance not drawn with the lane's extinction bias it.
void check_free_flight(const HomogeneousMedium &medium, SampledWavelengths lambda, float t_max, uint64_t seed) {
    SampledSpectrum sigma_s = medium.sigma_s(lambda), sigma_t = medium.sigma_a(lambda) + sigma_s;
    const int carried = lambda.secondary_terminated() ? 1 : NumWavelengths;
    std::vector<RunningMean> passed(NumWavelengths), scattered(NumWavelengths);
    Rng rng(seed, 1);
    float max_scattered_ratio = 0, max_passed = 0;
    for (int n = 0; n < 400000; ++n) {
        const int lane = std::min(int(rng.uniform() * NumWavelengths), NumWavelengths - 1);
        MediumEvent e = medium.sample_distance(Ray{}, t_max, lambda, lane, rng.uniform());
        const SampledSpectrum weight = e.f / e.density.average();
        ASSERT_FALSE(weight.has_non_finite());
        ASSERT_LE(e.t, t_max);
        for (int i = 0; i < NumWavelengths; ++i) {
            passed[i].add(e.scattered ? 0 : weight[i]);
            scattered[i].add(e.scattered ? weight[i] : 0);
            if (e.scattered) max_scattered_ratio = std::max(max_scattered_ratio, weight[i] * sigma_t[i] / sigma_s[i]);
            else max_passed = std::max(max_passed, weight[i]);
        }
    }
    for (int i = 0; i < NumWavelengths; ++i) {
        double T = std::exp(-double(sigma_t[i]) * t_max);
        if (i >= carried) {
            EXPECT_EQ(passed[i].sum + scattered[i].sum, 0) << "a terminated wavelength carries nothing";
            continue;
        }
        expect_mean(passed[i], T, "passed, wavelength " + std::to_string(i));
        expect_mean(scattered[i], sigma_s[i] / sigma_t[i] * (1 - T), "scattered, wavelength " + std::to_string(i));
    }
    // Each weight is one lane's density over the mean of all: at most NumWavelengths times
    // sigma_s / sigma_t when scattering, NumWavelengths when passing.
    EXPECT_LE(max_scattered_ratio, NumWavelengths * (1 + 1e-4f));
    EXPECT_LE(max_passed, NumWavelengths * (1 + 1e-4f));
}

TEST(HomogeneousMedium, FreeFlightSamplingIsUnbiasedPerWavelength) {
    // Coefficients that differ by 8x across the spectrum, and an albedo that varies too.
    HomogeneousMedium medium(std::make_shared<LinearSpectrum>(0.1f, 1.2f), std::make_shared<LinearSpectrum>(2.5f, 0.4f),
                             1, 0.3f);
    uint64_t seed = 1;
    for (float u : {0.1f, 0.6f})
        for (float t_max : {0.05f, 0.7f, 4.f}) check_free_flight(medium, SampledWavelengths::sample_visible(u), t_max, seed++);
    SampledWavelengths hero_only = SampledWavelengths::sample_visible(0.3f);
    hero_only.terminate_secondary();
    check_free_flight(medium, hero_only, 0.7f, seed++);
}

TEST(HomogeneousMedium, AnAbsorbingMediumWeightsByTransmittance) {
    // Without scattering no event is sampled: the weight is the transmittance itself, so
    // absorption adds no variance.
    HomogeneousMedium medium(std::make_shared<LinearSpectrum>(0.1f, 1.2f), std::make_shared<ConstantSpectrum>(0.f), 1, 0);
    SampledWavelengths lambda = SampledWavelengths::sample_visible(0.25f);
    Rng rng(2, 2);
    for (int n = 0; n < 1000; ++n) {
        float t_max = 3 * rng.uniform();
        MediumEvent e = medium.sample_distance(Ray{}, t_max, lambda, n % NumWavelengths, rng.uniform());
        ASSERT_FALSE(e.scattered);
        SampledSpectrum T = medium.transmittance(Ray{}, t_max, lambda);
        for (int i = 0; i < NumWavelengths; ++i) {
            ASSERT_FLOAT_EQ(e.f[i], T[i]);
            ASSERT_EQ(e.density[i], 1.f);
        }
    }
}

TEST(HomogeneousMedium, FreeFlightDistancesFollowTheLanesExtinction) {
    // Kolmogorov-Smirnov against the lane's CDF F(t) = 1 - exp(-sigma_t,lane t) with an infinite
    // segment (every sample scatters); 1.95 / sqrt(N) is the 1e-3 critical value.
    HomogeneousMedium medium(std::make_shared<LinearSpectrum>(0.2f, 3.f), std::make_shared<ConstantSpectrum>(0.5f), 1, 0);
    SampledWavelengths lambda = SampledWavelengths::sample_visible(0.77f);
    SampledSpectrum sigma_t = medium.sigma_a(lambda) + medium.sigma_s(lambda);
    Rng rng(4, 4);
    const int n = 50000;
    std::vector<float> t(n);
    const int lane = 2;
    for (float &x : t) {
        MediumEvent e = medium.sample_distance(Ray{}, Infinity, lambda, lane, rng.uniform());
        ASSERT_TRUE(e.scattered);
        // The reported densities are each wavelength's exponential density there.
        for (int k = 0; k < NumWavelengths; ++k)
            ASSERT_NEAR(e.density[k], sigma_t[k] * std::exp(-sigma_t[k] * e.t), 1e-5f * sigma_t[k]);
        x = e.t;
    }
    std::sort(t.begin(), t.end());
    double d = 0;
    for (int i = 0; i < n; ++i) {
        const double F = 1 - std::exp(-double(sigma_t[lane]) * t[i]);
        d = std::max({d, std::abs(F - double(i) / n), std::abs(F - double(i + 1) / n)});
    }
    EXPECT_LT(d, 1.95 / std::sqrt(double(n)));
}

TEST(MediumFactory, ReadsPbrtParametersAndRejectsBadValues) {
    using testing::dictionary;
    using testing::numbers;
    using testing::input_error_line;
    using testing::strings;
    SampledWavelengths lambda = SampledWavelengths::sample_visible(0.5f);

    MediumPtr defaults = create_medium("homogeneous", dictionary({}), {});
    EXPECT_NEAR(defaults->properties({}, lambda).sigma_a[0], 1, 1e-6f) << "pbrt-v4's default coefficients are 1";
    EXPECT_NEAR(defaults->properties({}, lambda).sigma_s[2], 1, 1e-6f);

    MediumPtr scaled = create_medium("homogeneous",
                                     dictionary({numbers("spectrum", "sigma_a", {0.25}, 2),
                                                 numbers("spectrum", "sigma_s", {0.5}, 3),
                                                 numbers("float", "scale", {4}, 4), numbers("float", "g", {0.6}, 5)}),
                                     {});
    EXPECT_NEAR(scaled->properties({}, lambda).sigma_a[1], 1, 1e-6f);
    EXPECT_NEAR(scaled->properties({}, lambda).sigma_s[1], 2, 1e-6f);
    EXPECT_FLOAT_EQ(scaled->phase().g(), 0.6f);

    auto error_line = [&](const std::string &type, std::vector<ParsedParameter> params) {
        return input_error_line(
            [&] { create_medium(type, dictionary(std::move(params)), SourceLocation{"test.pbrt", 1, 1}); });
    };
    EXPECT_EQ(error_line("homogeneous", {numbers("float", "g", {1}, 7)}), 7);
    EXPECT_EQ(error_line("homogeneous", {numbers("float", "g", {-1.5}, 7)}), 7);
    EXPECT_EQ(error_line("homogeneous", {numbers("spectrum", "sigma_a", {-0.1}, 8)}), 8);
    EXPECT_EQ(error_line("homogeneous", {numbers("rgb", "sigma_s", {1, std::nan(""), 1}, 9)}), 9);
    EXPECT_EQ(error_line("homogeneous", {numbers("float", "scale", {-2}, 6)}), 6);
    EXPECT_EQ(error_line("homogeneous", {numbers("spectrum", "Le", {-1}, 3)}), 3) << "negative emission";
    EXPECT_EQ(error_line("homogeneous", {numbers("rgb", "Le", {1, 1, 1}, 3)}), -1) << "an emissive medium";
    EXPECT_EQ(error_line("homogeneous", {strings("string", "preset", {"unobtainium"}, 4)}), 4);
    EXPECT_EQ(error_line("uniformgrid", {}), 1);
    // A Jensen et al. 2001 preset: skin1's sigma_a is (0.032, 0.17, 0.48) per mm, so at a red
    // wavelength it is far below the blue one, and "scale" 1000 converts to metres.
    MediumPtr skin = create_medium("homogeneous",
                                   dictionary({strings("string", "preset", {"Skin1"}, 2), numbers("float", "scale", {1000}, 3)}),
                                   {});
    SampledWavelengths red = SampledWavelengths::fixed(640), blue = SampledWavelengths::fixed(450);
    EXPECT_GT(skin->properties({}, blue).sigma_a[0], 5 * skin->properties({}, red).sigma_a[0]);
    EXPECT_NEAR(skin->properties({}, red).sigma_s[0], 740, 150) << "sigma_s' of skin1 in red is 0.74 per mm";
    EXPECT_EQ(error_line("homogeneous", {numbers("rgb", "Le", {0, 0, 0}, 3)}), -1) << "zero emission is allowed";
}

} // namespace
} // namespace caustica
