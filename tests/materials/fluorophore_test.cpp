// The fluorophore (materials/fluorophore.h) and its lobes (fluorescent_bxdf.h): energy, the
// sampled wavelength shifts against the closed-form albedos, and the elastic lobe's share.
#include "materials/fluorescent_bxdf.h"
#include "materials/fluorophore.h"
#include "spectral/sampled_wavelengths.h"
#include "spectral/spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace caustica;

namespace {

std::shared_ptr<const Spectrum> knots(std::initializer_list<float> pairs) {
    const std::vector<float> v(pairs);
    return PiecewiseLinearSpectrum::from_interleaved(v, false);
}

// A dye absorbing up to 480 nm and emitting from 430 nm: absorption and emission overlap, where
// the model must not emit above the energy it absorbed (anti-Stokes is left out).
Fluorophore overlapping_dye(float yield) {
    return Fluorophore(knots({300, 0.95f, 460, 0.95f, 480, 0, 900, 0}), knots({430, 0, 500, 1, 650, 0}), yield);
}

// Energy leaving at any wavelength per unit absorbed at lambda_in, by the midpoint rule.
double reradiated_fraction(const Fluorophore &dye, float lambda_in) {
    double sum = 0;
    for (float lo = LambdaMin + 0.05f; lo < LambdaMax; lo += 0.1f) sum += dye.reradiation(lambda_in, lo) * 0.1;
    return sum;
}

TEST(Fluorophore, NoMoreLeavesThanTheQuantumYieldAllows) {
    for (float yield : {1.f, 0.6f}) {
        const Fluorophore dye = overlapping_dye(yield);
        double largest = 0;
        for (float li = LambdaMin + 0.5f; li < LambdaMax; li += 1) {
            const double fraction = reradiated_fraction(dye, li);
            // Energy out over energy absorbed: at most Q, since each photon leaves with no more
            // energy than it came with.
            if (dye.absorption(li) > 0) {
                EXPECT_LE(fraction, yield * dye.absorption(li) * 1.0001) << li;
                largest = std::max(largest, fraction / (yield * dye.absorption(li)));
            }
            EXPECT_NEAR(dye.importance_albedo(li), fraction, 0.01 * yield) << li;
        }
        // The bound is nearly reached for ultraviolet light (the energy ratio is what is lost).
        EXPECT_GT(largest, 0.7);
    }
}

// E over u of the sampled shift's per-lane albedo is the closed-form albedo of that lane: the
// absorbed wavelength's density (radiance) and the emitted one's (importance) are exact.
TEST(Fluorophore, SampledShiftsAverageToTheAlbedos) {
    const Fluorophore dye = overlapping_dye(0.9f);
    const SampledWavelengths lambda = SampledWavelengths::sample_uniform(0.37f, 400, 700);
    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
        const int n = 200000;
        SampledSpectrum sum(0.f);
        for (int i = 0; i < n; ++i) sum += sample_reradiation_shift(dye, mode, lambda, (i + 0.5f) / n).albedo;
        for (int j = 0; j < NumWavelengths; ++j) {
            const float expected = mode == TransportMode::Radiance ? dye.radiance_albedo(lambda[j]) : dye.importance_albedo(lambda[j]);
            // Radiance, by the midpoint rule over the absorbed wavelength.
            double integral = 0;
            for (float l = LambdaMin + 0.05f; l < LambdaMax; l += 0.1f)
                integral += (mode == TransportMode::Radiance ? dye.reradiation(l, lambda[j]) : dye.reradiation(lambda[j], l)) * 0.1;
            EXPECT_NEAR(sum[j] / n, integral, 2e-3 * std::max(integral, 1e-3)) << lambda[j];
            EXPECT_NEAR(expected, integral, 0.01 * std::max(integral, 1e-2)) << lambda[j];
        }
    }
}

