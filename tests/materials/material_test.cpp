#include "param_helpers.h"

#include "core/error.h"
#include "geometry/interaction.h"
#include "materials/conductor_bxdf.h"
#include "materials/fresnel.h"
#include "materials/material_factory.h"
#include "spectral/named_spectra.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

using namespace caustica::testing;

SurfaceInteraction flat_surface() {
    SurfaceInteraction si;
    si.p = {0, 0, 0};
    si.n = {0, 0, 1};
    si.uv = {0.5f, 0.5f};
    si.dpdu = {1, 0, 0};
    si.dpdv = {0, 1, 0};
    si.shading.n = si.n;
    si.shading.dpdu = si.dpdu;
    si.shading.dpdv = si.dpdv;
    return si;
}

class MaterialTest : public ::testing::Test {
  protected:
    void SetUp() override { set_warnings_enabled(false); }
    void TearDown() override { set_warnings_enabled(true); }

    MaterialPtr create(const std::string &type, std::vector<ParsedParameter> params) {
        dict_ = std::make_unique<ParameterDictionary>(dictionary(std::move(params)));
        return create_material(type, *dict_, textures_, directive_location());
    }
    // Line of the InputError that creating the material throws, or -1 if it does not throw.
    int error_line(const std::string &type, std::vector<ParsedParameter> params) {
        return input_error_line([&] { create(type, std::move(params)); });
    }
    // f |cos| / pdf of a sample from the material's BSDF.
    SampledSpectrum weight(const Material &m, Vec3f wo, const SampledWavelengths &lambda,
                           SampleFlags flags = SampleFlags::All, BSDFSample *out = nullptr) {
        BSDF bsdf = m.get_bsdf(flat_surface(), lambda, scratch_);
        auto s = bsdf.sample_f(wo, 0.5f, {0.5f, 0.5f}, TransportMode::Radiance, flags);
        if (!s) return {};
        if (out) *out = *s;
        return s->f * std::abs(s->wi.z) / s->pdf;
    }

    std::unique_ptr<ParameterDictionary> dict_;
    NamedTextures textures_;
    ScratchBuffer scratch_;
    SampledWavelengths lambda_ = SampledWavelengths::sample_visible(0.4f);
};

TEST_F(MaterialTest, DiffuseDefaultsToHalfReflectance) {
    MaterialPtr m = create("diffuse", {});
    BSDF bsdf = m->get_bsdf(flat_surface(), lambda_, scratch_);
    SampledSpectrum f = bsdf.f(normalize(Vec3f(0.3f, 0, 1)), normalize(Vec3f(-0.2f, 0.4f, 1)));
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_NEAR(f[i], 0.5f * InvPi, 1e-6f);
    MaterialPtr grey = create("diffuse", {numbers("spectrum", "reflectance", {0.25}, 2)});
    EXPECT_NEAR(weight(*grey, Vec3f(0, 0, 1), lambda_)[0], 0.25f, 1e-6f);
    EXPECT_FALSE(grey->has_specular_lobe());
    EXPECT_FALSE(grey->is_dispersive());
}

TEST_F(MaterialTest, ConductorDefaultsToSmoothCopper) {
    MaterialPtr m = create("conductor", {});
    EXPECT_TRUE(m->has_specular_lobe());
    Vec3f wo = normalize(Vec3f(0.4f, 0.1f, 0.8f));
    SampledSpectrum w = weight(*m, wo, lambda_);
    SampledSpectrum eta = get_named_spectrum("metal-Cu-eta")->sample(lambda_);
    SampledSpectrum k = get_named_spectrum("metal-Cu-k")->sample(lambda_);
    SampledSpectrum expected = fresnel_conductor(wo.z, eta, k);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_NEAR(w[i], expected[i], 1e-5f);
}

TEST_F(MaterialTest, ConductorReflectanceIsNormalIncidenceReflectance) {
    // eta = 1, k = 2 sqrt(r) / sqrt(1 - r) gives ((eta-1)^2 + k^2) / ((eta+1)^2 + k^2) = r.
    MaterialPtr m = create("conductor", {numbers("spectrum", "reflectance", {0.7}, 2)});
    SampledSpectrum w = weight(*m, Vec3f(0, 0, 1), lambda_);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_NEAR(w[i], 0.7f, 1e-5f);
}

