#include "params/parameters.h"

#include "params/constant_textures.h"
#include "spectral/color_space.h"
#include "spectral/named_spectra.h"
#include "spectral/rgb_spectrum.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace caustica {
namespace {

ParsedParameter numbers(const std::string &type, const std::string &name,
                        std::vector<double> values, int line = 1) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.numbers = std::move(values);
    p.loc = {"scene.pbrt", line, 5};
    return p;
}

ParsedParameter strings(const std::string &type, const std::string &name,
                        std::vector<std::string> values, int line = 1) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.strings = std::move(values);
    p.loc = {"scene.pbrt", line, 5};
    return p;
}

ParsedParameter boolean(const std::string &name, bool value, int line = 1) {
    ParsedParameter p;
    p.type = "bool";
    p.name = name;
    p.bools = {value};
    p.loc = {"scene.pbrt", line, 5};
    return p;
}

const SourceLocation kDirective{"scene.pbrt", 1, 1};

ParameterDictionary dict(std::vector<ParsedParameter> params,
                         const RGBColorSpace *cs = nullptr, std::string base = "") {
    return ParameterDictionary(std::move(params), kDirective, cs, std::move(base));
}

// The location of the InputError that f throws.
template <typename F> SourceLocation error_location(F &&f) {
    try {
        f();
    } catch (const InputError &e) {
        return e.location();
    }
    ADD_FAILURE() << "no InputError thrown";
    return {};
}

TEST(ParameterDictionary, ScalarsArraysAndDefaults) {
    auto d = dict({numbers("float", "radius", {2.5}), numbers("integer", "n", {7}),
                   boolean("flag", true), strings("string", "file", {"a.ply"}),
                   numbers("point3", "from", {1, 2, 3}), numbers("vector3", "dir", {0, 0, 1}),
                   numbers("normal3", "N", {0, 1, 0, 1, 0, 0}), numbers("point2", "uv", {0.5, 0.25}),
                   numbers("integer", "indices", {0, 1, 2, 2, 1, 3}),
                   strings("string", "names", {"x", "y"})});
    EXPECT_FLOAT_EQ(d.get_one_float("radius", 1), 2.5f);
    EXPECT_FLOAT_EQ(d.get_one_float("missing", 1), 1);
    EXPECT_EQ(d.get_one_int("n", 0), 7);
    EXPECT_TRUE(d.get_one_bool("flag", false));
    EXPECT_EQ(d.get_one_string("file", ""), "a.ply");
    EXPECT_EQ(d.get_one_point3("from", {}), Vec3f(1, 2, 3));
    EXPECT_EQ(d.get_one_vector3("dir", {}), Vec3f(0, 0, 1));
    EXPECT_EQ(d.get_one_point2("uv", {}).y, 0.25f);
    auto normals = d.get_normal_array("N");
    ASSERT_EQ(normals.size(), 2u);
    EXPECT_EQ(normals[1], Vec3f(1, 0, 0));
    EXPECT_EQ(d.get_int_array("indices"), (std::vector<int>{0, 1, 2, 2, 1, 3}));
    EXPECT_EQ(d.get_string_array("names"), (std::vector<std::string>{"x", "y"}));
    EXPECT_TRUE(d.get_float_array("missing").empty());
    EXPECT_TRUE(d.has("uv"));
    EXPECT_FALSE(d.has("missing"));
    // An integer serves where a float is asked for.
    EXPECT_FLOAT_EQ(d.get_one_float("n", 0), 7);
    EXPECT_EQ(d.get_float_array("indices").size(), 6u);
}

TEST(ParameterDictionary, Locations) {
    auto d = dict({numbers("float", "a", {1}, 4)});
    EXPECT_EQ(d.location("a").line, 4);
    EXPECT_EQ(d.location("b").line, kDirective.line);
    EXPECT_EQ(d.location("b").column, kDirective.column);
    EXPECT_EQ(d.directive_location().file, "scene.pbrt");
}