// What a dye re-emits of a 1-nm line at 370 nm: the line's power times pi f, which is
// a Q (370 / l) e(l) at every longer wavelength and nothing below.
TEST(Fluorophore, ReemitsALineAsItsEmissionSpectrum) {
    const Fluorophore dye = overlapping_dye(0.8f);
    const std::vector<float> out = dye.reemitted([](float l) { return l == 370 ? 2.f : 0.f; });
    ASSERT_EQ(out.size(), size_t(LambdaMax - LambdaMin + 1));
    for (int nm = int(LambdaMin); nm <= int(LambdaMax); ++nm) {
        // The emission triangle 430-500-650 nm has area 110; the absorption at 370 nm is 0.95.
        const float e = nm <= 430 || nm >= 650 ? 0.f : nm <= 500 ? (nm - 430) / 70.f : (650 - nm) / 150.f;
        const float expected = 2 * 0.95f * 0.8f * (370.f / nm) * e / 110;
        EXPECT_NEAR(out[size_t(nm - LambdaMin)], expected, 1e-3f * expected + 1e-9f) << nm;
        if (nm < 370) {
            EXPECT_EQ(out[size_t(nm - LambdaMin)], 0.f);
        }
    }
    EXPECT_GT(out[size_t(500 - LambdaMin)], 0.f);
}

// Anti-Stokes emission is left out: no light leaves at a shorter wavelength than it arrived at,
// even where absorption and emission overlap (the dye above absorbs and emits at 440-480 nm).
TEST(Fluorophore, NeverEmitsShorterThanItAbsorbs) {
    const Fluorophore dye = overlapping_dye(1);
    EXPECT_GT(dye.reradiation(450, 470), 0.f);
    EXPECT_EQ(dye.reradiation(470, 450), 0.f);
    EXPECT_EQ(dye.reradiation(470, 469.9f), 0.f);
    EXPECT_GT(dye.reradiation(470, 470), 0.f);
}

TEST(Fluorophore, EmissionWithoutPowerIsRefused) {
    EXPECT_THROW(Fluorophore(knots({300, 1, 900, 1}), knots({900, 1, 950, 1}), 1), std::invalid_argument);
}

// The elastic lobe is sampled for its share of uc alone, with the density pdf() reports, which
// integrates to that share; the re-radiation lobe takes the rest of uc.
TEST(FluorescentBxDF, ElasticLobeTakesItsShare) {
    const Fluorophore dye = overlapping_dye(1);
    const Reradiation reradiation{&dye, 0.3f, 0.6f};
    const FluorescentBxDF elastic(SampledSpectrum(0.4f), reradiation);
    const ReradiationBxDF shifted(SampledSpectrum(2.f), reradiation);
    const Vec3f wo = normalize(Vec3f{0.3f, -0.2f, 0.9f});
    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
        const float p = reradiation.probability(mode);
        int elastic_samples = 0, shifted_samples = 0;
        const int n = 1000;
        for (int i = 0; i < n; ++i) {
            const float uc = (i + 0.5f) / n;
            const Vec2f u{0.3f, 0.7f};
            if (auto s = elastic.sample_f(wo, uc, u, mode)) {
                ++elastic_samples;
                EXPECT_NEAR(s->pdf, elastic.pdf(wo, s->wi, mode), 1e-6f);
                EXPECT_NEAR(s->pdf, (1 - p) * std::abs(s->wi.z) / 3.14159265f, 1e-6f);
            }
            if (uc < p && shifted.sample_f(wo, uc, u, mode)) ++shifted_samples;
        }
        EXPECT_NEAR(elastic_samples, (1 - p) * n, 1);
        EXPECT_NEAR(shifted_samples, p * n, 1);
        // Both lobes' densities integrate to their shares: cosine-weighted over the hemisphere.
        double elastic_total = 0, shifted_total = 0;
        const int m = 400;
        for (int a = 0; a < m; ++a)
            for (int b = 0; b < m; ++b) {
                const float cos_theta = (a + 0.5f) / m, phi = 2 * 3.14159265f * (b + 0.5f) / m;
                const float sin_theta = std::sqrt(1 - cos_theta * cos_theta);
                const Vec3f wi{sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
                const double dw = 2 * 3.14159265 / (double(m) * m);
                elastic_total += elastic.pdf(wo, wi, mode) * dw;
                shifted_total += shifted.pdf(wo, wi, mode) * dw;
            }
        EXPECT_NEAR(elastic_total, 1 - p, 1e-3);
        EXPECT_NEAR(shifted_total, p, 1e-3);
    }
}

} // namespace
