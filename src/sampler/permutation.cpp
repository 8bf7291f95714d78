#include "sampler/sample_hash.h"

#include <bit>

namespace caustica {

uint32_t permutation_element(uint32_t index, uint32_t n, uint64_t seed) {
    if (n <= 1) return 0;
    const int bits = std::bit_width(n - 1);
    const uint32_t mask = (bits >= 32) ? ~0u : ((1u << bits) - 1);
    const int shift = (bits + 1) / 2;
    // Three rounds of bijections on k-bit values: xor with a key, multiplication by an odd
    // key (invertible modulo 2^k) and a right xorshift (invertible: the high bits it reads
    // are unchanged by it). Keys come from the seed so each seed picks its own permutation.
    uint32_t keys[6];
    for (int i = 0; i < 3; ++i) {
        uint64_t h = mix_bits(seed + uint64_t(i) * 0x632be59bd9b4e019ULL);
        keys[2 * i] = uint32_t(h);
        keys[2 * i + 1] = uint32_t(h >> 32);
    }
    uint32_t v = index;
    do {
        for (int round = 0; round < 3; ++round) {
            v ^= keys[2 * round] & mask;
            v = (v * (keys[2 * round + 1] | 1u)) & mask;
            v ^= v >> shift;
        }
    } while (v >= n);
    return v;
}

} // namespace caustica
