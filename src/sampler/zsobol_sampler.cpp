#include "sampler/zsobol_sampler.h"

#include "core/rng.h"
#include "sampler/sobol_sequence.h"

#include <algorithm>
#include <array>
#include <bit>

namespace caustica {

namespace {

// Bits of the Morton code: 16 levels of the pixel quadtree.
constexpr int MortonBits = 32;

} // namespace

ZSobolSampler::ZSobolSampler(int samples_per_pixel, int seed, Randomization randomization)
    : samples_per_pixel_(samples_per_pixel),
      log2_samples_(std::bit_width(uint32_t(samples_per_pixel - 1))), seed_(seed),
      randomization_(randomization) {}

void ZSobolSampler::start_pixel_sample(Vec2i pixel, int sample_index, int dimension) {
    const uint64_t index = uint64_t(uint32_t(sample_index));
    const uint64_t round = index >> log2_samples_;
    const uint64_t in_round = index & ((uint64_t(1) << log2_samples_) - 1);
    // Coordinates modulo 2^16 (see the header).
    const uint32_t morton = morton_code(uint16_t(pixel.x), uint16_t(pixel.y));
    pixel_index_ = (uint64_t(morton) << log2_samples_) | in_round;
    round_seed_ = hash_values(seed_, round);
    dimension_ = uint64_t(dimension);
    // The caches hold the 64 dimensions from the multiple of 64 where this sample starts: a
    // camera path's from 0, a light path's from its own offset (vcm's 4096).
    const uint64_t base = dimension_ & ~uint64_t(CachedDimensions - 1);
    if (morton != cached_morton_ || round_seed_ != cached_round_seed_ || base != cache_base_) {
        cached_morton_ = morton;
        cached_round_seed_ = round_seed_;
        cached_dimensions_ = 0;
    }
    if (round_seed_ != keys_round_seed_ || base != cache_base_) {
        keys_round_seed_ = round_seed_;
        cached_keys_ = 0;
    }
    cache_base_ = base;
}

ZSobolSampler::DimensionKeys &ZSobolSampler::dimension_keys() {
    const uint64_t slot = dimension_ - cache_base_;
    const bool cacheable = slot < uint64_t(CachedDimensions);
    DimensionKeys &k = cacheable ? keys_[slot] : uncached_keys_;
    if (cacheable && ((cached_keys_ >> slot) & 1)) return k;
    k.key = dimension_key();
    k.block = ~uint64_t(0);
    if (randomization_ == Randomization::FastOwen) {
        k.x = fast_owen_keys(k.key + 1);
        k.y = fast_owen_keys(k.key + 2);
    }
    if (cacheable) cached_keys_ |= uint64_t(1) << slot;
    return k;
}

uint64_t ZSobolSampler::shuffled_index(DimensionKeys &keys) {
    // The index has MortonBits + k bits: each Morton level is one base-4 digit, then come the
    // digits of the sample index (for odd k the last is a single bit, permuted by a coin). The
    // Morton digits' permutation depends on nothing below them, so it is computed once per
    // pixel, round and dimension and reused by the pixel's other samples.
    const int bits = MortonBits + log2_samples_;
    const uint64_t marked = pixel_index_ | (uint64_t(1) << bits);
    uint64_t morton;
    const uint64_t slot = dimension_ - cache_base_;
    const bool cacheable = slot < uint64_t(CachedDimensions);
    if (cacheable && ((cached_dimensions_ >> slot) & 1)) {
        morton = uint64_t(shuffled_morton_[slot]) << log2_samples_;
    } else {
        // The digits above a 16 x 16 block of pixels (a whole number of digit pairs, so that
        // the two parts are shuffled as one call would shuffle them) are shared by its pixels,
        // which the renderer visits together.
        const int block_low = log2_samples_ + 8;
        const uint64_t block = marked >> block_low;
        if (block != keys.block) {
            keys.block = block;
            keys.shuffled_above_block = shuffle_digits(pixel_index_, marked, bits, block_low, keys.key);
        }
        morton = keys.shuffled_above_block | shuffle_digits(pixel_index_, marked, block_low, log2_samples_, keys.key);
        if (cacheable) {
            shuffled_morton_[slot] = uint32_t(morton >> log2_samples_);
            cached_dimensions_ |= uint64_t(1) << slot;
        }
    }
    return morton | shuffle_digits(pixel_index_, marked, log2_samples_, 0, keys.key);
}

// The keys of a dimension (pair): one for the index permutation, and the scramble seeds of
// its two coordinates (randomize() hashes its seed again, so consecutive seeds are fine).
uint64_t ZSobolSampler::dimension_key() const {
    return mix_bits(round_seed_ + (dimension_ + 1) * 0x9e3779b97f4a7c15ull);
}

float ZSobolSampler::get_1d() {
    DimensionKeys &k = dimension_keys();
    const uint64_t index = shuffled_index(k);
    ++dimension_;
    // Dimension 0 of the Sobol sequence: the index's bits in reverse order.
    const uint32_t bits = reverse_bits(uint32_t(index));
    return bits_to_unit_float(scramble(bits, k.x, k.key + 1));
}

Vec2f ZSobolSampler::get_2d() {
    DimensionKeys &k = dimension_keys();
    const uint64_t index = shuffled_index(k);
    dimension_ += 2;
    const uint32_t x = reverse_bits(uint32_t(index));
    const uint32_t y = sobol_second_dimension(index);
    return {bits_to_unit_float(scramble(x, k.x, k.key + 1)), bits_to_unit_float(scramble(y, k.y, k.key + 2))};
}

std::unique_ptr<Sampler> ZSobolSampler::clone() const { return std::make_unique<ZSobolSampler>(*this); }

} // namespace caustica