TEST(ParameterDictionary, WrongTypeIsAnErrorAtTheParameter) {
    auto d = dict({strings("string", "reflectance", {"red"}, 3), numbers("float", "n", {2}, 4),
                   numbers("point3", "p", {1, 2, 3}, 5)});
    NamedTextures textures;
    EXPECT_EQ(error_location([&] {
                  d.get_spectrum_texture("reflectance", nullptr, SpectrumType::Albedo, textures);
              }).line,
              3);
    EXPECT_EQ(error_location([&] { d.get_one_float("reflectance", 0); }).line, 3);
    EXPECT_EQ(error_location([&] { d.get_one_int("n", 0); }).line, 4);
    EXPECT_EQ(error_location([&] { d.get_one_string("n", ""); }).line, 4);
    EXPECT_EQ(error_location([&] { d.get_one_vector3("p", {}); }).line, 5);
    EXPECT_EQ(error_location([&] { d.get_one_spectrum("p", nullptr, SpectrumType::Albedo); }).line, 5);
}

TEST(ParameterDictionary, PropertyTypesCanBeProbed) {
    // pbrt's dielectric reads "eta" as floats first and as a spectrum second.
    auto d = dict({strings("spectrum", "eta", {"glass-BK7"}), numbers("rgb", "roughness", {.1, .1, .1})});
    EXPECT_TRUE(d.get_float_array("eta").empty());
    EXPECT_EQ(d.get_one_spectrum("eta", nullptr, SpectrumType::Unbounded),
              get_named_spectrum("glass-BK7"));
    NamedTextures textures;
    EXPECT_EQ(d.get_float_texture_or_null("roughness", textures), nullptr);
}

TEST(ParameterDictionary, ValueCounts) {
    auto d = dict({numbers("float", "two", {1, 2}, 2), numbers("point3", "pts", {0, 0, 0, 1, 1, 1}, 3)});
    EXPECT_EQ(error_location([&] { d.get_one_float("two", 0); }).line, 2);
    EXPECT_EQ(error_location([&] { d.get_one_point3("pts", {}); }).line, 3);
    EXPECT_EQ(d.get_point3_array("pts").size(), 2u);
    // A declaration whose values do not fit its type is rejected when the dictionary is built.
    EXPECT_THROW(dict({numbers("point3", "bad", {1, 2})}), InputError);
    EXPECT_THROW(dict({numbers("integer", "frac", {1.5})}), InputError);
    EXPECT_THROW(dict({numbers("blackbody", "L", {5000, 2})}), InputError);
    EXPECT_THROW(dict({numbers("spectrum", "odd", {400, 1, 500})}), InputError);
    EXPECT_THROW(dict({numbers("colour", "x", {1})}), InputError);
}

TEST(ParameterDictionary, CheckedFloat) {
    auto d = dict({numbers("float", "fov", {190}, 6), numbers("float", "ok", {0.5})});
    EXPECT_EQ(error_location([&] { d.get_one_float_checked("fov", 90, 0, 180); }).line, 6);
    EXPECT_FLOAT_EQ(d.get_one_float_checked("ok", 0, 0, 1), 0.5f);
    EXPECT_FLOAT_EQ(d.get_one_float_checked("absent", 45, 0, 180), 45);
}

TEST(ParameterDictionary, CanonicalTypes) {
    EXPECT_EQ(canonical_parameter_type("point"), "point3");
    EXPECT_EQ(canonical_parameter_type("normal"), "normal3");
    EXPECT_EQ(canonical_parameter_type("vector"), "vector3");
    EXPECT_EQ(canonical_parameter_type("vector2"), "vector2");
    EXPECT_EQ(canonical_parameter_type("color"), "");
}

