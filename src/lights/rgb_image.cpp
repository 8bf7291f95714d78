#include "lights/rgb_image.h"

#include "openimageio/openimageio_plugin.h"
#include "spectral/color.h"

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

}  // namespace caustica