TEST_F(MaterialTest, RoughnessIsRemappedByDefault) {
    Vec3f wo = normalize(Vec3f(0.3f, 0.2f, 0.9f)), wi = normalize(Vec3f(-0.4f, 0.1f, 0.8f));
    SampledSpectrum eta(0.2f), k(3.f);
    for (bool remap : {true, false}) {
        std::vector<ParsedParameter> p = {numbers("float", "roughness", {0.25}, 2),
                                          numbers("spectrum", "eta", {0.2}, 3), numbers("spectrum", "k", {3}, 4)};
        if (!remap) p.push_back(boolean("remaproughness", false, 5));
        MaterialPtr m = create("conductor", p);
        EXPECT_FALSE(m->has_specular_lobe());
        float alpha = remap ? 0.5f : 0.25f;
        ConductorBxDF reference(TrowbridgeReitzDistribution(alpha, alpha), eta, k);
        BSDF bsdf = m->get_bsdf(flat_surface(), lambda_, scratch_);
        EXPECT_NEAR(bsdf.f(wo, wi)[0], reference.f(wo, wi, TransportMode::Radiance)[0], 1e-5f);
    }
    // Anisotropic: uroughness along dpdu (x), vroughness along y.
    MaterialPtr aniso = create("conductor", {numbers("float", "uroughness", {0.01}, 2),
                                             numbers("float", "vroughness", {0.25}, 3),
                                             numbers("spectrum", "eta", {0.2}, 4), numbers("spectrum", "k", {3}, 5)});
    ConductorBxDF reference(TrowbridgeReitzDistribution(0.1f, 0.5f), eta, k);
    BSDF bsdf = aniso->get_bsdf(flat_surface(), lambda_, scratch_);
    EXPECT_NEAR(bsdf.f(wo, wi)[0], reference.f(wo, wi, TransportMode::Radiance)[0], 1e-5f);
}

TEST_F(MaterialTest, DielectricDefaultsAndIor) {
    MaterialPtr m = create("dielectric", {});
    EXPECT_TRUE(m->has_specular_lobe());
    EXPECT_FALSE(m->is_dispersive());
    EXPECT_FALSE(m->has_interior_absorption());
    // Normal incidence reflects ((n - 1) / (n + 1))^2 of the light.
    SampledSpectrum r = weight(*m, Vec3f(0, 0, 1), lambda_, SampleFlags::Reflection);
    EXPECT_NEAR(r[0], sqr(0.5f / 2.5f), 1e-6f);
    MaterialPtr water = create("dielectric", {numbers("float", "eta", {1.33}, 2)});
    EXPECT_NEAR(weight(*water, Vec3f(0, 0, 1), lambda_, SampleFlags::Reflection)[0], sqr(0.33f / 2.33f), 1e-6f);
}

TEST_F(MaterialTest, DielectricDispersionFromNamedGlass) {
    MaterialPtr m = create("dielectric", {strings("spectrum", "eta", {"glass-BK7"}, 2)});
    EXPECT_TRUE(m->is_dispersive());
    BSDFSample s;
    weight(*m, normalize(Vec3f(0.5f, 0, 0.8f)), lambda_, SampleFlags::Transmission, &s);
    EXPECT_TRUE(s.dispersive);
    // The hero wavelength's refraction index: BK7 is about 1.5168 at 587.6 nm (Schott).
    SampledWavelengths d_line = SampledWavelengths::fixed(587.56f);
    SampledSpectrum r = weight(*m, Vec3f(0, 0, 1), d_line, SampleFlags::Reflection);
    EXPECT_NEAR(r[0], sqr(0.5168f / 2.5168f), 2e-5f);
}

TEST_F(MaterialTest, DielectricSellmeierAndCauchy) {
    // Schott's Sellmeier coefficients for N-BK7; n_d = 1.5168 at 587.56 nm.
    MaterialPtr sellmeier = create("dielectric", {numbers("float", "sellmeierB", {1.03961212, 0.231792344, 1.01046945}, 2),
                                                  numbers("float", "sellmeierC", {0.00600069867, 0.0200179144, 103.560653}, 3)});
    EXPECT_TRUE(sellmeier->is_dispersive());
    SampledWavelengths d_line = SampledWavelengths::fixed(587.56f);
    EXPECT_NEAR(weight(*sellmeier, Vec3f(0, 0, 1), d_line, SampleFlags::Reflection)[0], sqr(0.5168f / 2.5168f), 2e-5f);
    // Cauchy: n(500 nm) = A + B / 0.25 um^2 = 1.5 + 0.0042 * 4 = 1.5168.
    MaterialPtr cauchy = create("dielectric", {numbers("float", "cauchyA", {1.5}, 2), numbers("float", "cauchyB", {0.0042}, 3)});
    EXPECT_TRUE(cauchy->is_dispersive());
    EXPECT_NEAR(weight(*cauchy, Vec3f(0, 0, 1), SampledWavelengths::fixed(500), SampleFlags::Reflection)[0],
                sqr(0.5168f / 2.5168f), 2e-5f);
}

