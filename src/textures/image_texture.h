// pbrt-v4's "imagemap" textures: an image file looked up at a 2D mapping's texture coordinates.
//
// Lookups go through the image's MIP map (mipmap.h) with the "filter" asked for ("point",
// "bilinear" (the default), "trilinear", "ewa"), over the footprint of a pixel at the point
// (the texture coordinates' screen-space derivatives, camera/camera_footprint.h). As in pbrt-v4,
// t = 0 is the bottom row of the image, texels are linear (8-bit files are decoded by their
// "encoding", sRGB unless stated), a value is scaled, then inverted (1 - v) if asked, then
// clamped at zero; spectrum textures turn the RGB of a lookup into a spectrum of the parameter's
// kind (albedo, unbounded, illuminant) in the file's colour space (sRGB), and float textures read
// the channel read_image_lookup describes.
#pragma once

#include "core/error.h"
#include "textures/texture.h"
#include "textures/texture_mapping.h"

#include <memory>
#include <vector>

namespace caustica {

class MIPMap;
class ParameterDictionary;
class RGBColorSpace;

// What happens to texture coordinates outside [0, 1]: pbrt-v4's "wrap" modes.
enum class ImageWrap { Repeat, Black, Clamp, OctahedralSphere };

// An image's linear texels, 1 or 3 channels interleaved, rows from the top down.
class TexelImage {
  public:
    TexelImage(int width, int height, int channels, std::vector<float> texels);
    // The bilinearly interpolated channels at texture coordinates st, t = 0 at the bottom row
    // (written to out[0 .. channels)).
    void lookup(Vec2f st, ImageWrap wrap, float *out) const;
    // The bilinearly interpolated channels at st, t = 0 at the top row (pbrt-v4's Image::Bilerp).
    void bilerp(Vec2f st, ImageWrap wrap, float *out) const;
    // Texel (x, y)'s channel c, by the wrap mode outside the image (0 with ImageWrap::Black).
    float texel(int x, int y, int c, ImageWrap wrap) const;

    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }
    // The texels, interleaved, rows from the top.
    const float *data() const { return texels_.data(); }

  private:
    int width_, height_, channels_;
    std::vector<float> texels_;
};

// The lookup settings an imagemap texture reads from its parameters.
struct ImageLookup {
    TextureMapping2D mapping;
    std::shared_ptr<const MIPMap> mipmap;
    float scale = 1;
    bool invert = false;
};

class FloatImageTexture final : public FloatTexture {
  public:
    explicit FloatImageTexture(ImageLookup lookup) : lookup_(std::move(lookup)) {}
    float evaluate(const TextureEvalContext &ctx) const override;

  private:
    ImageLookup lookup_;
};

class SpectrumImageTexture final : public SpectrumTexture {
  public:
    SpectrumImageTexture(ImageLookup lookup, SpectrumType type, const RGBColorSpace &color_space)
        : lookup_(std::move(lookup)), type_(type), color_space_(&color_space) {}
    SampledSpectrum evaluate(const TextureEvalContext &ctx, const SampledWavelengths &lambda) const override;

  private:
    ImageLookup lookup_;
    SpectrumType type_;
    const RGBColorSpace *color_space_;
};

// The texels of the image file at `path`, `channels` of them (1 or 3), read as linear values
// whatever the file's bit depth (pbrt-v4 reads normal maps so). Throws std::runtime_error.
std::shared_ptr<const TexelImage> read_linear_texels(const std::string &path, int channels);

// Reads an imagemap texture's parameters and its file (relative to the scene file), with
// `channels` texels (1 for a float texture, 3 for a spectrum one), looked up through `mapping`.
// Throws InputError at the parameter that is wrong or names an unreadable file.
ImageLookup read_image_lookup(TextureMapping2D mapping, const ParameterDictionary &params, int channels,
                              const SourceLocation &loc);

} // namespace caustica
