// pbrt-v4's "coateddiffuse" and "coatedconductor" from their scene-file parameters: names,
// defaults, what the scene analysis learns of them, and errors at the offending parameter.
#include "param_helpers.h"

#include "geometry/interaction.h"
#include "materials/material_factory.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

using namespace caustica::testing;

SurfaceInteraction flat_surface() {
    SurfaceInteraction si;
    si.n = si.shading.n = {0, 0, 1};
    si.dpdu = si.shading.dpdu = {1, 0, 0};
    si.dpdv = si.shading.dpdv = {0, 1, 0};
    return si;
}

class CoatedMaterialTest : public ::testing::Test {
  protected:
    void SetUp() override { set_warnings_enabled(false); }
    void TearDown() override { set_warnings_enabled(true); }

    MaterialPtr create(const std::string &type, std::vector<ParsedParameter> params) {
        dict_ = std::make_unique<ParameterDictionary>(dictionary(std::move(params)));
        return create_material(type, *dict_, textures_, directive_location());
    }
    // Line and column of the InputError that creating the material throws ({-1, -1} if none).
    std::pair<int, int> error_at(const std::string &type, std::vector<ParsedParameter> params) {
        try {
            create(type, std::move(params));
        } catch (const InputError &e) {
            return {e.location().line, e.location().column};
        }
        return {-1, -1};
    }
    bool all_looked_up() const {
        for (const ParsedParameter &p : dict_->parameters())
            if (!p.looked_up) return false;
        return true;
    }

    std::unique_ptr<ParameterDictionary> dict_;
    NamedTextures textures_;
    ScratchBuffer scratch_;
    SampledWavelengths lambda_ = SampledWavelengths::sample_visible(0.4f);
};

TEST_F(CoatedMaterialTest, CoatedDiffuseReadsPbrtV4Parameters) {
    MaterialPtr m = create("coateddiffuse", {numbers("rgb", "reflectance", {0.07, 0.09, 0.13}, 2),
                                             numbers("float", "roughness", {0.005}, 3), boolean("remaproughness", false, 4),
                                             numbers("float", "thickness", {0.02}, 5), numbers("float", "eta", {1.4}, 6),
                                             numbers("rgb", "albedo", {0.2, 0.2, 0.2}, 7), numbers("float", "g", {0.3}, 8),
                                             numbers("integer", "maxdepth", {5}, 9), numbers("integer", "nsamples", {2}, 10)});
    ASSERT_TRUE(m);
    EXPECT_TRUE(all_looked_up());
    EXPECT_TRUE(m->has_non_specular_lobe());
    EXPECT_TRUE(m->forms_caustics());  // alpha 0.005: a near-specular coat
    EXPECT_FALSE(m->is_dispersive());
    BSDF bsdf = m->get_bsdf(flat_surface(), lambda_, scratch_);
    EXPECT_TRUE(is_diffuse(bsdf.flags()));
    EXPECT_TRUE(is_reflective(bsdf.flags()));
    EXPECT_FALSE(is_transmissive(bsdf.flags()));
}

TEST_F(CoatedMaterialTest, CoatedDiffuseDefaultsToASmoothCoat) {
    MaterialPtr m = create("coateddiffuse", {});
    ASSERT_TRUE(m);
    EXPECT_TRUE(m->has_specular_lobe());
    EXPECT_TRUE(m->has_non_specular_lobe());
    BSDF bsdf = m->get_bsdf(flat_surface(), lambda_, scratch_);
    // Specular coat and diffuse base at once: non-specular for the integrators.
    EXPECT_TRUE(is_specular(bsdf.flags()));
    EXPECT_TRUE(is_non_specular(bsdf.flags()));
    // The coat's mirror reflection at normal incidence: ((1.5 - 1) / (1.5 + 1))^2 = 4%, its
    // sample's weight 1 (f / pdf, the choice by Fresnel reflectance cancelling it).
    auto s = bsdf.sample_f({0, 0, 1}, 0.01f, {0.5f, 0.5f});
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->is_specular());
    EXPECT_NEAR(s->pdf, 0.04f, 1e-4f);
    // A spectral coat index is dispersive.
    MaterialPtr glass = create("coateddiffuse", {strings("spectrum", "eta", {"glass-BK7"}, 2)});
    EXPECT_TRUE(glass->is_dispersive());
}

