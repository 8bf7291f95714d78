#include "materials/fresnel.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

TEST(Fresnel, DielectricNormalIncidenceMatchesClosedForm) {
    // At normal incidence both polarisations give ((n - 1) / (n + 1))^2 (Born and Wolf 1.5.3).
    for (float n : {1.0001f, 1.33f, 1.5f, 2.4f, 1 / 1.5f}) {
        float expected = sqr((n - 1) / (n + 1));
        EXPECT_NEAR(fresnel_dielectric(1, n), expected, 1e-6f) << n;
        // From the other side the same interface reflects the same fraction.
        EXPECT_NEAR(fresnel_dielectric(-1, n), expected, 1e-6f) << n;
        EXPECT_NEAR(fresnel_dielectric(-1, 1 / n), expected, 1e-6f) << n;
    }
    EXPECT_EQ(fresnel_dielectric(0.7f, 1), 0);
}

TEST(Fresnel, TotalInternalReflectionBeyondCriticalAngle) {
    float eta = 1.5f;
    float critical = std::asin(1 / eta);
    for (float offset : {1e-3f, 0.05f, 0.3f}) {
        // Light inside the glass (cos_i < 0) beyond the critical angle is totally reflected.
        EXPECT_EQ(fresnel_dielectric(-std::cos(critical + offset), eta), 1);
        // Just inside the critical angle some light escapes.
        EXPECT_LT(fresnel_dielectric(-std::cos(critical - offset), eta), 1);
    }
    // Seen from the outside with eta < 1, the same situation.
    EXPECT_EQ(fresnel_dielectric(std::cos(critical + 0.01f), 1 / eta), 1);
}

TEST(Fresnel, DielectricIsSymmetricAcrossTheInterface) {
    // Stokes relations: light refracted from angle theta_i to theta_t reflects the same fraction
    // as light arriving at theta_t from the other side.
    for (float eta : {1.33f, 1.5f, 2.4f})
        for (float cos_i = 0.05f; cos_i <= 1; cos_i += 0.05f) {
            float sin_t = std::sqrt(1 - sqr(cos_i)) / eta;
            float cos_t = std::sqrt(1 - sqr(sin_t));
            EXPECT_NEAR(fresnel_dielectric(cos_i, eta), fresnel_dielectric(-cos_t, eta), 2e-5f);
        }
}

TEST(Fresnel, DielectricGrazingIncidenceReflectsEverything) {
    EXPECT_NEAR(fresnel_dielectric(0, 1.5f), 1, 1e-6f);
    EXPECT_NEAR(fresnel_dielectric(1e-7f, 1.5f), 1, 1e-5f);
}

TEST(Fresnel, DielectricBrewsterAngleZeroesParallelPolarisation) {
    // At Brewster's angle tan(theta_B) = n the p-polarised reflectance vanishes, leaving half of
    // the s-polarised one: R_s = ((cos_i - n cos_t) / (cos_i + n cos_t))^2 with theta_t = 90 - theta_B.
    float n = 1.5f;
    float theta_b = std::atan(n);
    float cos_i = std::cos(theta_b), cos_t = std::sin(theta_b);
    float r_s = sqr((cos_i - n * cos_t) / (cos_i + n * cos_t));
    EXPECT_NEAR(fresnel_dielectric(cos_i, n), r_s / 2, 1e-6f);
}

TEST(Fresnel, ConductorMatchesClosedFormsAndDielectric) {
    // Normal incidence: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2).
    SampledSpectrum eta(0.2f, 0.5f, 1.1f, 2.0f), k(3.9f, 2.4f, 0.3f, 0.f);
    SampledSpectrum r = fresnel_conductor(1, eta, k);
    for (int i = 0; i < NumWavelengths; ++i)
        EXPECT_NEAR(r[i], (sqr(eta[i] - 1) + sqr(k[i])) / (sqr(eta[i] + 1) + sqr(k[i])), 1e-6f);
    // With k = 0 the complex formula is the dielectric one.
    for (float c = 0.02f; c <= 1; c += 0.07f)
        EXPECT_NEAR(fresnel_complex(c, {1.5f, 0}), fresnel_dielectric(c, 1.5f), 2e-6f) << c;
    // Grazing incidence reflects everything; values stay in [0, 1].
    EXPECT_NEAR(fresnel_conductor(0, eta, k)[0], 1, 1e-6f);
    for (float c = 0; c <= 1; c += 0.01f) {
        SampledSpectrum v = fresnel_conductor(c, eta, k);
        EXPECT_GE(v.min_value(), 0);
        EXPECT_LE(v.max_value(), 1 + 1e-6f);
    }
}

// The real-arithmetic conductor formula against the complex one in double precision, over
// metals (k > n: the branch that avoids cancellation), dielectrics (k = 0) and in between, to
// within float rounding of values up to 1 (the complex form in float was no closer).
TEST(Fresnel, ConductorAgreesWithComplexArithmeticInDouble) {
    using C = std::complex<double>;
    auto reference = [](double cos_i, C eta) {
        const C cos_t = std::sqrt(C(1) - C(1 - cos_i * cos_i) / (eta * eta));
        const C r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t), r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
        return (std::norm(r_p) + std::norm(r_s)) / 2;
    };
    double worst = 0;
    for (float n : {0.02f, 0.05f, 0.2f, 0.5f, 1.f, 1.5f, 2.5f, 4.f})
        for (float k : {0.f, 1e-3f, 0.1f, 0.5f, 1.f, 2.4f, 3.9f, 8.f})
            for (int i = 0; i <= 200; ++i) {
                const float c = i / 200.f;
                const double expected = reference(c, C(n, k));
                const double got = fresnel_complex(c, {n, k});
                // Grazing light at index 1 is 0 / 0 in the complex form; the real form says 1.
                if (!std::isfinite(expected)) {
                    EXPECT_EQ(got, 1.0) << "n " << n << " k " << k << " cos " << c;
                    continue;
                }
                worst = std::max(worst, std::abs(got - expected));
                ASSERT_NEAR(got, expected, 5e-6) << "n " << n << " k " << k << " cos " << c;
            }
    std::printf("largest difference from the complex formula in double: %.2e\n", worst);
}

TEST(Fresnel, SchlickInterpolatesFromNormalToGrazing) {
    EXPECT_FLOAT_EQ(fresnel_schlick(0.04f, 1), 0.04f);
    EXPECT_FLOAT_EQ(fresnel_schlick(0.04f, 0), 1);
    float previous = 0;
    for (float c = 1; c >= 0; c -= 0.05f) {
        float v = fresnel_schlick(0.04f, c);
        EXPECT_GE(v, previous);
        previous = v;
    }
    SampledSpectrum f0(0.1f, 0.5f, 0.9f, 1);
    SampledSpectrum s = fresnel_schlick(f0, 0.3f);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_FLOAT_EQ(s[i], fresnel_schlick(f0[i], 0.3f));
}

} // namespace
} // namespace caustica
