// pbrt-v4's "imagemap" textures (src/textures/image_texture.h): lookups against texels written
// here to files, wrap modes, scale and invert, the spectrum kinds, 8-bit decoding, and errors at
// the parameter.
#include "param_helpers.h"

#include "core/error.h"
#include "openimageio/openimageio_plugin.h"
#include "spectral/color_space.h"
#include "spectral/rgb_spectrum.h"
#include "textures/texture_factory.h"

#include <ImfRgbaFile.h>
#include <gtest/gtest.h>

#include <zlib.h>

#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace caustica {
namespace {

using namespace caustica::testing;

TextureEvalContext at_st(float s, float t) {
    TextureEvalContext ctx;
    ctx.uv = {s, t};
    return ctx;
}

class ImageTextureTest : public ::testing::Test {
  protected:
    void SetUp() override {
        set_warnings_enabled(false);
        dir_ = std::filesystem::temp_directory_path() / ("caustica-test-imagemap-" + std::to_string(getpid()));
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override {
        set_warnings_enabled(true);
        std::filesystem::remove_all(dir_);
    }
    // A 2x2 half-float EXR, rows from the top: (r, g, b) per texel, top-left first; with an alpha
    // channel when alpha is given.
    std::string write_exr(const std::string &name, const std::array<RGB, 4> &texels,
                          const std::array<float, 4> *alpha = nullptr) {
        const std::string path = (dir_ / name).string();
        Imf::Rgba pixels[4];
        for (int i = 0; i < 4; ++i) pixels[i] = Imf::Rgba(texels[i].r, texels[i].g, texels[i].b, alpha ? (*alpha)[i] : 1);
        Imf::RgbaOutputFile file(path.c_str(), 2, 2, alpha ? Imf::WRITE_RGBA : Imf::WRITE_RGB);
        file.setFrameBuffer(pixels, 1, 2);
        file.writePixels(2);
        return path;
    }
    // A 2x2 8-bit PNG with `channels` channels (2: grey and alpha, 4: RGBA), rows from the top,
    // written by hand so that the colour is stored as given, not multiplied by alpha.
    std::string write_png(const std::string &name, int channels, const std::vector<uint8_t> &texels) {
        const std::string path = (dir_ / name).string();
        std::vector<uint8_t> raw;
        for (int y = 0; y < 2; ++y) {
            raw.push_back(0); // no filter
            raw.insert(raw.end(), texels.begin() + y * 2 * channels, texels.begin() + (y + 1) * 2 * channels);
        }
        uLongf size = compressBound(uLong(raw.size()));
        std::vector<uint8_t> packed(size);
        compress(packed.data(), &size, raw.data(), uLong(raw.size()));
        packed.resize(size);
        std::FILE *f = std::fopen(path.c_str(), "wb");
        auto u32 = [&](uint32_t v) {
            const uint8_t b[4] = {uint8_t(v >> 24), uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)};
            std::fwrite(b, 1, 4, f);
        };
        auto chunk = [&](const char *kind, const std::vector<uint8_t> &data) {
            u32(uint32_t(data.size()));
            std::vector<uint8_t> body(kind, kind + 4);
            body.insert(body.end(), data.begin(), data.end());
            std::fwrite(body.data(), 1, body.size(), f);
            u32(uint32_t(crc32(0, body.data(), uInt(body.size()))));
        };
        const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
        std::fwrite(signature, 1, 8, f);
        chunk("IHDR", {0, 0, 0, 2, 0, 0, 0, 2, 8, uint8_t(channels == 2 ? 4 : 6), 0, 0, 0});
        chunk("IDAT", packed);
        chunk("IEND", {});
        std::fclose(f);
        return path;
    }
    FloatTexturePtr float_texture(std::vector<ParsedParameter> params) {
        ParameterDictionary d = dictionary(std::move(params));
        return create_float_texture("imagemap", {}, d, {}, directive_location());
    }
    SpectrumTexturePtr spectrum_texture(std::vector<ParsedParameter> params, SpectrumType type) {
        ParameterDictionary d = dictionary(std::move(params));
        return create_spectrum_texture("imagemap", {}, d, type, {}, directive_location());
    }
    // The line of the InputError that creating the float texture throws, or -1.
    int error_line(std::vector<ParsedParameter> params) {
        return input_error_line([&] { float_texture(std::move(params)); });
    }

