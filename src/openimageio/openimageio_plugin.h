// OpenImageIO as a plugin (libcaustica_openimageio.so), loaded on first use rather than linked
// into the executable. Debian's OpenImageIO pulls in about 260 shared libraries, and loading and
// initialising them takes 0.26 s at every start of a process: a third of a 16-sample Cornell box
// render and most of the run time of every test that starts the command. Only PNG output and
// lights that read image files need it; EXR goes through OpenEXR directly (film/image_io.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace caustica {

// An image file's pixels as floats with all channels interleaved, rows from the top down.
struct DecodedImage {
    int width = 0, height = 0, channels = 0;
    std::vector<std::string> channel_names;  // as stored; unnamed formats (PNG) report R, G, B, A
    bool float_format = false;               // stored as half, float or double
    std::string color_space;                 // OpenImageIO's "oiio:ColorSpace" attribute
    std::vector<float> pixels;

    int channel_index(const std::string &name) const;  // -1 if there is no such channel
    float at(int x, int y, int channel) const {
        return pixels[(size_t(y) * width + x) * channels + channel];
    }
};

// The plugin's functions. Each returns an empty string on success and the reason otherwise.
struct OpenImageIOPlugin {
    // 8-bit RGB, tagged sRGB; the format follows the file name's extension.
    std::string (*write_rgb8)(const std::string &path, int width, int height, const uint8_t *rgb);
    std::string (*read_image)(const std::string &path, DecodedImage *image);
};

// Loads the plugin on first call (thread-safe). Throws std::runtime_error saying where it looked
// and why loading failed.
const OpenImageIOPlugin &openimageio();

// Reads a whole image through the plugin; throws std::runtime_error naming the file and reason.
DecodedImage read_image_file(const std::string &path);

} // namespace caustica

// The plugin's only exported symbol.
extern "C" const caustica::OpenImageIOPlugin *caustica_openimageio_plugin();
