// The OpenImageIO plugin itself: the only code that includes OpenImageIO (see
// openimageio/openimageio_plugin.h for why it is a separate shared library).
#include "openimageio/openimageio_plugin.h"

#include <OpenImageIO/imageio.h>

namespace caustica {
namespace {

std::string write_rgb8(const std::string &path, int width, int height, const uint8_t *rgb) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return OIIO::geterror();
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgb) || !out->close())
        return out->geterror();
    return {};
}

bool is_float_format(OIIO::TypeDesc t) {
    return t.basetype == OIIO::TypeDesc::FLOAT || t.basetype == OIIO::TypeDesc::HALF ||
           t.basetype == OIIO::TypeDesc::DOUBLE;
}

std::string read_image(const std::string &path, DecodedImage *image) {
    // Colours as stored, not multiplied by alpha, as pbrt-v4 reads them.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        std::string why = OIIO::geterror();
        return why.empty() ? "unreadable" : why;
    }
    const OIIO::ImageSpec &spec = in->spec();
    image->width = spec.width;
    image->height = spec.height;
    image->channels = spec.nchannels;
    image->channel_names = spec.channelnames;
    image->float_format = is_float_format(spec.format);
    image->color_space = spec.get_string_attribute("oiio:ColorSpace");
    image->pixels.resize(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image->pixels.data()))
        return in->geterror();
    return {};
}

const OpenImageIOPlugin functions{write_rgb8, read_image};

} // namespace
} // namespace caustica

extern "C" const caustica::OpenImageIOPlugin *caustica_openimageio_plugin() {
    return &caustica::functions;
}
