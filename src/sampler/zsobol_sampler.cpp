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

using DigitPermutation = std::array<uint8_t, 4>;

constexpr std::array<DigitPermutation, 24> make_digit_permutations() {
    std::array<DigitPermutation, 24> permutations{};
    DigitPermutation p{0, 1, 2, 3};
    for (DigitPermutation &q : permutations) {
        q = p;
        std::next_permutation(p.begin(), p.end());
    }
    return permutations;
}

// All permutations of a base-4 digit, for each quadtree node to pick one.
constexpr std::array<DigitPermutation, 24> DigitPermutations = make_digit_permutations();

// Spreads the 16 bits of v to the even bit positions.
uint32_t spread_bits(uint32_t v) {
    v = (v | (v << 8)) & 0x00ff00ffu;
    v = (v | (v << 4)) & 0x0f0f0f0fu;
    v = (v | (v << 2)) & 0x33333333u;
    v = (v | (v << 1)) & 0x55555555u;
    return v;
}

} // namespace

uint32_t morton_code(uint16_t x, uint16_t y) { return spread_bits(x) | (spread_bits(y) << 1); }

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
    if (morton != cached_morton_ || round_seed_ != cached_round_seed_) {
        cached_morton_ = morton;
        cached_round_seed_ = round_seed_;
        cached_dimensions_ = 0;
    }
}

namespace {

// Permutes the base-4 digits of `index` in bit positions [low, high), taken from the top (a
// last, single bit when high - low is odd), and returns them in place. `marked` is the whole
// index with a 1 above its top bit.
//
// A digit's quadtree node is numbered by the digits above it below that leading 1 (heap
// order), so nodes of different levels never share a hash input. One 64-bit hash at a node
// chooses the permutations of the node (bits 0-11) and of its four children (bits 12-23, ...,
// 48-59): one hash per two levels. A 12-bit value v picks permutation floor(24 v / 4096),
// which favours some of the 24 by at most 1/170; the digits stay a permutation either way.
uint64_t shuffle_digits(uint64_t index, uint64_t marked, int high, int low, uint64_t key) {
    constexpr uint32_t ChoiceBits = 12, ChoiceMask = (1u << ChoiceBits) - 1;
    uint64_t shuffled = 0, hash = 0;
    uint32_t parent_digit = 0;
    bool new_pair = true;
    for (int position = high; position > low; new_pair = !new_pair) {
        const int width = position - low >= 2 ? 2 : 1;
        position -= width;
        uint32_t random;
        if (new_pair) {
            hash = mix_bits((marked >> (position + width)) ^ key);
            random = uint32_t(hash) & ChoiceMask;
        } else {
            random = uint32_t(hash >> (ChoiceBits * (parent_digit + 1))) & ChoiceMask;
        }
        const uint32_t digit = uint32_t(index >> position) & ((1u << width) - 1);
        const uint32_t permuted = width == 2 ? DigitPermutations[(random * 24) >> ChoiceBits][digit]
                                             : digit ^ (random & 1);
        shuffled |= uint64_t(permuted) << position;
        parent_digit = digit;
    }
    return shuffled;
}

} // namespace

uint64_t ZSobolSampler::shuffled_index(uint64_t dimension_key) {
    // The index has MortonBits + k bits: each Morton level is one base-4 digit, then come the
    // digits of the sample index (for odd k the last is a single bit, permuted by a coin). The
    // Morton digits' permutation depends on nothing below them, so it is computed once per
    // pixel, round and dimension and reused by the pixel's other samples.
    const int bits = MortonBits + log2_samples_;
    const uint64_t marked = pixel_index_ | (uint64_t(1) << bits);
    uint64_t morton;
    const bool cacheable = dimension_ < uint64_t(CachedDimensions);
    if (cacheable && ((cached_dimensions_ >> dimension_) & 1)) {
        morton = uint64_t(shuffled_morton_[dimension_]) << log2_samples_;
    } else {
        morton = shuffle_digits(pixel_index_, marked, bits, log2_samples_, dimension_key);
        if (cacheable) {
            shuffled_morton_[dimension_] = uint32_t(morton >> log2_samples_);
            cached_dimensions_ |= uint64_t(1) << dimension_;
        }
    }
    return morton | shuffle_digits(pixel_index_, marked, log2_samples_, 0, dimension_key);
}

// The keys of a dimension (pair): one for the index permutation, and the scramble seeds of
// its two coordinates (randomize() hashes its seed again, so consecutive seeds are fine).
uint64_t ZSobolSampler::dimension_key() const {
    return mix_bits(round_seed_ + (dimension_ + 1) * 0x9e3779b97f4a7c15ull);
}

float ZSobolSampler::get_1d() {
    const uint64_t key = dimension_key();
    const uint64_t index = shuffled_index(key);
    ++dimension_;
    // Dimension 0 of the Sobol sequence: the index's bits in reverse order.
    const uint32_t bits = reverse_bits(uint32_t(index));
    return bits_to_unit_float(randomize(bits, randomization_, key + 1));
}

Vec2f ZSobolSampler::get_2d() {
    const uint64_t key = dimension_key();
    const uint64_t index = shuffled_index(key);
    dimension_ += 2;
    const uint32_t x = reverse_bits(uint32_t(index));
    const uint32_t y = sobol_second_dimension(index);
    return {bits_to_unit_float(randomize(x, randomization_, key + 1)),
            bits_to_unit_float(randomize(y, randomization_, key + 2))};
}

std::unique_ptr<Sampler> ZSobolSampler::clone() const { return std::make_unique<ZSobolSampler>(*this); }

} // namespace caustica
