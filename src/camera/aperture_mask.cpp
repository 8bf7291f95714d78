#include "camera/aperture_mask.h"

#include "openimageio/openimageio_plugin.h"
#include "spectral/color.h"

#include <cmath>
#include <stdexcept>

namespace caustica {

namespace {

constexpr int BuiltinResolution = 256;

// Whether p lies inside the simple polygon (crossing number).
bool inside_polygon(const std::vector<Vec2f> &polygon, Vec2f p) {
    bool inside = false;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Vec2f a = polygon[i], b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside;
}

// A built-in shape sampled at the texel centres of a square image over [-1,1]^2. Row 0 holds
// y = +1 - 1/256: pbrt-v4 draws its shapes with y growing along the rows and then flips every
// aperture image, so a shape's top appears at the stop's -y.
template <typename Shape> std::vector<float> rasterize(Shape shape) {
    const int n = BuiltinResolution;
    std::vector<float> texels(size_t(n) * n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            texels[size_t(y) * n + x] = shape(Vec2f{-1 + 2 * (x + 0.5f) / n, 1 - 2 * (y + 0.5f) / n}, x, n - 1 - y);
    return texels;
}

} // namespace

ApertureMask::ApertureMask(int width, int height, std::vector<float> texels, bool clip_at_one)
    : width_(width), height_(height), texels_(std::move(texels)) {
    double sum = 0;
    for (float t : texels_) sum += t;
    const double mean = sum / double(texels_.size());
    if (!(mean > 0)) throw std::runtime_error("the aperture lets no light through (every texel is zero)");
    const float scale = float((Pi / 4) / mean);
    for (float &t : texels_) t = clip_at_one ? std::min(1.f, t * scale) : t * scale;
}

std::optional<ApertureMask> ApertureMask::builtin(const std::string &name) {
    const int n = BuiltinResolution;
    if (name == "gaussian")
        return ApertureMask(n, n, rasterize([](Vec2f p, int, int) {
                                return std::max(0.f, std::exp(-(p.x * p.x + p.y * p.y)) - std::exp(-1.f));
                            }));
    if (name == "square")
        // The middle half of the texels in each direction (pbrt-v4 writes 4 there; the
        // normalisation makes the value irrelevant).
        return ApertureMask(n, n, rasterize([n](Vec2f, int x, int y) {
                                const bool in = x >= n / 4 && x < 3 * n / 4 && y >= n / 4 && y < 3 * n / 4;
                                return in ? 1.f : 0.f;
                            }));
    if (name == "pentagon" || name == "star") {
        std::vector<Vec2f> polygon;
        if (name == "pentagon") {
            // A regular pentagon with a vertex at +y, scaled to 0.8 of the stop's radius.
            for (int i = 0; i < 5; ++i) {
                const float angle = Pi / 2 - 2 * Pi * float(i) / 5;
                polygon.push_back(Vec2f{std::cos(angle), std::sin(angle)} * 0.8f);
            }
        } else {
            // A five-pointed star: outer points on the unit circle at odd multiples of 36
            // degrees, inner corners between them on the circle through the pentagon's edges.
            const float inner = std::cos(2 * Pi / 5) / std::cos(Pi / 5);
            for (int i = 0; i < 10; ++i) {
                const float r = (i & 1) ? 1.f : inner, angle = Pi * float(i) / 5;
                polygon.push_back({r * std::cos(angle), r * std::sin(angle)});
            }
        }
        return ApertureMask(n, n, rasterize([&polygon](Vec2f p, int, int) {
                                return inside_polygon(polygon, p) ? 1.f : 0.f;
                            }));
    }
    return std::nullopt;
}

ApertureMask ApertureMask::from_image(const std::string &path) {
    const DecodedImage image = read_image_file(path);
    std::vector<int> channels;
    if (image.channels == 1) {
        channels = {0};
    } else {
        channels = {image.channel_index("R"), image.channel_index("G"), image.channel_index("B")};
        if (channels[0] < 0 || channels[1] < 0 || channels[2] < 0) {
            if (image.channels < 3)
                throw std::runtime_error("aperture image \"" + path + "\" has neither one channel nor R, G and B");
            channels = {0, 1, 2};
        }
    }
    const bool decode_srgb = !image.float_format && image.color_space != "Linear" && image.color_space != "linear";
    std::vector<float> texels(size_t(image.width) * image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            float sum = 0;
            for (int c : channels) {
                const float v = image.at(x, y, c);
                if (!std::isfinite(v) || v < 0)
                    throw std::runtime_error("aperture image \"" + path +
                                             "\" has negative, infinite or not-a-number pixel values");
                sum += decode_srgb ? srgb_to_linear(v) : v;
            }
            // The file's top row is the stop's +y (v = 1).
            texels[size_t(image.height - 1 - y) * image.width + x] = sum / float(channels.size());
        }
    try {
        // pbrt-v4 writes the normalised values back into the image's own pixel format, which
        // for 8- and 16-bit files clips them at 1: such a mask with less open area than the
        // round stop lets less light through. Kept, so that scenes render as in pbrt-v4.
        return ApertureMask(image.width, image.height, std::move(texels), !image.float_format);
    } catch (const std::runtime_error &e) {
        throw std::runtime_error("aperture image \"" + path + "\": " + e.what());
    }
}

float ApertureMask::texel(int x, int y) const {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return 0;
    return texels_[size_t(y) * width_ + x];
}

float ApertureMask::value(Vec2f uv) const {
    const float x = uv.x * float(width_) - 0.5f, y = uv.y * float(height_) - 0.5f;
    if (!(std::abs(x) < 1e7f && std::abs(y) < 1e7f)) return 0;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float dx = x - float(x0), dy = y - float(y0);
    return (1 - dx) * (1 - dy) * texel(x0, y0) + dx * (1 - dy) * texel(x0 + 1, y0) +
           (1 - dx) * dy * texel(x0, y0 + 1) + dx * dy * texel(x0 + 1, y0 + 1);
}

} // namespace caustica
