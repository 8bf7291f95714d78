// Diffuse area lights on a disk against closed forms.
#include "lights/diffuse_area_light.h"

#include "core/rng.h"
#include "params/constant_textures.h"
#include "test_disk.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

using testing::TestDisk;

SampledWavelengths some_wavelengths() { return SampledWavelengths::sample_visible(0.61f); }

// Irradiance at distance h on the axis of a Lambertian disk of radius R, facing it:
// E = pi L sin^2(theta) with sin^2(theta) = R^2 / (R^2 + h^2) (the disk's form factor).
double on_axis_irradiance(double L, double R, double h) { return Pi * L * R * R / (R * R + h * h); }

// MC estimate of irradiance at ctx from sample_li, checking pdf_li against each sample's pdf.
double estimate_irradiance(const Light &light, const LightSampleContext &ctx, int n,
                           uint64_t seed) {
    SampledWavelengths lambda = some_wavelengths();
    Rng rng(seed, 3);
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        auto s = light.sample_li(ctx, rng.uniform2(), lambda);
        if (!s) continue;
        float pdf = light.pdf_li(ctx, s->wi);
        EXPECT_NEAR(pdf, s->pdf, 2e-3f * s->pdf);
        sum += s->L[0] * std::max(0.f, dot(s->wi, ctx.n)) / s->pdf;
    }
    return sum / n;
}

// Area sampling of a disk seen from its axis: the estimate L A h^2 / d^4 has a relative standard
// deviation of 0.72 per sample at h = 1 (the worst case here; d^2 - h^2 is uniform on [0, R^2]),
// so 0.16% at N = 2e5: the 1.5% bound is over 9 sigma.
TEST(DiffuseAreaLight, OnAxisIrradianceMatchesFormFactor) {
    auto disk = std::make_shared<TestDisk>(Vec3f(0, 0, 2), Vec3f(0, 0, -1), 1.5f);
    DiffuseAreaLight light(disk, std::make_shared<ConstantSpectrum>(2.f), 1.5f, false);
    for (float h : {1.0f, 3.0f}) {
        LightSampleContext ctx{{0, 0, 2 - h}, {0, 0, 1}, {0, 0, 1}};
        double E = estimate_irradiance(light, ctx, 200000, uint64_t(h * 10));
        double expected = on_axis_irradiance(3.0, 1.5, h);
        EXPECT_NEAR(E, expected, 0.015 * expected) << "h = " << h;
    }
}

// Alpha 0 on the half x < 0 of the disk: that half is not there.
class HalfDiskCut final : public FloatTexture {
  public:
    float evaluate(const TextureEvalContext &ctx) const override { return ctx.p.x < 0 ? 0.f : 1.f; }
};

