#include "param_helpers.h"

#include "core/error.h"
#include "geometry/interaction.h"
#include "params/constant_textures.h"
#include "textures/texture_factory.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

using namespace caustica::testing;

TextureEvalContext at_uv(float u, float v, Vec3f p = {}) {
    TextureEvalContext ctx;
    ctx.uv = {u, v};
    ctx.p = p;
    ctx.n = {0, 0, 1};
    return ctx;
}

float eval_float(const std::string &type, std::vector<ParsedParameter> params, const TextureEvalContext &ctx,
                 const NamedTextures &textures = {}, const Transform &render_from_texture = {}) {
    ParameterDictionary d = dictionary(std::move(params));
    return create_float_texture(type, render_from_texture, d, textures, directive_location())->evaluate(ctx);
}

class TextureTest : public ::testing::Test {
  protected:
    void SetUp() override { set_warnings_enabled(false); }
    void TearDown() override { set_warnings_enabled(true); }
};

TEST_F(TextureTest, EvalContextFromSurfaceInteraction) {
    SurfaceInteraction si;
    si.p = {1, 2, 3};
    si.n = {0, 0, 1};
    si.uv = {0.25f, 0.75f};
    si.shading.n = normalize(Vec3f(0, 0.6f, 0.8f));
    TextureEvalContext ctx(si);
    EXPECT_EQ(ctx.p, si.p);
    EXPECT_EQ(ctx.n, si.shading.n);
    EXPECT_EQ(ctx.uv.x, 0.25f);
    EXPECT_EQ(ctx.uv.y, 0.75f);
}

TEST_F(TextureTest, ConstantScaleMix) {
    EXPECT_FLOAT_EQ(eval_float("constant", {numbers("float", "value", {0.3}, 2)}, at_uv(0, 0)), 0.3f);
    EXPECT_FLOAT_EQ(eval_float("constant", {}, at_uv(0, 0)), 1);
    EXPECT_FLOAT_EQ(eval_float("scale", {numbers("float", "tex", {2}, 2), numbers("float", "scale", {0.25}, 3)},
                               at_uv(0, 0)), 0.5f);
    // mix: (1 - amount) tex1 + amount tex2, defaults tex1 = 0, tex2 = 1.
    EXPECT_FLOAT_EQ(eval_float("mix", {numbers("float", "amount", {0.25}, 2)}, at_uv(0, 0)), 0.25f);
    NamedTextures named;
    named.float_textures["four"] = std::make_shared<ConstantFloatTexture>(4.f);
    EXPECT_FLOAT_EQ(eval_float("mix", {strings("texture", "tex1", {"four"}, 2), numbers("float", "tex2", {8}, 3),
                                       numbers("float", "amount", {0.5}, 4)},
                               at_uv(0, 0), named),
                    6);
}

TEST_F(TextureTest, Checkerboard2D) {
    std::vector<ParsedParameter> p = {numbers("float", "uscale", {2}, 2), numbers("float", "vscale", {2}, 3)};
    // Cells with an even sum of integer coordinates show tex1 (default 1), the others tex2 (0).
    EXPECT_EQ(eval_float("checkerboard", p, at_uv(0.1f, 0.1f)), 1);
    EXPECT_EQ(eval_float("checkerboard", p, at_uv(0.6f, 0.1f)), 0);
    EXPECT_EQ(eval_float("checkerboard", p, at_uv(0.6f, 0.6f)), 1);
    // Negative coordinates continue the pattern: s = -0.8 is in cell -1.
    EXPECT_EQ(eval_float("checkerboard", {numbers("float", "udelta", {-0.9}, 2)}, at_uv(0.1f, 0.1f)), 0);
    EXPECT_EQ(eval_float("checkerboard", {numbers("float", "udelta", {-1.9}, 2)}, at_uv(0.1f, 0.1f)), 1);
}

TEST_F(TextureTest, Checkerboard3D) {
    std::vector<ParsedParameter> p = {numbers("integer", "dimension", {3}, 2)};
    EXPECT_EQ(eval_float("checkerboard", p, at_uv(0, 0, {0.5f, 0.5f, 0.5f})), 1);
    EXPECT_EQ(eval_float("checkerboard", p, at_uv(0, 0, {1.5f, 0.5f, 0.5f})), 0);
    EXPECT_EQ(eval_float("checkerboard", p, at_uv(0, 0, {1.5f, -0.5f, 0.5f})), 1);
    // Texture space is twice as large as render space: render x = 1.5 is texture x = 0.75.
    EXPECT_EQ(eval_float("checkerboard", p, at_uv(0, 0, {1.5f, 0.5f, 0.5f}), {}, Transform::scale(2, 2, 2)), 1);
}

