#include "textures/image_texture.h"

#include "core/error.h"
#include "openimageio/openimageio_plugin.h"
#include "params/parameters.h"
#include "spectral/color.h"
#include "spectral/color_space.h"
#include "spectral/rgb_spectrum.h"
#include "textures/mipmap.h"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>

namespace caustica {

TexelImage::TexelImage(int width, int height, int channels, std::vector<float> texels)
    : width_(width), height_(height), channels_(channels), texels_(std::move(texels)) {}

float TexelImage::texel(int x, int y, int c, ImageWrap wrap) const {
    switch (wrap) {
    case ImageWrap::Repeat:
        x = ((x % width_) + width_) % width_;
        y = ((y % height_) + height_) % height_;
        break;
    case ImageWrap::Clamp:
        x = std::clamp(x, 0, width_ - 1);
        y = std::clamp(y, 0, height_ - 1);
        break;
    case ImageWrap::Black:
        if (x < 0 || x >= width_ || y < 0 || y >= height_) return 0;
        break;
    case ImageWrap::OctahedralSphere:
        // The equal-area octahedral map of a sphere (environment maps): stepping off one edge
        // re-enters at the mirrored position on the same edge.
        if (x < 0) {
            x = -x - 1;
            y = height_ - 1 - y;
        } else if (x >= width_) {
            x = 2 * width_ - 1 - x;
            y = height_ - 1 - y;
        }
        if (y < 0) {
            x = width_ - 1 - x;
            y = -y - 1;
        } else if (y >= height_) {
            x = width_ - 1 - x;
            y = 2 * height_ - 1 - y;
        }
        x = std::clamp(x, 0, width_ - 1);
        y = std::clamp(y, 0, height_ - 1);
        break;
    }
    return texels_[(size_t(y) * width_ + x) * channels_ + c];
}

void TexelImage::lookup(Vec2f st, ImageWrap wrap, float *out) const { bilerp({st.x, 1 - st.y}, wrap, out); }

void TexelImage::bilerp(Vec2f st, ImageWrap wrap, float *out) const {
    const double xs = double(st.x) * width_ - 0.5, ys = double(st.y) * height_ - 0.5;
    const int x0 = int(std::floor(xs)), y0 = int(std::floor(ys));
    const float dx = float(xs - x0), dy = float(ys - y0);
    for (int c = 0; c < channels_; ++c)
        out[c] = (1 - dx) * (1 - dy) * texel(x0, y0, c, wrap) + dx * (1 - dy) * texel(x0 + 1, y0, c, wrap) +
                 (1 - dx) * dy * texel(x0, y0 + 1, c, wrap) + dx * dy * texel(x0 + 1, y0 + 1, c, wrap);
}

// The MIP map's filtered value at the lookup's texture coordinates. The image's rows run down
// while t runs up; the footprint is passed unflipped, as pbrt-v4 passes it (which mirrors an EWA
// ellipse's orientation; trilinear lookups do not see it).
static void filtered_lookup(const ImageLookup &lookup, const TextureEvalContext &ctx, float *out) {
    const TexCoord2D c = lookup.mapping.map(ctx);
    lookup.mipmap->filter({c.st.x, 1 - c.st.y}, {c.dsdx, c.dtdx}, {c.dsdy, c.dtdy}, out);
}

float FloatImageTexture::evaluate(const TextureEvalContext &ctx) const {
    float v = 0;
    filtered_lookup(lookup_, ctx, &v);
    v *= lookup_.scale;
    return std::max(0.f, lookup_.invert ? 1 - v : v);
}

SampledSpectrum SpectrumImageTexture::evaluate(const TextureEvalContext &ctx, const SampledWavelengths &lambda) const {
    float v[3];
    filtered_lookup(lookup_, ctx, v);
    RGB rgb = RGB{v[0], v[1], v[2]} * lookup_.scale;
    if (lookup_.invert) rgb = RGB{1, 1, 1} - rgb;
    rgb = clamp_zero(rgb);
    switch (type_) {
    case SpectrumType::Albedo:
        return RGBAlbedoSpectrum(*color_space_, {std::min(rgb.r, 1.f), std::min(rgb.g, 1.f), std::min(rgb.b, 1.f)})
            .sample(lambda);
    case SpectrumType::Unbounded:
        return RGBUnboundedSpectrum(*color_space_, rgb).sample(lambda);
    case SpectrumType::Illuminant:
        return RGBIlluminantSpectrum(*color_space_, rgb).sample(lambda);
    }
    return {};
}

namespace {

// Which channel a float texture reads from a file with several (decode_texels).
enum class FloatTexels { FirstChannel, AlphaOrMean };

// How an 8-bit file's values map to linear ones (pbrt-v4's ColorEncoding).
struct Encoding {
    enum Kind { Linear, SRGB, Gamma } kind = SRGB;
    float gamma = 1;
    float decode(float v) const {
        if (kind == SRGB) return srgb_to_linear(v);
        if (kind == Gamma) return std::pow(std::max(v, 0.f), gamma);
        return v;
    }
};

Encoding read_encoding(const ParameterDictionary &params) {
    const std::string name = params.get_one_string("encoding", "sRGB");
    if (name == "sRGB") return {Encoding::SRGB};
    if (name == "linear") return {Encoding::Linear};
    float gamma = 0;
    char rest = 0;
    if (std::sscanf(name.c_str(), "gamma %f %c", &gamma, &rest) == 1 && gamma > 0 && std::isfinite(gamma))
        return {Encoding::Gamma, gamma};
    throw InputError(params.location("encoding"),
                     "\"encoding\" must be \"sRGB\", \"linear\" or \"gamma <exponent>\", not \"" + name + "\"");
}

// The channel of an alpha that is not 1 everywhere, or -1.
int partial_alpha_channel(const DecodedImage &decoded) {
    const int a = decoded.channel_index("A");
    if (a < 0) return -1;
    for (int y = 0; y < decoded.height; ++y)
        for (int x = 0; x < decoded.width; ++x)
            if (decoded.at(x, y, a) != 1) return a;
    return -1;
}

// The texels of `path` with `channels` channels: for 3, R, G and B (a grey image's one channel
// three times). For 1, as pbrt-v4's float textures read a file (its MIPMap's Texel and Bilerp):
// a grey image's grey (pbrt-v4 drops a grey PNG's alpha); a colour image's first channel with
// FloatTexels::FirstChannel ("point" and "ewa" lookups), and with FloatTexels::AlphaOrMean
// ("bilinear" and "trilinear") its alpha channel when that is not 1 everywhere (a cut-out's
// alpha map), else the mean of R, G and B.
std::shared_ptr<const TexelImage> decode_texels(const std::string &path, int channels, Encoding encoding,
                                                FloatTexels float_texels) {
    const DecodedImage decoded = read_image_file(path);
    if (decoded.width <= 0 || decoded.height <= 0 || decoded.channels <= 0)
        throw std::runtime_error("image \"" + path + "\" has no pixels");
    // Each output channel is the mean of its source channels (one, or R, G and B).
    std::vector<std::vector<int>> source(channels, std::vector<int>{0});
    int r = decoded.channel_index("R"), g = decoded.channel_index("G"), b = decoded.channel_index("B");
    if (r < 0 || g < 0 || b < 0) r = 0, g = 1, b = 2;
    if (channels == 3 && decoded.channels >= 3) {
        source = {{r}, {g}, {b}};
    } else if (channels == 1 && decoded.channels >= 3 && float_texels == FloatTexels::AlphaOrMean) {
        if (const int a = partial_alpha_channel(decoded); a >= 0) source = {{a}};
        else source = {{r, g, b}};
    }
    // Float files hold linear values; the encoding is for integer-coded ones.
    const bool decode = !decoded.float_format;
    std::vector<float> texels(size_t(decoded.width) * decoded.height * channels);
    for (int y = 0; y < decoded.height; ++y)
        for (int x = 0; x < decoded.width; ++x)
            for (int c = 0; c < channels; ++c) {
                float sum = 0;
                for (int s : source[c]) {
                    const float v = decoded.at(x, y, s);
                    if (!std::isfinite(v))
                        throw std::runtime_error("image \"" + path + "\" has infinite or not-a-number texels");
                    sum += decode ? encoding.decode(v) : v;
                }
                texels[(size_t(y) * decoded.width + x) * channels + c] = sum / float(source[c].size());
            }
    return std::make_shared<TexelImage>(decoded.width, decoded.height, channels, std::move(texels));
}

// Textures that read the same file the same way share its texels (scenes often use one image
// for several materials). Scene building is single-threaded, the lock is for safety only.
std::shared_ptr<const TexelImage> cached_texels(const std::string &path, int channels, Encoding encoding,
                                                FloatTexels float_texels = FloatTexels::AlphaOrMean) {
    static std::mutex mutex;
    static std::map<std::tuple<std::string, int, int, float, int>, std::weak_ptr<const TexelImage>> cache;
    std::lock_guard lock(mutex);
    auto key = std::tuple{path, channels, int(encoding.kind), encoding.gamma, int(float_texels)};
    if (auto image = cache[key].lock()) return image;
    auto image = decode_texels(path, channels, encoding, float_texels);
    cache[key] = image;
    return image;
}

// Lookups that read the same file the same way, with the same wrap mode and filter, share one
// pyramid (scenes often use one image for several materials).
std::shared_ptr<const MIPMap> cached_mipmap(const std::string &path, int channels, Encoding encoding,
                                            FloatTexels float_texels, ImageWrap wrap, MIPFilter filter,
                                            float max_anisotropy) {
    static std::mutex mutex;
    static std::map<std::tuple<std::string, int, int, float, int, int, int, float>, std::weak_ptr<const MIPMap>>
        cache;
    std::lock_guard lock(mutex);
    auto key = std::tuple{path,          channels,  int(encoding.kind), encoding.gamma, int(float_texels),
                          int(wrap), int(filter), max_anisotropy};
    if (auto mipmap = cache[key].lock()) return mipmap;
    auto mipmap = std::make_shared<const MIPMap>(cached_texels(path, channels, encoding, float_texels), wrap, filter,
                                                 max_anisotropy);
    cache[key] = mipmap;
    return mipmap;
}

} // namespace

std::shared_ptr<const TexelImage> read_linear_texels(const std::string &path, int channels) {
    return cached_texels(path, channels, {Encoding::Linear});
}

ImageLookup read_image_lookup(TextureMapping2D mapping, const ParameterDictionary &params, int channels,
                              const SourceLocation &loc) {
    ImageLookup lookup;
    lookup.mapping = std::move(mapping);
    const std::string filename = params.get_one_string("filename", "");
    if (filename.empty()) throw InputError(loc, "imagemap: no \"filename\" given");
    const Encoding encoding = read_encoding(params);
    const std::string path = params.file_path("filename", filename);
    const std::string filter = params.get_one_string("filter", "bilinear");
    const FloatTexels float_texels =
        filter == "point" || filter == "ewa" || filter == "EWA" ? FloatTexels::FirstChannel : FloatTexels::AlphaOrMean;
    const std::string wrap_name = params.get_one_string("wrap", "repeat");
    ImageWrap wrap = ImageWrap::Repeat;
    if (wrap_name == "black") wrap = ImageWrap::Black;
    else if (wrap_name == "clamp") wrap = ImageWrap::Clamp;
    else if (wrap_name == "octahedralsphere") wrap = ImageWrap::OctahedralSphere;
    else if (wrap_name != "repeat")
        throw InputError(params.location("wrap"),
                         "\"wrap\" must be \"repeat\", \"black\", \"clamp\" or \"octahedralsphere\", not \"" +
                             wrap_name + "\"");
    MIPFilter mip_filter = MIPFilter::Bilinear;
    if (filter == "point") mip_filter = MIPFilter::Point;
    else if (filter == "trilinear") mip_filter = MIPFilter::Trilinear;
    else if (filter == "ewa" || filter == "EWA") mip_filter = MIPFilter::EWA;
    else if (filter != "bilinear")
        throw InputError(params.location("filter"),
                         "\"filter\" must be \"point\", \"bilinear\", \"trilinear\" or \"ewa\", not \"" + filter + "\"");
    const float max_anisotropy = params.get_one_float("maxanisotropy", 8);
    if (!(max_anisotropy >= 1) || !std::isfinite(max_anisotropy))
        throw InputError(params.location("maxanisotropy"), "\"maxanisotropy\" must be a finite number of at least 1");
    try {
        lookup.mipmap = cached_mipmap(path, channels, encoding, float_texels, wrap, mip_filter, max_anisotropy);
    } catch (const std::runtime_error &e) {
        throw InputError(params.location("filename"), e.what());
    }
    lookup.scale = params.get_one_float("scale", 1);
    if (!std::isfinite(lookup.scale)) throw InputError(params.location("scale"), "\"scale\" must be finite");
    lookup.invert = params.get_one_bool("invert", false);
    return lookup;
}

} // namespace caustica
