#include "sampler/quadtree_shuffle.h"

#include "core/rng.h"

#include <algorithm>
#include <array>

namespace caustica {

namespace {

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

// A digit's quadtree node is numbered by the digits above it below the leading 1 of `marked`
// (heap order), so nodes of different levels never share a hash input. One 64-bit hash at a
// node chooses the permutations of the node (bits 0-11) and of its four children (bits 12-23,
// ..., 48-59): one hash per two levels. A 12-bit value v picks permutation floor(24 v / 4096),
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

} // namespace caustica
