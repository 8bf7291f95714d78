// pbrt-v4's "mix": one of two named materials per surface point and direction, the second with
// probability "amount".
#include "param_helpers.h"

#include "core/rng.h"
#include "geometry/interaction.h"
#include "materials/material_factory.h"
#include "materials/mix_material.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

using namespace caustica::testing;

class MixMaterialTest : public ::testing::Test {
  protected:
    void SetUp() override {
        set_warnings_enabled(false);
        named_["red"] = make("diffuse", {numbers("rgb", "reflectance", {0.8, 0.1, 0.1}, 2)});
        named_["metal"] = make("conductor", {});
        named_["tinted glass"] = make("dielectric", {numbers("spectrum", "sigma_a", {1}, 2)});
    }
    void TearDown() override { set_warnings_enabled(true); }

    MaterialPtr make(const std::string &type, std::vector<ParsedParameter> params) {
        dicts_.push_back(std::make_unique<ParameterDictionary>(dictionary(std::move(params))));
        return create_material(type, *dicts_.back(), textures_, directive_location(), &named_);
    }
    int error_line(std::vector<ParsedParameter> params) {
        return input_error_line([&] { make("mix", std::move(params)); });
    }

    std::map<std::string, MaterialPtr> named_;
    std::vector<std::unique_ptr<ParameterDictionary>> dicts_;
    NamedTextures textures_;
};

TEST_F(MixMaterialTest, ChoosesTheSecondWithProbabilityAmount) {
    auto mix = std::dynamic_pointer_cast<const MixMaterial>(
        make("mix", {strings("string", "materials", {"red", "metal"}, 2), numbers("float", "amount", {0.3}, 3)}));
    ASSERT_TRUE(mix);
    EXPECT_TRUE(mix->has_specular_lobe());      // the smooth metal's
    EXPECT_TRUE(mix->has_non_specular_lobe());  // the diffuse one's
    Rng rng(9, 9);
    const int n = 100000;
    int second = 0;
    SurfaceInteraction si;
    for (int i = 0; i < n; ++i) {
        si.p = {rng.uniform(), rng.uniform(), rng.uniform()};
        si.wo = normalize(Vec3f(rng.uniform() - 0.5f, rng.uniform() - 0.5f, 1));
        const Material *chosen = &mix->choose(si);
        EXPECT_EQ(chosen, &mix->choose(si));  // the same at the same point and direction
        second += chosen == named_["metal"].get();
    }
    // Binomial standard error sqrt(0.3 * 0.7 / n) = 0.0014: the bound of 4 of them is 0.0058,
    // and a 3% error (0.009) fails it.
    const double fraction = double(second) / n;
    EXPECT_NEAR(fraction, 0.3, 0.0058);
    // Negative control: a choice 3% off would be outside the bound.
    EXPECT_GT(std::abs(fraction * 1.03 - 0.3), 0.0058);
    // The ends choose one material only.
    auto first_only = std::dynamic_pointer_cast<const MixMaterial>(
        make("mix", {strings("string", "materials", {"red", "metal"}, 2), numbers("float", "amount", {0}, 3)}));
    EXPECT_EQ(&first_only->choose(si), named_["red"].get());
}

TEST_F(MixMaterialTest, Errors) {
    EXPECT_EQ(error_line({strings("string", "materials", {"red"}, 4)}), 4);
    EXPECT_EQ(error_line({strings("string", "materials", {"red", "blue"}, 5)}), 5);
    EXPECT_EQ(error_line({strings("string", "materials", {"red", "tinted glass"}, 6)}), 6);
    EXPECT_EQ(error_line({strings("string", "materials", {"red", "metal"}, 6)}), -1);
}

} // namespace
} // namespace caustica