TEST(ParameterDictionary, ReportUnusedNamesOnlyUnreadParameters) {
    auto d = dict({numbers("float", "used", {1}), numbers("float", "unused", {2}, 7),
                   numbers("float", "used", {3})});  // shadowed by the first "used"
    d.add_defaults({numbers("float", "default_only", {4})});
    d.get_one_float("used", 0);
    testing::internal::CaptureStderr();
    d.report_unused();
    std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("scene.pbrt:7:5: warning: unused parameter \"float unused\""), std::string::npos)
        << err;
    EXPECT_EQ(err.find("\"float used\""), std::string::npos) << err;
    EXPECT_EQ(err.find("default_only"), std::string::npos) << err;
}

TEST(ParameterDictionary, DefaultsComeAfterOwnValues) {
    auto d = dict({numbers("float", "radius", {2})});
    d.add_defaults({numbers("float", "radius", {5}), numbers("float", "zmax", {1})});
    EXPECT_FLOAT_EQ(d.get_one_float("radius", 0), 2);
    EXPECT_FLOAT_EQ(d.get_one_float("zmax", 0), 1);
}

// ---- Spectra ----------------------------------------------------------------------------------

TEST(ParameterSpectra, RgbFlavoursFollowTheSpectrumType) {
    auto d = dict({numbers("rgb", "c", {0.2, 0.5, 0.8})});
    EXPECT_NE(dynamic_cast<const RGBAlbedoSpectrum *>(
                  d.get_one_spectrum("c", nullptr, SpectrumType::Albedo).get()),
              nullptr);
    EXPECT_NE(dynamic_cast<const RGBUnboundedSpectrum *>(
                  d.get_one_spectrum("c", nullptr, SpectrumType::Unbounded).get()),
              nullptr);
    EXPECT_NE(dynamic_cast<const RGBIlluminantSpectrum *>(
                  d.get_one_spectrum("c", nullptr, SpectrumType::Illuminant).get()),
              nullptr);
    SpectrumPtr s = d.get_one_spectrum("c", nullptr, SpectrumType::Albedo);
    RGBAlbedoSpectrum direct(RGBColorSpace::srgb(), RGB{0.2f, 0.5f, 0.8f});
    for (float lambda : {400.f, 550.f, 700.f}) EXPECT_FLOAT_EQ((*s)(lambda), direct(lambda));
}

TEST(ParameterSpectra, RgbRanges) {
    auto d = dict({numbers("rgb", "bright", {2, 0.5, 0.5}, 2), numbers("rgb", "negative", {0.5, -0.1, 0}, 3)});
    set_warnings_enabled(false);
    // A reflectance above one is clamped (with a warning): the same spectrum as RGB (1, 0.5, 0.5).
    SpectrumPtr clamped = d.get_one_spectrum("bright", nullptr, SpectrumType::Albedo);
    set_warnings_enabled(true);
    RGBAlbedoSpectrum at_one(RGBColorSpace::srgb(), RGB{1, 0.5f, 0.5f});
    for (float lambda : {400.f, 550.f, 700.f}) EXPECT_FLOAT_EQ((*clamped)(lambda), at_one(lambda));
    EXPECT_NE(d.get_one_spectrum("bright", nullptr, SpectrumType::Unbounded), nullptr);
    EXPECT_NE(d.get_one_spectrum("bright", nullptr, SpectrumType::Illuminant), nullptr);
    for (SpectrumType t : {SpectrumType::Albedo, SpectrumType::Unbounded, SpectrumType::Illuminant})
        EXPECT_EQ(error_location([&] { d.get_one_spectrum("negative", nullptr, t); }).line, 3);
}

TEST(ParameterSpectra, RgbUsesTheColourSpace) {
    const RGBColorSpace &rec2020 = *RGBColorSpace::by_name("rec2020");
    RGB green{0.1f, 0.9f, 0.1f};
    auto in_rec2020 = dict({numbers("rgb", "c", {0.1, 0.9, 0.1})}, &rec2020);
    SpectrumPtr s = in_rec2020.get_one_spectrum("c", nullptr, SpectrumType::Albedo);
    RGBAlbedoSpectrum expected(rec2020, green), srgb(RGBColorSpace::srgb(), green);
    EXPECT_FLOAT_EQ((*s)(530), expected(530));
    EXPECT_NE((*s)(530), srgb(530));
    // An Attribute default keeps the colour space where it was declared.
    auto d = dict({}, &RGBColorSpace::srgb());
    ParsedParameter p = numbers("rgb", "c", {0.1, 0.9, 0.1});
    p.color_space = &rec2020;
    d.add_defaults({p});
    EXPECT_FLOAT_EQ((*d.get_one_spectrum("c", nullptr, SpectrumType::Albedo))(530), expected(530));
}

