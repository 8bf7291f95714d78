#include "materials/microfacet.h"

#include "materials/conductor_bxdf.h"
#include "materials/dielectric_bxdf.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

// Integral over the upper hemisphere of g(w) dw by the midpoint rule in (s, phi), with
// cos(theta) = 1 - (1 - s)^4 so that nodes cluster at the pole where lobes of small alpha live.
template <typename F> double integrate_hemisphere(F g, int n = 300) {
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        double s = (i + 0.5) / n;
        double z = 1 - std::pow(1 - s, 4);
        double dz = 4 * std::pow(1 - s, 3) / n;
        double r = std::sqrt(std::max(0.0, 1 - z * z));
        for (int j = 0; j < 2 * n; ++j) {
            double phi = 2 * Pi * (j + 0.5) / (2 * n);
            Vec3f w(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
            sum += g(w) * dz * (2 * Pi / (2 * n));
        }
    }
    return sum;
}

TEST(Microfacet, RoughnessToAlphaIsSquareRoot) {
    EXPECT_FLOAT_EQ(TrowbridgeReitzDistribution::roughness_to_alpha(0.25f), 0.5f);
    EXPECT_FLOAT_EQ(TrowbridgeReitzDistribution::roughness_to_alpha(0), 0);
    EXPECT_TRUE(TrowbridgeReitzDistribution(9e-4f, 9e-4f).effectively_smooth());
    EXPECT_FALSE(TrowbridgeReitzDistribution(1e-3f, 1e-3f).effectively_smooth());
    EXPECT_FALSE(TrowbridgeReitzDistribution(1e-4f, 0.3f).effectively_smooth());
    // Rough along one axis only: the smooth axis is floored so D and Lambda stay finite.
    TrowbridgeReitzDistribution one_axis(0, 0.3f);
    EXPECT_TRUE(std::isfinite(one_axis.D(normalize(Vec3f(1e-5f, 0.2f, 1)))));
    EXPECT_TRUE(std::isfinite(one_axis.Lambda(normalize(Vec3f(0.5f, 0.2f, 1)))));
    EXPECT_TRUE(is_finite(one_axis.sample_wm(normalize(Vec3f(0.5f, 0.2f, 1)), {0.3f, 0.6f})));
}

TEST(Microfacet, ProjectedNormalAreaIsOne) {
    // The microsurface projects onto the macro surface: integral of D(wm) cos(wm) = 1.
    for (auto [ax, ay] : {std::pair{0.05f, 0.05f}, {0.3f, 0.3f}, {1.f, 1.f}, {0.1f, 0.7f}}) {
        TrowbridgeReitzDistribution d(ax, ay);
        double integral = integrate_hemisphere([&](Vec3f m) { return d.D(m) * m.z; });
        EXPECT_NEAR(integral, 1, 2e-3) << ax << " " << ay;
    }
}

TEST(Microfacet, VisibleNormalsIntegrateToOne) {
    // Integral of G1(w) max(0, w.m) D(m) dm = cos(w) is the relation that defines Smith's Lambda
    // (Heitz 2014, eq. 17), so this checks the closed-form Lambda against D independently.
    for (auto [ax, ay] : {std::pair{0.05f, 0.05f}, {0.3f, 0.3f}, {1.f, 1.f}, {0.1f, 0.7f}})
        for (float theta : {0.f, 30.f, 70.f, 88.f, 120.f}) {
            TrowbridgeReitzDistribution d(ax, ay);
            float t = radians(theta);
            Vec3f w(std::sin(t) * 0.6f, std::sin(t) * 0.8f, std::cos(t));
            double integral = integrate_hemisphere([&](Vec3f m) { return d.D(w, m); });
            EXPECT_NEAR(integral, 1, 3e-3) << ax << " " << ay << " " << theta;
        }
}

TEST(Microfacet, HeightCorrelatedMaskingLiesBetweenBounds) {
    // Heitz 2014, section 6: the height-correlated G lies between the uncorrelated product
    // G1(wo) G1(wi) and min(G1(wo), G1(wi)).
    TrowbridgeReitzDistribution d(0.4f, 0.2f);
    for (float a : {0.1f, 0.8f, 1.3f, 1.55f})
        for (float b : {0.2f, 1.f, 1.5f}) {
            Vec3f wo(std::sin(a), 0, std::cos(a)), wi(0, std::sin(b), std::cos(b));
            float g = d.G(wo, wi);
            EXPECT_GE(g, d.G1(wo) * d.G1(wi) - 1e-6f);
            EXPECT_LE(g, std::min(d.G1(wo), d.G1(wi)) + 1e-6f);
        }
    // No masking at normal incidence, full masking at the horizon.
    EXPECT_FLOAT_EQ(d.G1(Vec3f(0, 0, 1)), 1);
    EXPECT_EQ(d.G1(Vec3f(1, 0, 0)), 0);
}

TEST(Microfacet, SampledNormalsFaceTheViewer) {
    TrowbridgeReitzDistribution d(0.6f, 0.2f);
    Vec3f w = normalize(Vec3f(0.7f, -0.2f, -0.3f));  // from below: normals face -w
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            Vec3f m = d.sample_wm(w, Vec2f((i + 0.5f) / 64, (j + 0.5f) / 64));
            EXPECT_GT(m.z, 0);
            EXPECT_GE(dot(-w, m), -1e-6f);
            EXPECT_NEAR(length(m), 1, 1e-5f);
        }
}

// pbrt-v4's TrowbridgeReitzDistribution::Regularize: alphas below 0.3 are doubled into [0.1, 0.3].
TEST(Microfacet, RegularizedWidensNarrowLobesAsPbrtV4Does) {
    auto expect_alphas = [](TrowbridgeReitzDistribution d, float ax, float ay) {
        EXPECT_FLOAT_EQ(d.alpha_x(), ax);
        EXPECT_FLOAT_EQ(d.alpha_y(), ay);
    };
    expect_alphas(TrowbridgeReitzDistribution(0, 0).regularized(), 0.1f, 0.1f);
    expect_alphas(TrowbridgeReitzDistribution(0.04f, 0.12f).regularized(), 0.1f, 0.24f);
    expect_alphas(TrowbridgeReitzDistribution(0.2f, 0.29f).regularized(), 0.3f, 0.3f);
    expect_alphas(TrowbridgeReitzDistribution(0.3f, 0.8f).regularized(), 0.3f, 0.8f);
}

// A smooth interface and a smooth metal turn glossy when regularised; the BxDFs they came from
// are left as they were (materials may share them).
TEST(Microfacet, RegularizedBxDFsAreGlossyCopies) {
    ScratchBuffer scratch;
    const DielectricBxDF glass(SampledSpectrum(1.5f), TrowbridgeReitzDistribution(0, 0));
    const ConductorBxDF metal(TrowbridgeReitzDistribution(0, 0), SampledSpectrum(0.2f), SampledSpectrum(3.f));
    for (const BxDF *smooth : {static_cast<const BxDF *>(&glass), static_cast<const BxDF *>(&metal)}) {
        ASSERT_TRUE(is_specular(smooth->flags()));
        const BxDF *widened = smooth->regularized(scratch);
        EXPECT_NE(widened, smooth);
        EXPECT_FALSE(is_specular(widened->flags()));
        EXPECT_TRUE(is_specular(smooth->flags()));
        const Vec3f wo = normalize(Vec3f(0.3f, 0.1f, 1)), mirror{-wo.x, -wo.y, wo.z};
        EXPECT_GT(widened->pdf(wo, mirror, TransportMode::Radiance), 0.f);
    }
}

} // namespace
} // namespace caustica
