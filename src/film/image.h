// An RGB image in linear floating point: what the film produces and the image files hold.
#pragma once

#include "core/vecmath.h"

#include <cstddef>
#include <string>
#include <vector>

namespace caustica {

struct Image {
    int width = 0, height = 0;
    // Where the image lies within the full frame and the frame's size: a crop window renders
    // part of a frame (OpenEXR's data window within its display window). An uncropped image has
    // origin (0, 0) and full_resolution (width, height).
    Vec2i origin{0, 0};
    Vec2i full_resolution{0, 0};
    // Three floats (R, G, B) per pixel, rows from the top of the image down.
    std::vector<float> rgb;
    // Extra RGB layers with the same layout (e.g. "variance"), written to EXR as NAME.R/G/B.
    struct Layer {
        std::string name;
        std::vector<float> rgb;
    };
    std::vector<Layer> layers;
    // Single channels under their own names (a spectral film's "S0.550,000nm", a G-buffer's
    // "P.X" or "u"), one float per pixel in the same order.
    struct Channel {
        std::string name;
        std::vector<float> values;
    };
    std::vector<Channel> channels;
    const Channel *channel(const std::string &name) const {
        for (const Channel &c : channels)
            if (c.name == name) return &c;
        return nullptr;
    }

    Image() = default;
    Image(int w, int h) : width(w), height(h), full_resolution{w, h}, rgb(size_t(w) * h * 3, 0.f) {}

    float &at(int x, int y, int c) { return rgb[(size_t(y) * width + x) * 3 + c]; }
    float at(int x, int y, int c) const { return rgb[(size_t(y) * width + x) * 3 + c]; }
};

} // namespace caustica