TEST(ParameterSpectra, Blackbody) {
    auto d = dict({numbers("blackbody", "L", {3000}), numbers("blackbody", "cold", {0}, 4)});
    SpectrumPtr s = d.get_one_spectrum("L", nullptr, SpectrumType::Illuminant);
    BlackbodySpectrum expected(3000);
    EXPECT_FLOAT_EQ((*s)(600), expected(600));
    EXPECT_EQ(error_location([&] { d.get_one_spectrum("cold", nullptr, SpectrumType::Illuminant); }).line, 4);
}

TEST(ParameterSpectra, ConstantAndInlinePairs) {
    auto d = dict({numbers("spectrum", "k", {2.5}), numbers("spectrum", "pairs", {400, 1, 500, 3}),
                   numbers("spectrum", "descending", {500, 1, 400, 3}, 5), numbers("float", "f", {1.5})});
    SpectrumPtr k = d.get_one_spectrum("k", nullptr, SpectrumType::Unbounded);
    EXPECT_TRUE(k->is_constant());
    EXPECT_FLOAT_EQ((*k)(380), 2.5f);
    EXPECT_FLOAT_EQ((*k)(780), 2.5f);
    // Linear interpolation between (400, 1) and (500, 3).
    SpectrumPtr pairs = d.get_one_spectrum("pairs", nullptr, SpectrumType::Unbounded);
    EXPECT_FLOAT_EQ((*pairs)(400), 1);
    EXPECT_FLOAT_EQ((*pairs)(450), 2);
    EXPECT_FLOAT_EQ((*pairs)(475), 2.5f);
    EXPECT_EQ(error_location([&] { d.get_one_spectrum("descending", nullptr, SpectrumType::Unbounded); }).line, 5);
    // A plain float is a constant spectrum too.
    EXPECT_FLOAT_EQ((*d.get_one_spectrum("f", nullptr, SpectrumType::Unbounded))(500), 1.5f);
}

TEST(ParameterSpectra, NamedAndFromFile) {
    std::string data = std::string(CAUSTICA_TEST_DATA) + "/parser";
    auto d = dict({strings("spectrum", "eta", {"metal-Cu-eta"}),
                   strings("spectrum", "file", {"spectrum_pairs.spd"}),
                   strings("spectrum", "nothing", {"no-such-spectrum"}, 6)},
                  nullptr, data);
    EXPECT_EQ(d.get_one_spectrum("eta", nullptr, SpectrumType::Unbounded),
              get_named_spectrum("metal-Cu-eta"));
    SpectrumPtr f = d.get_one_spectrum("file", nullptr, SpectrumType::Unbounded);
    // The file holds (400, 1) (500, 3) (600, 2).
    EXPECT_FLOAT_EQ((*f)(450), 2);
    EXPECT_FLOAT_EQ((*f)(550), 2.5f);
    EXPECT_EQ(error_location([&] { d.get_one_spectrum("nothing", nullptr, SpectrumType::Unbounded); }).line, 6);
    EXPECT_EQ(d.base_directory(), data);
}

