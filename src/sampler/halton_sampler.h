// pbrt-v4's "halton" sampler (pbrt-v4 section 8.6): dimension k of sample i is the radical
// inverse of a Halton index in the k-th prime base (Halton 1960). The first two dimensions, bases
// 2 and 3, cover the image: the sequence is scaled so that each pixel of a 2^j x 3^k tile
// (2^j, 3^k the first powers reaching min(resolution, 128)) owns every (2^j 3^k)-th index, found
// with the Chinese remainder theorem (Gruenschloss et al. 2012, "Enumerating quasi-Monte Carlo
// point sequences in elementary intervals"); those two dimensions give the position in the pixel
// and the rest are the integrator's, from base 5 on. Past the 1000th prime the dimensions start
// again at base 5, as in pbrt-v4.
//
// Randomization: "permutedigits" (pbrt-v4's default: each digit position of each base has its
// own random permutation of the digits, Faure 1992), "owen" (nested: the permutation of a digit
// also depends on the digits above it) or "none". Permutations are hashed (sample_hash.h), so no
// tables are stored. Sample indices beyond spp continue the sequence.
#pragma once

#include "sampler/randomization.h"
#include "sampler/sampler.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace caustica {

// The digit permutations of "permutedigits" for the first Halton dimensions, tabled once per
// seed (a path rarely needs more): entry [offset[d] + position * base + digit].
struct HaltonDigitPermutations {
    std::vector<uint32_t> offsets;
    std::vector<uint16_t> digits;
};

class HaltonSampler final : public Sampler {
  public:
    // `resolution` is the film's full resolution, which sets the pixel tile.
    HaltonSampler(int samples_per_pixel, Vec2i resolution, int seed, Randomization randomization);

    int samples_per_pixel() const override { return samples_per_pixel_; }
    void start_pixel_sample(Vec2i pixel, int sample_index, int dimension = 0) override;
    float get_1d() override;
    Vec2f get_2d() override;
    Vec2f get_pixel_2d() override;
    std::unique_ptr<Sampler> clone() const override;

  private:
    // Halton dimension (index into the primes) of the sampler's dimension d.
    static int halton_dimension(uint64_t d);
    float sample_dimension(int halton_dimension, uint64_t index) const;

    int samples_per_pixel_;
    uint64_t seed_;
    Randomization randomization_;
    int base_exponents_[2];
    uint64_t base_scales_[2];
    uint64_t multiplicative_inverses_[2];
    std::shared_ptr<const HaltonDigitPermutations> tables_;
    uint64_t halton_index_ = 0;
    uint64_t dimension_ = 0;
};

} // namespace caustica
