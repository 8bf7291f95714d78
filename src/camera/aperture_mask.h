// The shape of a realistic camera's aperture stop (pbrt-v4's "aperture" parameter): a greyscale
// transmission over the square that bounds the stop's circle, so that out-of-focus highlights
// (bokeh) take its shape. Built-in shapes or an image file; either way scaled so that its mean
// over the square is pi/4, the mean of the open circle, and it lets through as much light as the
// round stop it replaces (except where pbrt-v4 clips an integer-coded image, from_image).
#pragma once

#include "core/vecmath.h"

#include <optional>
#include <string>
#include <vector>

namespace caustica {

class ApertureMask {
  public:
    // "gaussian", "square", "pentagon" or "star", as pbrt-v4 draws them at 256x256; empty for
    // any other name.
    static std::optional<ApertureMask> builtin(const std::string &name);
    // The mean of R, G and B (or the only channel) of an image file, as linear values; as in
    // pbrt-v4, the scaled values of an 8- or 16-bit file are clipped at 1. Throws
    // std::runtime_error naming the file and the reason.
    static ApertureMask from_image(const std::string &path);

    // Transmission at uv in [0,1]^2 over the stop's bounding square (u along x, v along y),
    // bilinearly interpolated between texel centres and zero outside.
    float value(Vec2f uv) const;

  private:
    // Scales the texels to a mean of pi/4; clip_at_one then limits them to 1.
    ApertureMask(int width, int height, std::vector<float> texels, bool clip_at_one = false);
    float texel(int x, int y) const;
    int width_ = 0, height_ = 0;
    std::vector<float> texels_;  // row 0 at v = 0
};

} // namespace caustica
