// Jittered stratified sampling (pbrt-v4's "stratified" sampler): each dimension's unit
// interval (or, for 2D requests, the unit square as an x_samples by y_samples grid) is cut
// into samples_per_pixel strata, and the pixel's samples visit them in a pseudorandom order
// that differs per pixel and dimension (a hashed permutation, so no per-pixel tables and no
// correlation between dimensions). With jitter the sample lies uniformly within its stratum,
// otherwise at its centre.
#pragma once

#include "sampler/sampler.h"

#include <cstdint>

namespace caustica {

class StratifiedSampler final : public Sampler {
  public:
    StratifiedSampler(int x_samples, int y_samples, bool jitter, int seed);

    int samples_per_pixel() const override { return x_samples_ * y_samples_; }
    void start_pixel_sample(Vec2i pixel, int sample_index, int dimension = 0) override;
    float get_1d() override;
    Vec2f get_2d() override;
    Vec2f get_pixel_2d() override { return get_2d(); }
    std::unique_ptr<Sampler> clone() const override;

    int x_samples() const { return x_samples_; }
    int y_samples() const { return y_samples_; }

  private:
    // The stratum this sample occupies in the current dimension.
    int stratum();

    int x_samples_, y_samples_;
    bool jitter_;
    int seed_;
    Vec2i pixel_;
    int index_in_round_ = 0;  // sample index modulo samples_per_pixel()
    int round_ = 0;           // which pass over all strata (beyond spp: time-limited renders)
    uint64_t jitter_key_ = 0;
    uint64_t dimension_ = 0;
};

// Splits n samples into a grid of x by y = n strata that is as square as n allows, x >= y
// (pbrt-v4's rule for a sample count given on the command line).
Vec2i stratified_grid(int n);

} // namespace caustica
