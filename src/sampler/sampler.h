// Sample generators. A sampler is a value owned by one thread; start_pixel_sample() makes the
// sequence a pure function of (pixel, sample index, seed), so images do not depend on threads.
//
// Dimension layout (what the n-th request after start_pixel_sample returns), shared by every
// sampler and by every integrator that renders from the camera:
//   dimension 0      get_1d()        hero wavelength (sample_wavelengths, tile_renderer.h)
//   dimensions 1-2   get_pixel_2d()  position within the pixel (through the filter's sampler)
//   dimensions 3-4   get_2d()        lens position (thin-lens depth of field)
//   dimension 5      get_1d()        the time within the shutter, only when geometry moves
//   dimensions 5...  integrator      path vertices, in the order the integrator requests them
//                                    (6... with moving geometry)
// get_camera_sample() (film/film.h) consumes dimensions 1-4 (1-5 with moving geometry). Every get_1d() advances the
// dimension by one and every get_2d() / get_pixel_2d() by two, so start_pixel_sample(p, i, d)
// continues a sample's sequence exactly where the d-th value would have come.
#pragma once

#include "core/vecmath.h"

#include <memory>

namespace caustica {

// Cache-line aligned (and so padded to whole lines): a sampler's state changes with every value it
// draws, and a line it shared with scene data read by another thread would bounce between cores.
class alignas(64) Sampler {
  public:
    virtual ~Sampler() = default;
    virtual int samples_per_pixel() const = 0;
    // Sample indices beyond samples_per_pixel() are valid (time-limited and progressive
    // renders keep going) and keep every value uniform: independent, stratified and zsobol
    // start new, independently randomised rounds of their pattern; paddedsobol and sobol
    // continue their Sobol sequence.
    virtual void start_pixel_sample(Vec2i pixel, int sample_index, int dimension = 0) = 0;
    virtual float get_1d() = 0;
    virtual Vec2f get_2d() = 0;
    // The 2D sample used for the position within the pixel (film plane).
    virtual Vec2f get_pixel_2d() = 0;
    virtual std::unique_ptr<Sampler> clone() const = 0;
};

} // namespace caustica
