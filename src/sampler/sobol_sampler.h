// The global Sobol sampler (pbrt-v4's "sobol"): one Sobol sequence over the whole image, in
// which a pixel's samples are the sequence points whose first two coordinates fall in that
// pixel (Gruenschloss, Raab and Keller 2012, "Enumerating quasi-Monte Carlo point sequences in
// elementary intervals"). The image plane is the unit square cut into 2^16 x 2^16 pixels (the
// resolution is not known when samplers are made; pixel coordinates enter modulo 2^16), so
// the pixel fixes the first 16 digits of both coordinates. As dimensions 0 and 1 form a
// (0,2)-sequence, each block of 2^32 consecutive points has exactly one point in every pixel:
// pixel sample i is the one in block i, whose index is found by solving a 16 x 16 linear
// system over GF(2) (SobolSampler's constructor inverts it once). The position within the
// pixel is the remaining digits of coordinates 0 and 1, unrandomised (a randomisation would
// move the point to another pixel); every other request reads its own higher Sobol dimension,
// randomised with one scramble per dimension for the whole image.
//
// Requests at sample dimension d (sampler.h's layout) read Sobol dimension d + 2, except the
// pixel position, which is always Sobol dimensions 0 and 1. The table has 64 dimensions
// (sobol_sequence.h); Sobol dimension s >= 64 reuses dimension 2 + (s - 2) mod 62 under an
// extra Owen scramble keyed by s, so that it is not a copy of the reused one: its values, each
// uniform, are a random nested permutation of the reused ones (a Latin-hypercube-like pairing,
// not a 2D net).
//
// Sample indices need no special case: sample i of a pixel is the point of block i, for every
// i up to 2^32 - 1, and the sequence simply continues.
#pragma once

#include "sampler/randomization.h"
#include "sampler/sampler.h"

#include <array>
#include <cstdint>

namespace caustica {

class SobolSampler final : public Sampler {
  public:
    SobolSampler(int samples_per_pixel, int seed, Randomization randomization);

    int samples_per_pixel() const override { return samples_per_pixel_; }
    void start_pixel_sample(Vec2i pixel, int sample_index, int dimension = 0) override;
    float get_1d() override;
    Vec2f get_2d() override;
    Vec2f get_pixel_2d() override;
    std::unique_ptr<Sampler> clone() const override;

    // The index of the Sobol point that is sample `sample_index` of `pixel`.
    uint64_t sequence_index(Vec2i pixel, int sample_index) const;

  private:
    float sample_dimension(uint64_t sobol_dimension) const;

    int samples_per_pixel_;
    int seed_;
    Randomization randomization_;
    // Column j: the index digits 16..31 that move the first 16 digits of coordinate 1 by the
    // unit vector j, i.e. the inverse of the system's matrix.
    std::array<uint32_t, 16> inverse_columns_{};
    uint64_t index_ = 0;
    uint64_t dimension_ = 0;
};

} // namespace caustica