TEST(ParameterSpectra, ReflectanceAboveOneIsClampedAndBelowZeroIsAnError) {
    auto d = dict({numbers("float", "high", {1.5}), numbers("spectrum", "pairs", {400, 0.5, 700, 1.25}),
                   numbers("float", "negative", {-0.25}, 4), numbers("spectrum", "dip", {400, 0.5, 700, -0.5}, 5),
                   numbers("spectrum", "eta", {400, 1.5, 700, 1.25})});
    set_warnings_enabled(false);
    EXPECT_FLOAT_EQ((*d.get_one_spectrum("high", nullptr, SpectrumType::Albedo))(550), 1);
    SpectrumPtr pairs = d.get_one_spectrum("pairs", nullptr, SpectrumType::Albedo);
    // Linear from 0.5 at 400 nm to 1 (clamped from 1.25) at 700 nm.
    EXPECT_FLOAT_EQ((*pairs)(400), 0.5f);
    EXPECT_FLOAT_EQ((*pairs)(550), 0.75f);
    EXPECT_FLOAT_EQ((*pairs)(700), 1);
    // Quantities that are not reflectances keep their values.
    EXPECT_FLOAT_EQ((*d.get_one_spectrum("high", nullptr, SpectrumType::Unbounded))(550), 1.5f);
    EXPECT_FLOAT_EQ((*d.get_one_spectrum("eta", nullptr, SpectrumType::Albedo))(700), 1);
    EXPECT_FLOAT_EQ((*d.get_one_spectrum("eta", nullptr, SpectrumType::Unbounded))(700), 1.25f);
    EXPECT_EQ(error_location([&] { d.get_one_spectrum("negative", nullptr, SpectrumType::Albedo); }).line, 4);
    EXPECT_EQ(error_location([&] { d.get_one_spectrum("dip", nullptr, SpectrumType::Albedo); }).line, 5);
    set_warnings_enabled(true);
}

TEST(ParameterDictionary, ValuesBeyondSinglePrecisionAreErrors) {
    // Finite as doubles, infinite as the floats every quantity is read as.
    EXPECT_EQ(error_location([] { dict({numbers("float", "radius", {1e39}, 3)}); }).line, 3);
    EXPECT_EQ(error_location([] { dict({numbers("point3", "P", {0, -5e38, 0}, 4)}); }).line, 4);
    EXPECT_NO_THROW(dict({numbers("float", "radius", {3e38})}));
}

TEST(ParameterDictionary, FilePathsAndDisabledFileAccess) {
    auto d = dict({strings("string", "filename", {"mesh.ply"}, 2),
                   strings("spectrum", "eta", {"glass-BK7"}, 3),
                   strings("spectrum", "file", {"spectrum_pairs.spd"}, 4)},
                  nullptr, "scenes");
    EXPECT_EQ(d.file_path("filename", "mesh.ply"), (std::filesystem::path("scenes") / "mesh.ply").string());
    EXPECT_EQ(d.file_path("filename", "/abs/mesh.ply"), "/abs/mesh.ply");
    d.disable_file_access();
    EXPECT_EQ(error_location([&] { d.file_path("filename", "mesh.ply"); }).line, 2);
    // Named spectra need no file; any other name would be read from disk, which is refused.
    EXPECT_EQ(d.get_one_spectrum("eta", nullptr, SpectrumType::Unbounded), get_named_spectrum("glass-BK7"));
    try {
        d.get_one_spectrum("file", nullptr, SpectrumType::Unbounded);
        ADD_FAILURE() << "a spectrum file was read with file access disabled";
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 4);
        EXPECT_NE(e.message().find("file access is disabled"), std::string::npos) << e.message();
    }
}

TEST(ParameterSpectra, DefaultsAndTextureParametersReadAsAbsent) {
    auto d = dict({strings("texture", "Kd", {"checks"})});
    SpectrumPtr def = std::make_shared<ConstantSpectrum>(0.5f);
    EXPECT_EQ(d.get_one_spectrum("Kd", def, SpectrumType::Albedo), def);
    EXPECT_EQ(d.get_one_spectrum("absent", def, SpectrumType::Albedo), def);
    EXPECT_EQ(d.get_one_spectrum("absent", nullptr, SpectrumType::Albedo), nullptr);
}

// ---- Textures ---------------------------------------------------------------------------------