TEST_F(CoatedMaterialTest, CoatedConductorReadsPbrtV4Parameters) {
    MaterialPtr m = create("coatedconductor",
                           {numbers("float", "interface.roughness", {0.1}, 2), numbers("float", "interface.eta", {1.3}, 3),
                            strings("spectrum", "conductor.eta", {"metal-Au-eta"}, 4),
                            strings("spectrum", "conductor.k", {"metal-Au-k"}, 5),
                            numbers("float", "conductor.uroughness", {0.2}, 6), numbers("float", "conductor.vroughness", {0.3}, 7),
                            numbers("float", "thickness", {0.05}, 8)});
    ASSERT_TRUE(m);
    EXPECT_TRUE(all_looked_up());
    EXPECT_FALSE(m->has_specular_lobe());
    EXPECT_TRUE(m->has_non_specular_lobe());
    // Defaults: smooth copper under a smooth coat, both delta lobes, nothing non-specular.
    MaterialPtr copper = create("coatedconductor", {});
    EXPECT_TRUE(copper->has_specular_lobe());
    EXPECT_FALSE(copper->has_non_specular_lobe());
    EXPECT_FALSE(is_non_specular(copper->get_bsdf(flat_surface(), lambda_, scratch_).flags()));
    // A scattering slab gives even a smooth coated metal a diffuse lobe.
    MaterialPtr milky = create("coatedconductor", {numbers("rgb", "albedo", {0.5, 0.5, 0.5}, 2)});
    EXPECT_TRUE(milky->has_non_specular_lobe());
    // An artist's reflectance instead of eta and k.
    MaterialPtr r = create("coatedconductor", {numbers("rgb", "reflectance", {0.9, 0.6, 0.3}, 2),
                                               numbers("float", "conductor.roughness", {0.3}, 3)});
    ASSERT_TRUE(r);
    EXPECT_TRUE(all_looked_up());
}

TEST_F(CoatedMaterialTest, BadParametersAreReportedWhereTheyAre) {
    using At = std::pair<int, int>;
    EXPECT_EQ(error_at("coateddiffuse", {numbers("float", "thickness", {-0.01}, 4)}), At(4, 5));
    EXPECT_EQ(error_at("coateddiffuse", {numbers("integer", "maxdepth", {0}, 5)}), At(5, 5));
    EXPECT_EQ(error_at("coateddiffuse", {numbers("integer", "nsamples", {-1}, 6)}), At(6, 5));
    EXPECT_EQ(error_at("coateddiffuse", {numbers("float", "g", {1}, 7)}), At(7, 5));
    EXPECT_EQ(error_at("coateddiffuse", {numbers("float", "eta", {0}, 8)}), At(8, 5));
    EXPECT_EQ(error_at("coateddiffuse", {numbers("float", "roughness", {-0.1}, 9)}), At(9, 5));
    EXPECT_EQ(error_at("coateddiffuse", {numbers("rgb", "albedo", {-1, 0, 0}, 3)}).first, 3);
    EXPECT_EQ(error_at("coatedconductor", {numbers("float", "interface.eta", {-1.5}, 3)}), At(3, 5));
    EXPECT_EQ(error_at("coatedconductor", {numbers("float", "conductor.roughness", {-1}, 4)}), At(4, 5));
    EXPECT_EQ(error_at("coatedconductor", {numbers("float", "interface.uroughness", {NAN}, 5)}), At(5, 5));
    EXPECT_EQ(error_at("coatedconductor", {numbers("spectrum", "reflectance", {0.5}, 2),
                                           numbers("spectrum", "conductor.eta", {1}, 6)}), At(2, 5));
    // Negative control: good values throw nothing.
    EXPECT_EQ(error_at("coateddiffuse", {numbers("float", "thickness", {0}, 4), numbers("integer", "maxdepth", {1}, 5)}),
              At(-1, -1));
}

} // namespace
} // namespace caustica
