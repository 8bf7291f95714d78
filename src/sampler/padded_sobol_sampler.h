// Per-pixel Owen-scrambled Sobol samples padded to any dimension (pbrt-v4's "paddedsobol").
// Every 1D or 2D request draws from the first two Sobol dimensions, a (0,2)-sequence whose
// first spp points (a (0,2)-net when spp is a power of two) are well stratified in 1D and 2D.
// Each pixel and each dimension (pair) gets its own random order of those points (a hashed
// permutation, sample_hash.h) and its own scramble of their values, so different pairs of
// dimensions are uncorrelated, as if independent, and pixels are independent of each other
// (white-noise error across the image; "zsobol" correlates neighbours to make it blue).
//
// Sample indices beyond spp continue the Sobol sequence: index i of round r = i / spp uses the
// sequence point r * spp + pi_r(i mod spp), with pi_r the round's own permutation. Rounds
// therefore fill in the same scrambled sequence, and the first 2^m samples of a pixel remain a
// (0,m,2)-net whenever spp divides 2^m.
#pragma once

#include "sampler/randomization.h"
#include "sampler/sampler.h"

#include <cstdint>

namespace caustica {

class PaddedSobolSampler final : public Sampler {
  public:
    PaddedSobolSampler(int samples_per_pixel, int seed, Randomization randomization);

    int samples_per_pixel() const override { return samples_per_pixel_; }
    void start_pixel_sample(Vec2i pixel, int sample_index, int dimension = 0) override;
    float get_1d() override;
    Vec2f get_2d() override;
    Vec2f get_pixel_2d() override { return get_2d(); }
    std::unique_ptr<Sampler> clone() const override;

  private:
    uint64_t dimension_key() const;
    // The Sobol point index of the current sample in the dimension (pair) with this key.
    uint64_t sequence_index(uint64_t dimension_key) const;

    int samples_per_pixel_;
    int seed_;
    Randomization randomization_;
    uint64_t pixel_key_ = 0;  // hash of (pixel, seed)
    uint64_t round_ = 0;
    uint32_t index_in_round_ = 0;
    uint64_t dimension_ = 0;
};

} // namespace caustica
