// pbrt-v4's "subsurface" material (subsurface_material.h): its boundary (the dielectric whose
// transmissions become the BSSRDF's entry, subsurface_entry_bxdf.h), its exit lobe (the
// normalised Fresnel lobe, normalized_fresnel_bxdf.h) and the factory's parameters.
#include "param_helpers.h"

#include "core/rng.h"
#include "geometry/interaction.h"
#include "materials/fresnel.h"
#include "materials/material_factory.h"
#include "materials/normalized_fresnel_bxdf.h"
#include "materials/photon_beam_diffusion.h"
#include "materials/subsurface_entry_bxdf.h"
#include "materials/subsurface_material.h"

#include <gtest/gtest.h>

#include <cmath>

namespace caustica {
namespace {

using namespace caustica::testing;

const TransportMode Radiance = TransportMode::Radiance, Importance = TransportMode::Importance;

Vec3f direction(float theta, float phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Behind a smooth boundary, light from outside is reflected with probability F and enters with
// 1 - F, each sample carrying weight 1, in both transport modes (the entry's 1/eta^2 cancels
// against the exit's eta^2, so it is left out of both); entries go straight in and are not part
// of f or pdf. Negative control: keeping the dielectric's 1/eta^2 on radiance entries makes
// their weight 0.44 at eta 1.5.
TEST(SubsurfaceEntryBxDF, SmoothBoundaryEntersWithTheFresnelTransmittance) {
    const SubsurfaceEntryBxDF b(DielectricBxDF(SampledSpectrum(1.5f), TrowbridgeReitzDistribution(0, 0)));
    for (TransportMode mode : {Radiance, Importance})
        for (float theta : {0.f, 0.7f, 1.4f}) {
            const Vec3f wo = direction(theta, 0.3f);
            Rng rng(2, 1);
            int entries = 0;
            const int n = 20000;
            for (int i = 0; i < n; ++i) {
                const std::optional<BSDFSample> s = b.sample_f(wo, rng.uniform(), rng.uniform2(), mode);
                ASSERT_TRUE(s);
                const float weight = s->f[0] * std::abs(s->wi.z) / s->pdf;
                EXPECT_NEAR(weight, 1.f, 1e-5f);
                if (!s->is_transmission()) continue;
                ++entries;
                EXPECT_EQ(s->flags, BxDFDiffuseTransmission);
                EXPECT_EQ(s->wi, Vec3f(0, 0, -1));
                EXPECT_EQ(b.f(wo, s->wi, mode)[0], 0.f);
                EXPECT_EQ(b.pdf(wo, s->wi, mode), 0.f);
            }
            const double transmittance = 1 - fresnel_dielectric(wo.z, 1.5f);
            EXPECT_NEAR(double(entries) / n, transmittance, 4 * std::sqrt(transmittance * (1 - transmittance) / n) + 1e-9);
        }
}

// Behind a rough boundary the entries' mean weight times their probability is the rough
// dielectric's transmittance, the same in both modes: 1 minus its reflected albedo, estimated
// by sampling reflections only. Entries carry no 1/eta^2, so the two estimates must add to 1
// up to the microfacet model's own energy loss (multiple scattering between microfacets is not
// modelled: under 2% at roughness 0.3).
TEST(SubsurfaceEntryBxDF, RoughBoundaryEntersWithItsTransmittance) {
    const SubsurfaceEntryBxDF b(DielectricBxDF(SampledSpectrum(1.5f), TrowbridgeReitzDistribution(0.3f, 0.3f)));
    for (TransportMode mode : {Radiance, Importance}) {
        const Vec3f wo = direction(0.6f, 1.f);
        Rng rng(4, 2);
        double entered = 0, reflected = 0;
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
            const std::optional<BSDFSample> s = b.sample_f(wo, rng.uniform(), rng.uniform2(), mode);
            if (!s) continue;
            const double weight = s->f[0] * std::abs(s->wi.z) / s->pdf;
            (s->is_transmission() ? entered : reflected) += weight / n;
        }
        EXPECT_GT(entered, 0.85);
        EXPECT_NEAR(entered + reflected, 1.0, 0.02) << int(mode);
    }
}

// The exit lobe's cosine-weighted integral is 1 for every eta: d'Eon and Irving's fit of the
// first Fresnel moment normalises it (to 0.3% here, the fit's accuracy). Negative control:
// without the normalisation (c = 1) the albedo is 0.90 at eta 1.33.
TEST(NormalizedFresnelBxDF, ReflectsAllTheEnergyItIsGiven) {
    for (float eta : {1.1f, 1.33f, 1.5f, 2.f}) {
        const NormalizedFresnelBxDF b(eta, fresnel_moment1(1 / eta));
        const Vec3f wo(0, 0, -1);
        double sum = 0;
        const int n = 400;
        for (int i = 0; i < n; ++i) {
            const float cos_theta = (i + 0.5f) / n;
            sum += b.f(wo, direction(std::acos(cos_theta), 0), Radiance)[0] * cos_theta * 2 * Pi / n;
        }
        EXPECT_NEAR(sum, 1.0, 3e-3) << eta;
        Rng rng(7, 1);
        for (int i = 0; i < 100; ++i) {
            const std::optional<BSDFSample> s = b.sample_f(wo, 0, rng.uniform2(), Importance);
            ASSERT_TRUE(s);
            EXPECT_GT(s->wi.z, 0);
            EXPECT_FLOAT_EQ(s->pdf, b.pdf(wo, s->wi, Importance));
            EXPECT_EQ(s->f, b.f(wo, s->wi, Radiance));
        }
    }
}

class SubsurfaceFactoryTest : public ::testing::Test {
  protected:
    MaterialPtr create(std::vector<ParsedParameter> params) {
        return create_material("subsurface", dictionary(std::move(params)), textures_, {"test.pbrt", 1, 1});
    }
    int error_line(std::vector<ParsedParameter> params) {
        try {
            create(std::move(params));
        } catch (const InputError &e) {
            return e.location().line;
        }
        return -1;
    }
    NamedTextures textures_;
};

TEST_F(SubsurfaceFactoryTest, EveryWayOfGivingTheCoefficientsMakesAProfileMaterial) {
    const std::vector<std::vector<ParsedParameter>> ways = {
        {},
        {strings("string", "name", {"Skin1"}, 2), numbers("float", "scale", {10}, 3)},
        {strings("string", "name", {"Regular Milk"}, 2)},
        {numbers("rgb", "sigma_a", {0.1, 0.2, 0.3}, 2), numbers("rgb", "sigma_s", {1, 2, 3}, 3)},
        {numbers("rgb", "reflectance", {0.8, 0.5, 0.3}, 2), numbers("float", "roughness", {0.3}, 3)},
    };
    for (const auto &params : ways) {
        MaterialPtr m = create(params);
        ASSERT_TRUE(m);
        EXPECT_TRUE(m->has_profile_subsurface());
        EXPECT_NE(dynamic_cast<const ProfileSubsurfaceMaterial *>(m.get()), nullptr);
    }
}

TEST_F(SubsurfaceFactoryTest, BadParametersAreErrorsAtThem) {
    EXPECT_EQ(error_line({strings("string", "name", {"Skin3"}, 4)}), 4);
    EXPECT_EQ(error_line({numbers("rgb", "sigma_a", {0.1, 0.2, 0.3}, 5)}), 5);
    EXPECT_EQ(error_line({numbers("rgb", "sigma_s", {0.1, 0.2, 0.3}, 6)}), 6);
    EXPECT_EQ(error_line({numbers("rgb", "sigma_a", {-0.1, 0.2, 0.3}, 7), numbers("rgb", "sigma_s", {1, 1, 1}, 8)}), 7);
    EXPECT_EQ(error_line({numbers("float", "g", {1}, 9)}), 9);
    EXPECT_EQ(error_line({numbers("float", "eta", {0}, 10)}), 10);
    EXPECT_EQ(error_line({numbers("float", "scale", {-1}, 11)}), 11);
    EXPECT_EQ(error_line({numbers("float", "roughness", {-1}, 12)}), 12);
}

} // namespace
} // namespace caustica
