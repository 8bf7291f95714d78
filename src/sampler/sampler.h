// Sample generators. A sampler is a value owned by one thread; start_pixel_sample() makes the
// sequence a pure function of (pixel, sample index, seed), so images do not depend on threads.
#pragma once

#include "core/vecmath.h"

#include <memory>

namespace caustica {

class Sampler {
  public:
    virtual ~Sampler() = default;
    virtual int samples_per_pixel() const = 0;
    virtual void start_pixel_sample(Vec2i pixel, int sample_index, int dimension = 0) = 0;
    virtual float get_1d() = 0;
    virtual Vec2f get_2d() = 0;
    // The 2D sample used for the position within the pixel (film plane).
    virtual Vec2f get_pixel_2d() = 0;
    virtual std::unique_ptr<Sampler> clone() const = 0;
};

} // namespace caustica