// A disk light with half of it cut away gives half the full disk's on-axis irradiance (by
// symmetry), and neither light sampling nor emitted rays start on the cut half. Tolerance as in
// OnAxisIrradianceMatchesFormFactor (the estimator's variance at most doubles).
TEST(DiffuseAreaLight, AlphaCutOutEmitsOnlyWhereTheShapeIs) {
    auto disk = std::make_shared<TestDisk>(Vec3f(0, 0, 2), Vec3f(0, 0, -1), 1.5f);
    DiffuseAreaLight light(disk, std::make_shared<ConstantSpectrum>(2.f), 1.5f, false,
                           make_alpha_mask(std::make_shared<HalfDiskCut>()));
    const LightSampleContext ctx{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    const double E = estimate_irradiance(light, ctx, 200000, 11);
    const double expected = 0.5 * on_axis_irradiance(3.0, 1.5, 1.0);
    EXPECT_NEAR(E, expected, 0.015 * expected);
    Rng rng(4, 4);
    int started = 0;
    for (int i = 0; i < 4000; ++i) {
        auto s = light.sample_le(rng.uniform2(), rng.uniform2(), some_wavelengths());
        if (!s) continue;
        ++started;
        EXPECT_GE(s->ray.o.x, -1e-4f);
    }
    EXPECT_NEAR(started / 4000.0, 0.5, 0.04); // 5 binomial standard deviations
}

// A shape whose alpha is the constant 0 is pbrt-v4's invisible lamp: a delta-position light
// (no ray meets it) that emits as if it had no alpha; any other alpha keeps it an area light.
TEST(DiffuseAreaLight, ConstantZeroAlphaIsAnInvisibleLamp) {
    auto disk = std::make_shared<TestDisk>(Vec3f(0, 0, 2), Vec3f(0, 0, -1), 1.5f);
    auto L = std::make_shared<ConstantSpectrum>(2.f);
    DiffuseAreaLight lamp(disk, L, 1.5f, false, make_alpha_mask(std::make_shared<ConstantFloatTexture>(0.f)));
    EXPECT_EQ(lamp.type(), LightType::DeltaPosition);
    const LightSampleContext ctx{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    const double E = estimate_irradiance(lamp, ctx, 200000, 12);
    EXPECT_NEAR(E, on_axis_irradiance(3.0, 1.5, 1.0), 0.015 * on_axis_irradiance(3.0, 1.5, 1.0));
    Rng rng(5, 5);
    for (int i = 0; i < 100; ++i) EXPECT_TRUE(lamp.sample_le(rng.uniform2(), rng.uniform2(), some_wavelengths()));

    DiffuseAreaLight half(disk, L, 1.5f, false, make_alpha_mask(std::make_shared<ConstantFloatTexture>(0.5f)));
    EXPECT_EQ(half.type(), LightType::Area);
    DiffuseAreaLight cut(disk, L, 1.5f, false, make_alpha_mask(std::make_shared<HalfDiskCut>()));
    EXPECT_EQ(cut.type(), LightType::Area);
}

TEST(DiffuseAreaLight, OneSidedEmitsOnlyOnTheNormalSide) {
    auto disk = std::make_shared<TestDisk>(Vec3f(0, 0, 0), Vec3f(0, 0, 1), 1.f);
    SampledWavelengths lambda = some_wavelengths();
    auto L = std::make_shared<ConstantSpectrum>(1.f);
    DiffuseAreaLight one(disk, L, 1.f, false), two(disk, L, 1.f, true);

    EXPECT_FLOAT_EQ(one.L({0, 0, 0}, {0, 0, 1}, {}, {0, 0.6f, 0.8f}, lambda)[0], 1.f);
    EXPECT_TRUE(one.L({0, 0, 0}, {0, 0, 1}, {}, {0, 0.6f, -0.8f}, lambda).is_black());
    EXPECT_FLOAT_EQ(two.L({0, 0, 0}, {0, 0, 1}, {}, {0, 0.6f, -0.8f}, lambda)[0], 1.f);

    // Below the disk, looking up at it: nothing from the one-sided light, and the two-sided one
    // gives the on-axis form factor.
    LightSampleContext below{{0, 0, -1}, {0, 0, 1}, {0, 0, 1}};
    Rng rng(1, 1);
    for (int i = 0; i < 100; ++i) EXPECT_FALSE(one.sample_li(below, rng.uniform2(), lambda));
    double E = estimate_irradiance(two, below, 200000, 8);
    EXPECT_NEAR(E, on_axis_irradiance(1, 1, 1), 0.015 * on_axis_irradiance(1, 1, 1));
}

// Power: the exitance pi L over the area, per emitting side. Every cosine-sampled emitted ray
// carries exactly L cos / (pdf_pos pdf_dir) = pi A L, so the estimate must match phi to float
// precision; two-sided lights must send half their rays to each side.
TEST(DiffuseAreaLight, EmittedRaysCarryItsPower) {
    auto disk = std::make_shared<TestDisk>(Vec3f(1, 0, 0), normalize(Vec3f(1, 1, 0)), 0.5f);
    SampledWavelengths lambda = some_wavelengths();
    auto L = std::make_shared<ConstantSpectrum>(4.f);
    for (bool two_sided : {false, true}) {
        DiffuseAreaLight light(disk, L, 0.5f, two_sided);
        double expected = Pi * (two_sided ? 2 : 1) * disk->area() * 2.0;
        EXPECT_NEAR(light.phi(lambda)[0], expected, 1e-5 * expected);
        Rng rng(two_sided, 5);
        const int n = 100000;
        double power = 0;
        int front = 0;
        for (int i = 0; i < n; ++i) {
            auto s = light.sample_le(rng.uniform2(), rng.uniform2(), lambda);
            ASSERT_TRUE(s);
            float pos, dir;
            light.pdf_le(s->ray, s->n, &pos, &dir);
            ASSERT_NEAR(pos, s->pdf_pos, 1e-5f * pos);
            ASSERT_NEAR(dir, s->pdf_dir, 1e-3f * dir);
            float cos_t = dot(s->n, s->ray.d);
            front += cos_t > 0;
            power += s->L[0] * std::abs(cos_t) / (s->pdf_pos * s->pdf_dir);
        }
        EXPECT_NEAR(power / n, expected, 1e-3 * expected);
        // Binomial(n, 1/2): standard deviation 158; 5 sigma.
        if (two_sided)
            EXPECT_NEAR(front, n / 2, 800);
        else
            EXPECT_EQ(front, n);
    }
}

}  // namespace
}  // namespace caustica
