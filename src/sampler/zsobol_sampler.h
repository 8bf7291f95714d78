// Owen-scrambled Sobol samples with screen-space blue-noise error (pbrt-v4's "zsobol", its
// default sampler), after Ahmed and Wonka 2020, "Screen-space blue-noise diffusion of Monte
// Carlo sampling error via hierarchical ordering of pixels".
//
// The pixels are ordered along a Morton (Z) curve and pixel m takes the samples
// m * 2^k ... (m + 1) * 2^k - 1 of a 2D (0,2)-sequence (Sobol dimensions 0 and 1), 2^k >= spp.
// Each aligned 2^j x 2^j block of pixels then owns an aligned block of 4^j * 2^k consecutive
// samples, which is a (0,2)-net: the block's pixels share one well-stratified point set, so
// their errors are negatively correlated and the remaining error is pushed to high screen-space
// frequencies (blue noise). To break the Z curve's regular structure, every level of the
// quadtree permutes its four children at random: base-4 digit j of the index (a Morton level,
// or a pair of sample-index bits) is permuted by one of the 24 permutations of {0,1,2,3},
// chosen by a hash of the digits above it, which is a nested uniform scramble of the index in
// base 4. Every dimension (pair) hashes its own permutations and its own scramble of the
// values (randomization.h; one per dimension for the whole image, as in pbrt-v4), which pads
// the 2D sequence to any number of dimensions with the sample order of each pair decorrelated
// from the others.
//
// Pixel coordinates enter modulo 2^16 (16 Morton levels: pixels 65536 apart would share their
// samples), since samplers are made before the resolution is known; the levels above the image
// are permuted like any other and only relabel which part of the sequence the image uses.
//
// Sample indices beyond 2^k: index i is sample i mod 2^k of round i / 2^k, and every round is
// the same construction with the seed hashed with the round number, so rounds are independent
// randomisations and an unbiased estimate continues to converge.
#pragma once

#include "sampler/quadtree_shuffle.h"
#include "sampler/randomization.h"
#include "sampler/sampler.h"

#include <array>
#include <cstdint>

namespace caustica {

class ZSobolSampler final : public Sampler {
  public:
    ZSobolSampler(int samples_per_pixel, int seed, Randomization randomization);

    int samples_per_pixel() const override { return samples_per_pixel_; }
    void start_pixel_sample(Vec2i pixel, int sample_index, int dimension = 0) override;
    float get_1d() override;
    Vec2f get_2d() override;
    Vec2f get_pixel_2d() override { return get_2d(); }
    std::unique_ptr<Sampler> clone() const override;

  private:
    // The keys of the current dimension (pair): that of its index permutation and scramble, and
    // for fastowen its coordinates' scramble constants, which depend on the round alone.
    struct DimensionKeys {
        uint64_t key;
        FastOwenKeys x, y;
        // The permuted Morton digits above the last 16 x 16 block of pixels seen (block: the
        // index above that block's digits, ~0 for none), which the block's pixels share.
        uint64_t block = ~uint64_t(0);
        uint64_t shuffled_above_block = 0;
    };
    DimensionKeys &dimension_keys();
    uint32_t scramble(uint32_t bits, const FastOwenKeys &fast, uint64_t seed) const {
        return randomization_ == Randomization::FastOwen ? fast_owen_scramble(bits, fast)
                                                         : randomize(bits, randomization_, seed);
    }
    uint64_t dimension_key() const;
    // The sequence index of the current sample for the current dimension (pair), whose keys
    // are given.
    uint64_t shuffled_index(DimensionKeys &keys);

    static constexpr int CachedDimensions = 64;

    int samples_per_pixel_;
    int log2_samples_;          // k: 2^k >= samples_per_pixel
    int seed_;
    Randomization randomization_;
    uint64_t pixel_index_ = 0;  // Morton code of the pixel, then the sample within the round
    uint64_t round_seed_ = 0;
    uint64_t dimension_ = 0;
    // The caches below hold dimensions cache_base_ .. cache_base_ + 63 (slot d: dimension
    // cache_base_ + d). The permuted Morton digits for one pixel and round (bit d of
    // cached_dimensions_ set: slot d is valid), since a pixel's samples share them.
    uint32_t cached_morton_ = 0;
    uint64_t cached_round_seed_ = 0;
    uint64_t cached_dimensions_ = 0;
    std::array<uint32_t, CachedDimensions> shuffled_morton_{};
    // The dimensions' keys for the round of keys_round_seed_ (bit d of cached_keys_ set: slot d
    // is valid); a dimension outside the slots has its keys made afresh in uncached_keys_.
    std::array<DimensionKeys, CachedDimensions> keys_{};
    uint64_t cached_keys_ = 0;
    uint64_t keys_round_seed_ = 0;
    DimensionKeys uncached_keys_{};
    uint64_t cache_base_ = 0;
};

} // namespace caustica
