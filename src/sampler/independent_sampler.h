// Uniform random samples with no correlation between samples or dimensions (pbrt-v4's
// "independent" sampler): the baseline every other sampler must agree with in expectation.
#pragma once

#include "sampler/sampler.h"

#include <cstdint>

namespace caustica {

class IndependentSampler final : public Sampler {
  public:
    IndependentSampler(int samples_per_pixel, int seed);

    int samples_per_pixel() const override { return samples_per_pixel_; }
    void start_pixel_sample(Vec2i pixel, int sample_index, int dimension = 0) override;
    float get_1d() override;
    Vec2f get_2d() override;
    Vec2f get_pixel_2d() override { return get_2d(); }
    std::unique_ptr<Sampler> clone() const override;

  private:
    int samples_per_pixel_;
    int seed_;
    uint64_t key_ = 0;      // hash of (pixel, sample index, seed)
    uint64_t dimension_ = 0;
};

} // namespace caustica
