#include "sampler/randomization.h"

#include "core/rng.h"

namespace caustica {

std::optional<Randomization> parse_randomization(const std::string &name) {
    if (name == "none") return Randomization::None;
    if (name == "permutedigits") return Randomization::PermuteDigits;
    if (name == "fastowen") return Randomization::FastOwen;
    if (name == "owen") return Randomization::Owen;
    return std::nullopt;
}

uint32_t owen_scramble(uint32_t bits, uint64_t seed) {
    // Digit k (k = 0 is the most significant) belongs to the tree node reached by digits
    // 0..k-1, and each node needs its own fair coin. A node is numbered by its digits below a
    // leading 1 (heap order: the root is 1, its children 2 and 3, ...), so nodes of different
    // depths never share a number. One 64-bit hash of (seed, node) at every sixth level holds
    // the coins of that node's whole subtree of depth 6 (63 nodes, bit j for heap number j
    // within the subtree): 4 hashes scramble 24 digits instead of 24 hashes. The digits past
    // the 24th are left as they are, since floats keep 24 (bits_to_unit_float).
    constexpr int GroupDepth = 6, ScrambledDigits = 24;
    const uint64_t key = mix_bits(seed);
    const uint64_t marked = uint64_t(bits) | (uint64_t(1) << 32);
    uint32_t flips = 0;
    for (int first = 0; first < ScrambledDigits; first += GroupDepth) {
        const uint64_t coins = mix_bits((marked >> (32 - first)) ^ key);
        for (int r = 0; r < GroupDepth; ++r) {
            // Digits first..first+r-1 below a leading 1: the node within the subtree.
            const uint64_t node = ((uint64_t(bits) >> (32 - first - r)) & ((1u << r) - 1)) | (1u << r);
            flips |= uint32_t((coins >> node) & 1) << (31 - first - r);
        }
    }
    return bits ^ flips;
}

FastOwenKeys fast_owen_keys(uint64_t seed) {
    const uint64_t key0 = mix_bits(seed), key1 = mix_bits(key0);
    return {uint32_t(key0), uint32_t(key0 >> 32) | 1u, uint32_t(key1), uint32_t(key1 >> 32) | 1u};
}

uint32_t fast_owen_scramble(uint32_t bits, const FastOwenKeys &keys) {
    // After bit reversal the most significant digit is bit 0, and the nested structure asks
    // that output bit i be input bit i xor a function of bits 0..i-1 only. Adding a constant,
    // multiplying by an odd constant and x ^= x * (even constant) all have that form (carries
    // and products only move information towards higher bits) and are bijections. The seed
    // picks the added constants and the odd multipliers; the fixed even multipliers (= 2 mod 4,
    // so that each product reaches the very next bit) spread every bit's influence over all
    // higher ones. Measured over 4000 seeds, the coins of two values that part at digit k are
    // uncorrelated at every later digit to within the sampling noise, as exact Owen
    // scrambling's are; with fixed multipliers only and the seed merely added, they were not
    // (correlation 0.26 between the coins of digit 2 for values parting at digit 0).
    uint32_t x = reverse_bits(bits);
    x += keys.add0;
    x *= keys.multiply0;
    x ^= x * 0x85ebca6au;
    x += keys.add1;
    x *= keys.multiply1;
    x ^= x * 0xc2b2ae36u;
    x ^= x * 0x27d4eb2eu;
    return reverse_bits(x);
}

uint32_t randomize(uint32_t bits, Randomization randomization, uint64_t seed) {
    switch (randomization) {
    case Randomization::None: return bits;
    case Randomization::PermuteDigits: return bits ^ uint32_t(mix_bits(seed));
    case Randomization::FastOwen: return fast_owen_scramble(bits, seed);
    case Randomization::Owen: return owen_scramble(bits, seed);
    }
    return bits;
}

} // namespace caustica
