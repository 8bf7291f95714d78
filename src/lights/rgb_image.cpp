#include "lights/rgb_image.h"

#include <OpenImageIO/imageio.h>
#include <cmath>
#include <stdexcept>

namespace caustica {

namespace {

// IEC 61966-2-1 sRGB decoding.
float srgb_to_linear(float v) {
    if (v <= 0.04045f) return v / 12.92f;
    return std::pow((v + 0.055f) / 1.055f, 2.4f);
}

bool is_float_format(OIIO::TypeDesc t) {
    return t.basetype == OIIO::TypeDesc::FLOAT || t.basetype == OIIO::TypeDesc::HALF ||
           t.basetype == OIIO::TypeDesc::DOUBLE;
}

}  // namespace

RGBImage read_rgb_image(const std::string &filename) {
    auto in = OIIO::ImageInput::open(filename);
    if (!in) {
        std::string why = OIIO::geterror();
        throw std::runtime_error("cannot read image \"" + filename + "\"" +
                                 (why.empty() ? "" : ": " + why));
    }
    const OIIO::ImageSpec &spec = in->spec();
    int nc = spec.nchannels;
    int channel[3] = {spec.channelindex("R"), spec.channelindex("G"), spec.channelindex("B")};
    if (channel[0] < 0 || channel[1] < 0 || channel[2] < 0) {
        // Files without channel names (PNG, JPEG, HDR) list R, G, B first.
        if (nc < 3)
            throw std::runtime_error("image \"" + filename + "\" has no R, G and B channels");
        channel[0] = 0, channel[1] = 1, channel[2] = 2;
    }
    std::vector<float> data(size_t(spec.width) * spec.height * nc);
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, data.data()))
        throw std::runtime_error("cannot read image \"" + filename + "\": " + in->geterror());
    std::string color_space = spec.get_string_attribute("oiio:ColorSpace");
    bool decode_srgb =
        !is_float_format(spec.format) && color_space != "Linear" && color_space != "linear";

    RGBImage image;
    image.width = spec.width;
    image.height = spec.height;
    image.pixels.resize(size_t(spec.width) * spec.height * 3);
    for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i)
        for (int c = 0; c < 3; ++c) {
            float v = data[i * nc + channel[c]];
            if (!std::isfinite(v))
                throw std::runtime_error("image \"" + filename +
                                         "\" has infinite or not-a-number pixel values and so is "
                                         "not suitable as a light");
            image.pixels[i * 3 + c] = decode_srgb ? srgb_to_linear(v) : v;
        }
    return image;
}

}  // namespace caustica
