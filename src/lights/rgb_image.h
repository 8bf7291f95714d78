// Linear RGB images for lights that read emission from a file (environment maps).
#pragma once

#include "core/vecmath.h"
#include "spectral/color.h"

#include <string>
#include <vector>

namespace caustica {

struct RGBImage {
    int width = 0, height = 0;
    std::vector<float> pixels;  // 3 floats per pixel, rows from the top of the image down

    const float *at(int x, int y) const { return &pixels[3 * (size_t(y) * width + x)]; }
    float *at(int x, int y) { return &pixels[3 * (size_t(y) * width + x)]; }
    // Bilinear interpolation at st in [0, 1]^2 (s to the right, t down, pixel centres at
    // half-integers over the resolution), clamped at the edges, as pbrt-v4's Image::Bilerp.
    RGB bilerp(Vec2f st) const;
    // The mean of every pixel.
    RGB average() const;
};

// Reads R, G and B through the OpenImageIO plugin as linear floats: integer-coded files (PNG, JPEG, ...) are
// decoded from sRGB unless they declare themselves linear, as pbrt-v4 does. Throws
// std::runtime_error with a reason (unreadable file, no R/G/B channels, NaN or infinite values).
RGBImage read_rgb_image(const std::string &filename);

}  // namespace caustica