TEST(ParameterTextures, FloatTextures) {
    NamedTextures textures;
    auto bumps = std::make_shared<ConstantFloatTexture>(0.7f);
    textures.float_textures["bumps"] = bumps;
    textures.albedo["colour"] = std::make_shared<ConstantSpectrumTexture>(std::make_shared<ConstantSpectrum>(1.f));
    auto d = dict({numbers("float", "roughness", {0.3}), strings("texture", "bump", {"bumps"}),
                   strings("texture", "missing", {"nope"}, 8), strings("texture", "wrong", {"colour"}, 9)});
    TextureEvalContext ctx;
    FloatTexturePtr r = d.get_float_texture("roughness", 0, textures);
    EXPECT_FLOAT_EQ(r->evaluate(ctx), 0.3f);
    ASSERT_NE(r->constant_value(), nullptr);
    EXPECT_FLOAT_EQ(*r->constant_value(), 0.3f);
    EXPECT_EQ(d.get_float_texture("bump", 0, textures), bumps);
    EXPECT_FLOAT_EQ(d.get_float_texture("absent", 0.25f, textures)->evaluate(ctx), 0.25f);
    EXPECT_EQ(d.get_float_texture_or_null("absent", textures), nullptr);
    EXPECT_EQ(error_location([&] { d.get_float_texture("missing", 0, textures); }).line, 8);
    try {
        d.get_float_texture("wrong", 0, textures);
        ADD_FAILURE();
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 9);
        EXPECT_NE(e.message().find("spectrum texture"), std::string::npos) << e.message();
    }
}

TEST(ParameterTextures, SpectrumTexturesPerType) {
    NamedTextures textures;
    auto albedo = std::make_shared<ConstantSpectrumTexture>(std::make_shared<ConstantSpectrum>(0.5f));
    auto unbounded = std::make_shared<ConstantSpectrumTexture>(std::make_shared<ConstantSpectrum>(5.f));
    textures.albedo["t"] = albedo;
    textures.unbounded["t"] = unbounded;
    auto d = dict({strings("texture", "tex", {"t"}, 2), numbers("rgb", "c", {0.2, 0.4, 0.6}),
                   numbers("spectrum", "k", {0.5})});
    EXPECT_EQ(d.get_spectrum_texture("tex", nullptr, SpectrumType::Albedo, textures), albedo);
    EXPECT_EQ(d.get_spectrum_texture("tex", nullptr, SpectrumType::Unbounded, textures), unbounded);
    EXPECT_EQ(error_location([&] {
                  d.get_spectrum_texture("tex", nullptr, SpectrumType::Illuminant, textures);
              }).line,
              2);
    SampledWavelengths lambda = SampledWavelengths::sample_uniform(0.3f);
    TextureEvalContext ctx;
    SpectrumTexturePtr c = d.get_spectrum_texture("c", nullptr, SpectrumType::Albedo, textures);
    RGBAlbedoSpectrum expected(RGBColorSpace::srgb(), RGB{0.2f, 0.4f, 0.6f});
    SampledSpectrum v = c->evaluate(ctx, lambda);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_FLOAT_EQ(v[i], expected(lambda[i]));
    EXPECT_FALSE(c->is_wavelength_independent());
    EXPECT_TRUE(d.get_spectrum_texture("k", nullptr, SpectrumType::Albedo, textures)
                    ->is_wavelength_independent());
    EXPECT_EQ(d.get_spectrum_texture_or_null("absent", SpectrumType::Albedo, textures), nullptr);
    EXPECT_EQ(d.get_spectrum_texture("absent", nullptr, SpectrumType::Albedo, textures), nullptr);
    SpectrumTexturePtr def = d.get_spectrum_texture(
        "absent", std::make_shared<ConstantSpectrum>(0.25f), SpectrumType::Albedo, textures);
    ASSERT_NE(def, nullptr);
    EXPECT_FLOAT_EQ(def->evaluate(ctx, lambda)[0], 0.25f);
}

} // namespace
} // namespace caustica
