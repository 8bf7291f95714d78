// Thin-film interference (src/materials/thin_film.h) against closed forms: a quarter-wave film
// at normal incidence, the half-wave "absentee" film, energy conservation over a lossless base
// with T computed from its own amplitudes, a zero thickness as the bare interface, and the
// conductor BxDF with a film.
#include "materials/conductor_bxdf.h"
#include "materials/dielectric_bxdf.h"
#include "materials/fresnel.h"
#include "materials/thin_dielectric_bxdf.h"
#include "materials/thin_film.h"

#include <gtest/gtest.h>

#include <cmath>

namespace caustica {
namespace {

// A quarter-wave film (n_f d = lambda / 4) at normal incidence reflects
// ((n3 - n_f^2) / (n3 + n_f^2))^2 (Born and Wolf 7.6.1): zero for n_f = sqrt(n3), the ideal
// anti-reflection coating.
TEST(ThinFilm, QuarterWaveCoating) {
    for (float lambda : {450.f, 550.f, 650.f})
        for (auto [n_f, n3] : {std::pair{1.2247449f, 1.5f}, std::pair{1.38f, 1.52f}, std::pair{2.0f, 1.5f}}) {
            const float d = lambda / (4 * n_f);
            const float expected = std::pow((n3 - n_f * n_f) / (n3 + n_f * n_f), 2.f);
            EXPECT_NEAR(thin_film_response(1, n_f, n3, d, lambda).reflectance, expected, 1e-6f)
                << n_f << " " << n3 << " " << lambda;
        }
    // Away from its design wavelength the coating reflects more.
    const float d = 550 / (4 * 1.2247449f);
    EXPECT_GT(thin_film_response(1, 1.2247449f, 1.5f, d, 420).reflectance, 1e-3f);
}

// A half-wave film (n_f d = lambda / 2) is absent at normal incidence; a zero thickness is the
// bare interface at every angle, for glass and for a metal.
TEST(ThinFilm, AbsentFilmsReproduceTheBareInterface) {
    const float lambda = 600, n_f = 1.4f, n3 = 1.7f;
    EXPECT_NEAR(thin_film_response(1, n_f, n3, lambda / (2 * n_f), lambda).reflectance,
                fresnel_dielectric(1, n3), 1e-6f);
    for (float cos_i : {1.f, 0.8f, 0.5f, 0.2f, 0.05f}) {
        EXPECT_NEAR(thin_film_response(cos_i, n_f, n3, 0, lambda).reflectance, fresnel_dielectric(cos_i, n3), 1e-6f);
        const std::complex<float> gold(0.27f, 2.78f);
        EXPECT_NEAR(thin_film_response(cos_i, n_f, gold, 0, lambda).reflectance, fresnel_complex(cos_i, gold), 1e-6f);
    }
}

// Over a lossless base, reflected and transmitted power (each from its own amplitude) add to 1,
// through films thinner and thicker than a wavelength, at any angle, also when the film is
// denser or rarer than the base and beyond its critical angle.
TEST(ThinFilm, LosslessFilmsConserveEnergy) {
    for (float n_f : {1.2f, 1.45f, 2.4f})
        for (float n3 : {1.33f, 1.5f, 1.9f})
            for (float d : {50.f, 137.f, 420.f, 1500.f})
                for (float cos_i : {1.f, 0.7f, 0.3f, 0.02f}) {
                    FilmResponse r = thin_film_response(cos_i, n_f, n3, d, 530);
                    EXPECT_GE(r.reflectance, 0);
                    EXPECT_LE(r.reflectance, 1);
                    EXPECT_NEAR(r.reflectance + r.transmittance, 1, 2e-5f) << n_f << " " << n3 << " " << d << " " << cos_i;
                }
}

// The film's colour: the reflectance oscillates with 1 / lambda, with maxima where the round
// trip 2 n_f d cos theta_f is a whole number of wavelengths plus the phase shifts'. For a soap
// film in air (n3 = 1 below it too, one reflection phase-shifted by pi) at normal incidence the
// maxima lie at 2 n_f d = (m + 1/2) lambda.
TEST(ThinFilm, SoapFilmMaximaWhereTheRoundTripPredicts) {
    const float n_f = 1.33f, d = 500;
    for (int m = 2; m <= 4; ++m) {
        const float peak = 2 * n_f * d / (m + 0.5f);
        const float at_peak = thin_film_response(1, n_f, 1.f, d, peak).reflectance;
        EXPECT_GT(at_peak, thin_film_response(1, n_f, 1.f, d, peak * 1.03f).reflectance);
        EXPECT_GT(at_peak, thin_film_response(1, n_f, 1.f, d, peak / 1.03f).reflectance);
        // And the peak value: 4 R0 / (1 + R0)^2 with R0 the single-surface reflectance.
        const float r0 = fresnel_dielectric(1, n_f);
        EXPECT_NEAR(at_peak, 4 * r0 / ((1 + r0) * (1 + r0)), 1e-5f);
    }
}

// A conductor with a film: the BxDF's reflectance is the film's over the metal, per wavelength,
// on the mirror and on the microfacets; it stays within [0, 1] and is reciprocal.
TEST(ThinFilm, ConductorBxDFWithAFilm) {
    ThinFilm film;
    film.thickness_nm = 300;
    film.eta = SampledSpectrum(1.5f);
    film.lambda[0] = 400, film.lambda[1] = 500, film.lambda[2] = 600, film.lambda[3] = 700;
    const SampledSpectrum eta(0.2f), k(3.f);
    ConductorBxDF mirror(TrowbridgeReitzDistribution(0, 0), eta, k, film);
    Vec3f wo = normalize(Vec3f(0.3f, 0.1f, 0.9f));
    auto s = mirror.sample_f(wo, 0.5f, {0.5f, 0.5f}, TransportMode::Radiance);
    ASSERT_TRUE(s);
    for (int i = 0; i < NumWavelengths; ++i) {
        const float expected = thin_film_response(wo.z, 1.5f, {0.2f, 3.f}, 300, film.lambda[i]).reflectance;
        EXPECT_NEAR(s->f[i] * std::abs(s->wi.z), expected, 1e-5f);
        EXPECT_LE(expected, 1.f);
    }
    // The four wavelengths see different reflectances: the film colours the metal.
    EXPECT_GT(std::abs(s->f[0] - s->f[2]), 1e-3f);
    ConductorBxDF rough(TrowbridgeReitzDistribution(0.3f, 0.3f), eta, k, film);
    Vec3f wi = normalize(Vec3f(-0.5f, 0.2f, 0.7f));
    SampledSpectrum a = rough.f(wo, wi, TransportMode::Radiance), b = rough.f(wi, wo, TransportMode::Radiance);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_NEAR(a[i], b[i], 1e-6f * std::max(1.f, a[i]));
}

// A dielectric with a film: each lane reflects the film's reflectance and transmits the rest
// (in importance transport, without radiance compression, the two add to 1), from outside and
// from inside, where total internal reflection still reflects everything.
TEST(ThinFilm, DielectricBxDFWithAFilm) {
    ThinFilm film;
    film.thickness_nm = 240;
    film.eta = SampledSpectrum(1.38f);
    film.lambda = SampledSpectrum(410, 520, 630, 740);
    const float eta = 1.52f;
    DielectricBxDF glass(SampledSpectrum(eta), TrowbridgeReitzDistribution(0, 0), film);
    EXPECT_FALSE(glass.is_dispersive());
    for (Vec3f wo : {normalize(Vec3f(0.2f, 0, 0.98f)), normalize(Vec3f(0.6f, 0.1f, 0.5f)),
                     normalize(Vec3f(0.3f, 0, -0.9f))}) {
        // uc = 0 picks reflection, uc just below 1 transmission.
        auto r = glass.sample_f(wo, 0, {0.5f, 0.5f}, TransportMode::Importance);
        auto t = glass.sample_f(wo, 0.9999f, {0.5f, 0.5f}, TransportMode::Importance);
        ASSERT_TRUE(r && t);
        ASSERT_EQ(r->flags, BxDFSpecularReflection);
        ASSERT_EQ(t->flags, BxDFSpecularTransmission);
        for (int i = 0; i < NumWavelengths; ++i) {
            const float reflected = r->f[i] * std::abs(r->wi.z), transmitted = t->f[i] * std::abs(t->wi.z);
            EXPECT_NEAR(reflected, film.over_dielectric(wo.z, eta, i), 1e-6f);
            EXPECT_NEAR(reflected + transmitted, 1, 1e-5f) << i;
        }
        EXPECT_GT(std::abs(r->f[0] - r->f[2]), 1e-3f); // coloured
    }
    // Beyond the critical angle inside the glass every lane reflects everything.
    Vec3f grazing_inside = normalize(Vec3f(0.9f, 0, -0.3f));
    for (int i = 0; i < NumWavelengths; ++i)
        EXPECT_NEAR(film.over_dielectric(grazing_inside.z, eta, i), 1, 1e-5f);
    // A film of zero thickness leaves the bare interface.
    ThinFilm none = film;
    none.thickness_nm = 0;
    DielectricBxDF bare(SampledSpectrum(eta), TrowbridgeReitzDistribution(0, 0), none);
    auto r = bare.sample_f(normalize(Vec3f(0.6f, 0.1f, 0.5f)), 0, {0.5f, 0.5f}, TransportMode::Radiance);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->f[0] * r->wi.z, fresnel_dielectric(r->wi.z, eta), 1e-6f);
}

// A soap bubble's wall: a thin dielectric slab that is a coherent film (filmthickness). At any
// angle, Airy's symmetric-film formula R = F sin^2(delta) / (1 + F sin^2(delta)), with
// F = 4 R1 / (1 - R1)^2, R1 the single-surface reflectance for one polarisation and delta the
// half round-trip phase 2 pi n d cos(theta_f) / lambda, averaged over s and p (Born and Wolf
// 7.6.1). Half-wave walls vanish, every wavelength reflects its own share, the rest is
// transmitted straight on, and thickness 0 is the incoherent slab.
TEST(ThinFilm, SoapBubbleWall) {
    const SampledSpectrum lambda(420, 510, 600, 690), eta(1.33f);
    const float d = 380;
    const ThinDielectricBxDF wall(eta, d, lambda);
    for (float cos_o : {1.f, 0.8f, 0.4f, 0.1f}) {
        const SampledSpectrum r = wall.reflectance(cos_o);
        const float sin_o2 = 1 - cos_o * cos_o, cos_f = std::sqrt(1 - sin_o2 / (1.33f * 1.33f));
        for (int i = 0; i < NumWavelengths; ++i) {
            // Single-surface amplitude reflectances, s and p (Fresnel).
            const float rs = (cos_o - 1.33f * cos_f) / (cos_o + 1.33f * cos_f);
            const float rp = (1.33f * cos_o - cos_f) / (1.33f * cos_o + cos_f);
            const float delta = 2 * Pi * 1.33f * d * cos_f / lambda[i];
            auto airy = [&](float r1) {
                const float f = 4 * r1 * r1 / ((1 - r1 * r1) * (1 - r1 * r1));
                return f * std::sin(delta) * std::sin(delta) / (1 + f * std::sin(delta) * std::sin(delta));
            };
            EXPECT_NEAR(r[i], (airy(rs) + airy(rp)) / 2, 2e-5f) << "cos " << cos_o << " lambda " << lambda[i];
        }
    }
    // Half-wave at normal incidence: 2 n d = lambda.
    const ThinDielectricBxDF half_wave(eta, 510 / (2 * 1.33f), lambda);
    EXPECT_NEAR(half_wave.reflectance(1)[1], 0, 1e-6f);
    // Sampling: reflection or straight through, R' and T' = 1 - R' per lane, in both modes.
    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance})
        for (float uc : {0.01f, 0.99f}) {
            const Vec3f wo = normalize(Vec3f(0.3f, 0.2f, 0.7f));
            const auto s = wall.sample_f(wo, uc, {}, mode);
            ASSERT_TRUE(s);
            const SampledSpectrum expected =
                s->is_reflection() ? wall.reflectance(wo.z) : SampledSpectrum(1) - wall.reflectance(wo.z);
            for (int i = 0; i < NumWavelengths; ++i) EXPECT_NEAR(s->f[i] * wo.z, expected[i], 1e-6f);
            EXPECT_EQ(s->wi, s->is_reflection() ? Vec3f(-wo.x, -wo.y, wo.z) : -wo);
        }
    // No film: pbrt-v4's incoherent sum R + T^2 R / (1 - R^2).
    const float r1 = fresnel_dielectric(1, 1.33f);
    EXPECT_NEAR(ThinDielectricBxDF(eta).reflectance(1)[0], r1 + (1 - r1) * (1 - r1) * r1 / (1 - r1 * r1), 1e-6f);
}

} // namespace
} // namespace caustica
