#include "lights/rgb_image.h"

#include "openimageio/openimageio_plugin.h"
#include "spectral/color.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace caustica {

RGBImage read_rgb_image(const std::string &filename) {
    DecodedImage decoded = read_image_file(filename);
    int channel[3] = {decoded.channel_index("R"), decoded.channel_index("G"),
                      decoded.channel_index("B")};
    if (channel[0] < 0 || channel[1] < 0 || channel[2] < 0) {
        // Files without channel names (HDR, some TIFFs) list R, G, B first.
        if (decoded.channels < 3)
            throw std::runtime_error("image \"" + filename + "\" has no R, G and B channels");
        channel[0] = 0, channel[1] = 1, channel[2] = 2;
    }
    bool decode_srgb = !decoded.float_format && decoded.color_space != "Linear" &&
                       decoded.color_space != "linear";

    RGBImage image;
    image.width = decoded.width;
    image.height = decoded.height;
    image.pixels.resize(size_t(decoded.width) * decoded.height * 3);
    for (int y = 0; y < decoded.height; ++y)
        for (int x = 0; x < decoded.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float v = decoded.at(x, y, channel[c]);
                if (!std::isfinite(v))
                    throw std::runtime_error("image \"" + filename +
                                             "\" has infinite or not-a-number pixel values and "
                                             "so is not suitable as a light");
                image.at(x, y)[c] = decode_srgb ? srgb_to_linear(v) : v;
            }
    return image;
}

RGB RGBImage::bilerp(Vec2f st) const {
    const float x = st.x * float(width) - 0.5f, y = st.y * float(height) - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float dx = x - float(x0), dy = y - float(y0);
    auto texel = [&](int xi, int yi) {
        const float *p = at(std::clamp(xi, 0, width - 1), std::clamp(yi, 0, height - 1));
        return RGB{p[0], p[1], p[2]};
    };
    return texel(x0, y0) * ((1 - dx) * (1 - dy)) + texel(x0 + 1, y0) * (dx * (1 - dy)) +
           texel(x0, y0 + 1) * ((1 - dx) * dy) + texel(x0 + 1, y0 + 1) * (dx * dy);
}

RGB RGBImage::average() const {
    double sum[3] = {0, 0, 0};
    for (size_t i = 0; i < pixels.size(); ++i) sum[i % 3] += pixels[i];
    const double n = double(width) * double(height);
    return RGB{float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
}

}  // namespace caustica
