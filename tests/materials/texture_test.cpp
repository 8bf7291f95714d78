#include "param_helpers.h"

#include "core/error.h"
#include "geometry/interaction.h"
#include "params/constant_textures.h"
#include "textures/noise_textures.h"
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

// Perlin noise vanishes on the integer lattice and varies smoothly between; the sums of
// octaves follow from it. (Agreement with pbrt-v4's patterns is the render test
// NoiseTexturesMatchPbrtV4.)
TEST_F(TextureTest, NoiseTextures) {
    for (Vec3f lattice : {Vec3f(0, 0, 0), Vec3f(3, -7, 12), Vec3f(-255, 256, 1000)})
        EXPECT_EQ(perlin_noise(lattice), 0);
    float largest = 0;
    for (int i = 0; i < 1000; ++i) {
        Vec3f p(0.37f * float(i), 0.11f * float(i) - 20, 0.053f * float(i));
        float n = perlin_noise(p);
        largest = std::max(largest, std::abs(n));
        // Continuity: a step of 1e-3 changes it by at most the gradient bound times the step.
        EXPECT_LT(std::abs(perlin_noise(p + Vec3f(1e-3f, 0, 0)) - n), 4e-3f);
    }
    EXPECT_LE(largest, 1.f);
    EXPECT_GT(largest, 0.3f);
    // One octave is the noise itself; turbulence adds 0.2 of the next octave's amplitude.
    Vec3f p(0.3f, 1.7f, -2.2f);
    EXPECT_FLOAT_EQ(fractional_brownian_motion(p, 0.5f, 1), perlin_noise(p));
    EXPECT_FLOAT_EQ(turbulence(p, 0.5f, 1), std::abs(perlin_noise(p)) + 0.5f * 0.2f);
    EXPECT_FLOAT_EQ(fractional_brownian_motion(p, 0.5f, 2),
                    perlin_noise(p) + 0.5f * perlin_noise(1.99f * p));
    // The texture types read "roughness" (omega) and "octaves" as pbrt-v4 does.
    std::vector<ParsedParameter> two = {numbers("float", "roughness", {0.25}, 2),
                                        numbers("integer", "octaves", {2}, 3)};
    EXPECT_FLOAT_EQ(eval_float("fbm", two, at_uv(0, 0, p)),
                    fractional_brownian_motion(p, 0.25f, 2));
    EXPECT_FLOAT_EQ(eval_float("wrinkled", two, at_uv(0, 0, p)), turbulence(p, 0.25f, 2));
    EXPECT_FLOAT_EQ(eval_float("windy", {}, at_uv(0, 0, p)),
                    std::abs(fractional_brownian_motion(0.1f * p, 0.5f, 3)) *
                        fractional_brownian_motion(p, 0.5f, 6));
    // The texture's transform: texture space is the CTM's inverse image of render space.
    EXPECT_FLOAT_EQ(eval_float("fbm", {}, at_uv(0, 0, 2.f * p), {}, Transform::scale(2, 2, 2)),
                    fractional_brownian_motion(p, 0.5f, 8));
    EXPECT_THROW(eval_float("fbm", {numbers("integer", "octaves", {-1}, 2)}, at_uv(0, 0)), InputError);
}

// Dots: about half the unit cells hold a dot of radius 0.35. As in pbrt-v4, the dots show
// "outside" and the rest "inside" (its reader swaps the two; noise_textures.h).
TEST_F(TextureTest, DotsAndDirectionMix) {
    int in_dots = 0, cells_with_dots = 0;
    const int n = 200;
    for (int cell = 0; cell < n; ++cell) {
        bool any = false;
        for (int k = 0; k < 100; ++k) {
            Vec2f st(float(cell) + (float(k % 10) + 0.5f) / 10 - 0.5f, (float(k / 10) + 0.5f) / 10 - 0.5f);
            bool inside = inside_polka_dot(st);
            in_dots += inside;
            any = any || inside;
            EXPECT_FLOAT_EQ(eval_float("dots", {}, at_uv(st.x, st.y)), inside ? 0.f : 1.f);
        }
        cells_with_dots += any;
    }
    EXPECT_GT(cells_with_dots, n / 4);
    EXPECT_LT(cells_with_dots, 3 * n / 4);
    // Each dot covers pi 0.35^2 = 0.385 of its cell.
    EXPECT_NEAR(double(in_dots) / (100.0 * cells_with_dots), 0.385, 0.03);

    // directionmix: tex1 where the normal is along "dir", tex2 where it is across.
    std::vector<ParsedParameter> mix = {numbers("vector3", "dir", {0, 0, 1}, 2),
                                        numbers("float", "tex1", {4}, 3), numbers("float", "tex2", {8}, 4)};
    TextureEvalContext facing = at_uv(0, 0), edge_on = at_uv(0, 0), halfway = at_uv(0, 0);
    edge_on.n = {1, 0, 0};
    halfway.n = normalize(Vec3f(1, 0, 1));
    EXPECT_FLOAT_EQ(eval_float("directionmix", mix, facing), 4);
    EXPECT_FLOAT_EQ(eval_float("directionmix", mix, edge_on), 8);
    EXPECT_NEAR(eval_float("directionmix", mix, halfway), 4 * 0.7071f + 8 * (1 - 0.7071f), 1e-4f);
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