TEST_F(MaterialTest, DielectricInteriorAbsorption) {
    MaterialPtr sigma = create("dielectric", {numbers("spectrum", "sigma_a", {2}, 2)});
    EXPECT_TRUE(sigma->has_interior_absorption());
    EXPECT_NEAR(sigma->interior_sigma_a(lambda_)[2], 2, 1e-6f);
    // Burley's parameterisation: sigma_a = -ln(T) / d.
    MaterialPtr at_distance = create("dielectric", {numbers("spectrum", "transmittance", {0.5}, 2),
                                                    numbers("float", "atDistance", {2}, 3)});
    EXPECT_TRUE(at_distance->has_interior_absorption());
    EXPECT_NEAR(at_distance->interior_sigma_a(lambda_)[1], -std::log(0.5f) / 2, 1e-6f);
    // An RGB transmittance goes through the albedo RGB-to-spectrum conversion; grey stays grey.
    MaterialPtr rgb = create("dielectric", {numbers("rgb", "transmittance", {0.5, 0.5, 0.5}, 2)});
    EXPECT_NEAR(rgb->interior_sigma_a(lambda_)[0], -std::log(0.5f), 1e-2f);
}

TEST_F(MaterialTest, ThinDielectricAndInterface) {
    MaterialPtr thin = create("thindielectric", {numbers("float", "eta", {1.5}, 2)});
    ASSERT_TRUE(thin);
    EXPECT_TRUE(thin->has_specular_lobe());
    EXPECT_FALSE(thin->is_dispersive());
    BSDFSample s;
    weight(*thin, normalize(Vec3f(0.2f, 0.3f, 0.9f)), lambda_, SampleFlags::Transmission, &s);
    EXPECT_EQ(s.wi, -normalize(Vec3f(0.2f, 0.3f, 0.9f)));
    EXPECT_EQ(create("interface", {}), nullptr);
}

TEST_F(MaterialTest, UnusedParametersAreNotLookedUp) {
    create("diffuse", {numbers("spectrum", "reflectance", {0.3}, 2), numbers("float", "sheen", {1}, 3)});
    EXPECT_TRUE(dict_->parameters()[0].looked_up);
    EXPECT_FALSE(dict_->parameters()[1].looked_up);
}

TEST_F(MaterialTest, FactoryErrorsPointAtTheParameter) {
    EXPECT_EQ(error_line("plastic", {}), 1);
    EXPECT_EQ(error_line("conductor", {numbers("float", "roughness", {-0.1}, 4)}), 4);
    EXPECT_EQ(error_line("conductor", {numbers("float", "uroughness", {NAN}, 5)}), 5);
    EXPECT_EQ(error_line("dielectric", {numbers("float", "vroughness", {-1}, 6)}), 6);
    EXPECT_EQ(error_line("dielectric", {numbers("float", "eta", {0}, 7)}), 7);
    EXPECT_EQ(error_line("dielectric", {numbers("float", "eta", {-1.5}, 7)}), 7);
    EXPECT_EQ(error_line("dielectric", {numbers("float", "eta", {NAN}, 8)}), 8);
    EXPECT_EQ(error_line("thindielectric", {numbers("float", "eta", {0}, 9)}), 9);
    EXPECT_EQ(error_line("conductor", {numbers("spectrum", "reflectance", {0.5}, 3), numbers("spectrum", "eta", {1}, 4)}), 3);
    EXPECT_EQ(error_line("dielectric", {numbers("float", "sellmeierB", {1, 0.2}, 3),
                                        numbers("float", "sellmeierC", {0.006, 0.02, 100}, 4)}), 3);
    EXPECT_EQ(error_line("dielectric", {numbers("float", "eta", {1.5}, 2), numbers("float", "cauchyA", {1.5}, 5)}), 5);
    EXPECT_EQ(error_line("dielectric", {numbers("spectrum", "sigma_a", {-1}, 6)}), 6);
    EXPECT_EQ(error_line("dielectric", {numbers("spectrum", "transmittance", {0.5}, 2), numbers("float", "atDistance", {0}, 8)}), 8);
    EXPECT_EQ(error_line("dielectric", {numbers("spectrum", "transmittance", {0.5}, 2), numbers("spectrum", "sigma_a", {1}, 9)}), 2);
    EXPECT_EQ(error_line("dielectric", {numbers("float", "eta", {1.5}, 2)}), -1);
}

} // namespace
} // namespace caustica
