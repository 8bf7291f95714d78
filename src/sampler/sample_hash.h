// The counter-based generator behind the samplers: a uniform value in [0, 1) that is a pure
// function of (key, dimension). A splitmix-style finaliser of the key offset by the dimension
// times the golden-ratio increment (Steele et al. 2014, "Fast Splittable Pseudorandom Number
// Generators") gives independent, well-mixed values per dimension, and lets a sample's
// sequence start at any dimension without stepping through the earlier ones (which a
// sequential generator such as Rng would have to do).
#pragma once

#include "core/rng.h"

namespace caustica {

inline float sample_hash_uniform(uint64_t key, uint64_t dimension) {
    uint64_t bits = mix_bits(key + (dimension + 1) * 0x9e3779b97f4a7c15ULL);
    // The top 32 bits, scaled as Rng::uniform() does.
    return std::min(OneMinusEpsilon, float(uint32_t(bits >> 32)) * 0x1p-32f);
}

// A pseudorandom permutation of {0, ..., n-1} selected by seed, evaluated one element at a
// time in O(1) expected work (the idea of Kensler 2013, "Correlated Multi-Jittered Sampling",
// section 3): a keyed bijection on the k-bit integers, with 2^k the smallest power of two
// >= n, applied repeatedly ("cycle walking") until the value falls below n. Restricting a
// bijection this way yields a bijection of {0, ..., n-1}; as 2^k < 2n, fewer than two steps
// are needed on average.
uint32_t permutation_element(uint32_t index, uint32_t n, uint64_t seed);

} // namespace caustica