    std::filesystem::path dir_;
    SampledWavelengths lambda_ = SampledWavelengths::sample_visible(0.3f);
};

// Grey texel values 0.25 (top left), 0.5 (top right), 0.75 (bottom left), 1 (bottom right).
const std::array<RGB, 4> Ramp = {RGB{0.25f, 0.25f, 0.25f}, RGB{0.5f, 0.5f, 0.5f}, RGB{0.75f, 0.75f, 0.75f},
                                 RGB{1, 1, 1}};

TEST_F(ImageTextureTest, BilinearLookupsWithTUpwards) {
    auto tex = float_texture({strings("string", "filename", {write_exr("ramp.exr", Ramp)}, 2)});
    // Texel centres: s = 0.25 or 0.75; t = 0.75 is the top row, 0.25 the bottom one.
    EXPECT_FLOAT_EQ(tex->evaluate(at_st(0.25f, 0.75f)), 0.25f);
    EXPECT_FLOAT_EQ(tex->evaluate(at_st(0.75f, 0.75f)), 0.5f);
    EXPECT_FLOAT_EQ(tex->evaluate(at_st(0.25f, 0.25f)), 0.75f);
    EXPECT_FLOAT_EQ(tex->evaluate(at_st(0.75f, 0.25f)), 1);
    // Between the four centres, their average; between two, theirs.
    EXPECT_FLOAT_EQ(tex->evaluate(at_st(0.5f, 0.5f)), 0.625f);
    EXPECT_FLOAT_EQ(tex->evaluate(at_st(0.5f, 0.75f)), 0.375f);
    // Repeat (the default): s = 0 lies halfway between the right column and the left one.
    EXPECT_FLOAT_EQ(tex->evaluate(at_st(0, 0.75f)), 0.375f);
    EXPECT_FLOAT_EQ(tex->evaluate(at_st(1.25f, -0.75f)), tex->evaluate(at_st(0.25f, 0.25f)));
}

TEST_F(ImageTextureTest, WrapModesFilterScaleAndInvert) {
    const std::string file = write_exr("ramp.exr", Ramp);
    auto clamp = float_texture({strings("string", "filename", {file}, 2), strings("string", "wrap", {"clamp"}, 3)});
    EXPECT_FLOAT_EQ(clamp->evaluate(at_st(0, 0.75f)), 0.25f);
    EXPECT_FLOAT_EQ(clamp->evaluate(at_st(3, -2)), 1);
    auto black = float_texture({strings("string", "filename", {file}, 2), strings("string", "wrap", {"black"}, 3)});
    EXPECT_FLOAT_EQ(black->evaluate(at_st(0, 0.75f)), 0.125f);  // half the left texel, half black
    EXPECT_FLOAT_EQ(black->evaluate(at_st(2, 2)), 0);
    // The octahedral sphere map re-enters a left step at the mirrored row of the same edge: the
    // texel left of the top-left one is the bottom-left one (repeat would give the top-right,
    // clamp the top-left itself).
    auto octahedral = float_texture({strings("string", "filename", {file}, 2),
                                     strings("string", "wrap", {"octahedralsphere"}, 3),
                                     strings("string", "filter", {"point"}, 4)});
    EXPECT_FLOAT_EQ(octahedral->evaluate(at_st(-0.25f, 0.75f)), 0.75f);
    EXPECT_FLOAT_EQ(octahedral->evaluate(at_st(0.25f, 1.25f)), 0.5f);
    auto point = float_texture({strings("string", "filename", {file}, 2), strings("string", "filter", {"point"}, 3)});
    EXPECT_FLOAT_EQ(point->evaluate(at_st(0.49f, 0.51f)), 0.25f);
    EXPECT_FLOAT_EQ(point->evaluate(at_st(0.51f, 0.49f)), 1);
    // scale, then invert, then clamped at zero.
    auto scaled = float_texture({strings("string", "filename", {file}, 2), numbers("float", "scale", {2}, 3)});
    EXPECT_FLOAT_EQ(scaled->evaluate(at_st(0.25f, 0.75f)), 0.5f);
    auto inverted = float_texture({strings("string", "filename", {file}, 2), numbers("float", "scale", {2}, 3),
                                   boolean("invert", true, 4)});
    EXPECT_FLOAT_EQ(inverted->evaluate(at_st(0.25f, 0.75f)), 0.5f);
    EXPECT_FLOAT_EQ(inverted->evaluate(at_st(0.75f, 0.25f)), 0);
    // The mapping's parameters apply: uscale 2 repeats the image twice across u.
    auto tiled = float_texture({strings("string", "filename", {file}, 2), numbers("float", "uscale", {2}, 3)});
    EXPECT_FLOAT_EQ(tiled->evaluate(at_st(0.125f + 0.5f, 0.75f)), 0.25f);
}

TEST_F(ImageTextureTest, SpectrumKindsAndChannels) {
    const std::array<RGB, 4> colours = {RGB{0.8f, 0.4f, 0.2f}, RGB{0.1f, 0.5f, 0.9f}, RGB{2, 1, 0.5f}, RGB{0, 0, 0}};
    const std::string file = write_exr("colours.exr", colours);
    const RGBColorSpace &srgb = RGBColorSpace::srgb();
    auto albedo = spectrum_texture({strings("string", "filename", {file}, 2)}, SpectrumType::Albedo);
    auto unbounded = spectrum_texture({strings("string", "filename", {file}, 2)}, SpectrumType::Unbounded);
    auto illuminant = spectrum_texture({strings("string", "filename", {file}, 2)}, SpectrumType::Illuminant);
    const SampledSpectrum a = albedo->evaluate(at_st(0.75f, 0.75f), lambda_);
    const SampledSpectrum expected_a = RGBAlbedoSpectrum(srgb, colours[1]).sample(lambda_);
    // An albedo above 1 is clamped to 1; unbounded and illuminant keep it.
    const SampledSpectrum clamped = albedo->evaluate(at_st(0.25f, 0.25f), lambda_);
    const SampledSpectrum expected_clamped = RGBAlbedoSpectrum(srgb, RGB{1, 1, 0.5f}).sample(lambda_);
    const SampledSpectrum u = unbounded->evaluate(at_st(0.25f, 0.25f), lambda_);
    const SampledSpectrum expected_u = RGBUnboundedSpectrum(srgb, colours[2]).sample(lambda_);
    const SampledSpectrum e = illuminant->evaluate(at_st(0.25f, 0.25f), lambda_);
    const SampledSpectrum expected_e = RGBIlluminantSpectrum(srgb, colours[2]).sample(lambda_);
    for (int i = 0; i < NumWavelengths; ++i) {
        EXPECT_NEAR(a[i], expected_a[i], 1e-3f);
        EXPECT_NEAR(clamped[i], expected_clamped[i], 1e-3f);
        EXPECT_NEAR(u[i], expected_u[i], 2e-3f);
        EXPECT_NEAR(e[i], expected_e[i], 2e-3f * expected_e[i] + 1e-4f);
    }
}

// A float texture reads a colour file as pbrt-v4's MIP maps do: "bilinear" (and "trilinear") the
// mean of R, G and B, or the alpha channel when it is not 1 everywhere (a cut-out's alpha map);
// "point" (and "ewa") the first channel.
TEST_F(ImageTextureTest, FloatTexturesReadTheMeanOrTheAlphaOfColourFiles) {
    const std::array<RGB, 4> colours = {RGB{0.8f, 0.4f, 0.2f}, RGB{0.1f, 0.5f, 0.9f}, RGB{2, 1, 0.5f}, RGB{0, 0, 0}};
    const std::string opaque = write_exr("colours.exr", colours);
    auto mean = float_texture({strings("string", "filename", {opaque}, 2)});
    EXPECT_NEAR(mean->evaluate(at_st(0.25f, 0.75f)), (0.8f + 0.4f + 0.2f) / 3, 1e-3f);
    auto first = float_texture({strings("string", "filename", {opaque}, 2), strings("string", "filter", {"point"}, 3)});
    EXPECT_NEAR(first->evaluate(at_st(0.25f, 0.75f)), 0.8f, 1e-3f);
    const std::array<float, 4> alpha = {0, 0.25f, 1, 0.5f};
    const std::string cut = write_exr("cut.exr", colours, &alpha);
    auto alpha_map = float_texture({strings("string", "filename", {cut}, 2)});
    EXPECT_NEAR(alpha_map->evaluate(at_st(0.25f, 0.75f)), 0, 1e-3f);
    EXPECT_NEAR(alpha_map->evaluate(at_st(0.75f, 0.75f)), 0.25f, 1e-3f);
    EXPECT_NEAR(alpha_map->evaluate(at_st(0.25f, 0.25f)), 1, 1e-3f);
    const std::array<float, 4> ones = {1, 1, 1, 1};
    auto all_one = float_texture({strings("string", "filename", {write_exr("ones.exr", colours, &ones)}, 2)});
    EXPECT_NEAR(all_one->evaluate(at_st(0.25f, 0.75f)), (0.8f + 0.4f + 0.2f) / 3, 1e-3f);
}

// An RGBA PNG's colour is read as stored (pbrt-v4 does not multiply it by alpha), its alpha,
// sRGB-decoded like the colour, is what a float texture reads, and a grey PNG's alpha is dropped
// (pbrt-v4 reads such a file as grey).
TEST_F(ImageTextureTest, PngAlphaIsNotMultipliedIn) {
    const std::vector<uint8_t> rgba = {200, 100, 50, 128, 10, 20, 30, 0, 255, 255, 255, 255, 0, 0, 0, 255};
    const std::string file = write_png("rgba.png", 4, rgba);
    auto colour = spectrum_texture({strings("string", "filename", {file}, 2)}, SpectrumType::Unbounded);
    const SampledSpectrum c = colour->evaluate(at_st(0.25f, 0.75f), lambda_);
    const RGB stored{srgb_to_linear(200 / 255.f), srgb_to_linear(100 / 255.f), srgb_to_linear(50 / 255.f)};
    const SampledSpectrum expected = RGBUnboundedSpectrum(RGBColorSpace::srgb(), stored).sample(lambda_);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_NEAR(c[i], expected[i], 2e-3f * expected[i]);
    auto alpha = float_texture({strings("string", "filename", {file}, 2)});
    EXPECT_NEAR(alpha->evaluate(at_st(0.25f, 0.75f)), srgb_to_linear(128 / 255.f), 1e-4f);
    EXPECT_NEAR(alpha->evaluate(at_st(0.75f, 0.75f)), 0, 1e-6f);
    const std::string grey = write_png("grey-alpha.png", 2, {100, 0, 150, 64, 200, 128, 250, 255});
    auto y = float_texture({strings("string", "filename", {grey}, 2)});
    EXPECT_NEAR(y->evaluate(at_st(0.25f, 0.75f)), srgb_to_linear(100 / 255.f), 1e-4f);
}

// 8-bit files are decoded by "encoding": sRGB by default, or linear, or a gamma.
TEST_F(ImageTextureTest, EightBitEncodings) {
    const std::string path = (dir_ / "grey.png").string();
    const uint8_t texels[4 * 3] = {128, 128, 128, 128, 128, 128, 128, 128, 128, 128, 128, 128};
    ASSERT_EQ(openimageio().write_rgb8(path, 2, 2, texels), "");
    const float encoded = 128.f / 255;
    EXPECT_NEAR(float_texture({strings("string", "filename", {path}, 2)})->evaluate(at_st(0.5f, 0.5f)),
                srgb_to_linear(encoded), 1e-5f);
    EXPECT_NEAR(float_texture({strings("string", "filename", {path}, 2), strings("string", "encoding", {"linear"}, 3)})
                    ->evaluate(at_st(0.5f, 0.5f)),
                encoded, 1e-5f);
    EXPECT_NEAR(float_texture({strings("string", "filename", {path}, 2), strings("string", "encoding", {"gamma 2.2"}, 3)})
                    ->evaluate(at_st(0.5f, 0.5f)),
                std::pow(encoded, 2.2f), 1e-5f);
}

TEST_F(ImageTextureTest, ErrorsPointAtTheParameter) {
    const std::string file = write_exr("ramp.exr", Ramp);
    EXPECT_EQ(error_line({}), 1);  // no filename: the directive
    EXPECT_EQ(error_line({strings("string", "filename", {(dir_ / "missing.png").string()}, 5)}), 5);
    EXPECT_EQ(error_line({strings("string", "filename", {file}, 2), strings("string", "wrap", {"mirror"}, 6)}), 6);
    EXPECT_EQ(error_line({strings("string", "filename", {file}, 2), strings("string", "filter", {"gaussian"}, 7)}), 7);
    EXPECT_EQ(error_line({strings("string", "filename", {file}, 2), strings("string", "encoding", {"gamma -1"}, 8)}), 8);
    EXPECT_EQ(error_line({strings("string", "filename", {file}, 2), strings("string", "filter", {"ewa"}, 3),
                          numbers("float", "maxanisotropy", {16}, 4)}),
              -1);
}

} // namespace
} // namespace caustica