TEST_F(TextureTest, BilerpAndMappings) {
    std::vector<ParsedParameter> p = {numbers("float", "v00", {1}, 2), numbers("float", "v10", {2}, 3),
                                      numbers("float", "v01", {3}, 4), numbers("float", "v11", {5}, 5)};
    float s = 0.25f, t = 0.75f;
    float expected = (1 - s) * (1 - t) * 1 + s * (1 - t) * 2 + (1 - s) * t * 3 + s * t * 5;
    EXPECT_FLOAT_EQ(eval_float("bilerp", p, at_uv(s, t)), expected);
    // Planar mapping: s = p.v1 + udelta, t = p.v2 + vdelta.
    std::vector<ParsedParameter> planar = {strings("string", "mapping", {"planar"}, 2),
                                           numbers("vector3", "v1", {0, 1, 0}, 3),
                                           numbers("vector3", "v2", {0, 0, 1}, 4),
                                           numbers("float", "udelta", {0.1}, 5)};
    // With the default corners (v00 = v10 = 0, v01 = v11 = 1) the value is t; with
    // v10 = v11 = 1 and v00 = v01 = 0 it is s.
    EXPECT_FLOAT_EQ(eval_float("bilerp", planar, at_uv(9, 9, {7, 0.15f, 0.5f})), 0.5f);
    planar.push_back(numbers("float", "v10", {1}, 6));
    planar.push_back(numbers("float", "v01", {0}, 7));
    EXPECT_FLOAT_EQ(eval_float("bilerp", planar, at_uv(9, 9, {7, 0.15f, 0.5f})), 0.25f);
    // Spherical mapping: s = theta / pi, 0 at the +z pole, 1 at the -z pole, 1/2 on the equator.
    std::vector<ParsedParameter> spherical = {strings("string", "mapping", {"spherical"}, 2),
                                              numbers("float", "v10", {1}, 3), numbers("float", "v01", {0}, 4)};
    EXPECT_NEAR(eval_float("bilerp", spherical, at_uv(0, 0, {0, 0, 2})), 0, 1e-6f);
    EXPECT_NEAR(eval_float("bilerp", spherical, at_uv(0, 0, {0, 0, -2})), 1, 1e-6f);
    EXPECT_NEAR(eval_float("bilerp", spherical, at_uv(0, 0, {0, 3, 0})), 0.5f, 1e-6f);
    // Cylindrical: t = z, s = (pi + atan2(y, x)) / (2 pi) = 0.5 on the +x axis.
    std::vector<ParsedParameter> cylindrical = {strings("string", "mapping", {"cylindrical"}, 2),
                                                numbers("float", "v01", {1}, 3), numbers("float", "v11", {1}, 4)};
    EXPECT_NEAR(eval_float("bilerp", cylindrical, at_uv(0, 0, {1, 0, 0.3f})), 0.3f, 1e-6f);
}

TEST_F(TextureTest, SpectrumTextures) {
    SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f);
    NamedTextures named;
    ParameterDictionary d = dictionary({numbers("float", "amount", {0.5}, 2), numbers("spectrum", "tex1", {0.2}, 3),
                                        numbers("spectrum", "tex2", {0.6}, 4)});
    SpectrumTexturePtr mix = create_spectrum_texture("mix", {}, d, SpectrumType::Albedo, named, directive_location());
    SampledSpectrum v = mix->evaluate(at_uv(0, 0), lambda);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_NEAR(v[i], 0.4f, 1e-6f);
    EXPECT_TRUE(mix->is_wavelength_independent());
    ParameterDictionary c = dictionary({strings("string", "mapping", {"uv"}, 2)});
    SpectrumTexturePtr checker =
        create_spectrum_texture("checkerboard", {}, c, SpectrumType::Albedo, named, directive_location());
    EXPECT_EQ(checker->evaluate(at_uv(0.5f, 0.5f), lambda)[0], 1);
    EXPECT_EQ(checker->evaluate(at_uv(1.5f, 0.5f), lambda)[0], 0);
}

TEST_F(TextureTest, UnsupportedTypesFallBackToHalf) {
    EXPECT_FLOAT_EQ(eval_float("fbm", {}, at_uv(0.3f, 0.3f)), 0.5f);
}

TEST_F(TextureTest, Errors) {
    try {
        eval_float("wood", {}, at_uv(0, 0));
        FAIL() << "unknown texture type accepted";
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 1);
        EXPECT_NE(e.message().find("wood"), std::string::npos);
    }
    try {
        eval_float("checkerboard", {numbers("integer", "dimension", {4}, 7)}, at_uv(0, 0));
        FAIL() << "dimension 4 accepted";
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 7);
    }
    try {
        eval_float("bilerp", {strings("string", "mapping", {"cubic"}, 6)}, at_uv(0, 0));
        FAIL() << "unknown mapping accepted";
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 6);
    }
}

} // namespace
} // namespace caustica
