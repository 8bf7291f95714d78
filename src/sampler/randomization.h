// Randomisations of base-2 digital nets (pbrt-v4's "randomization" sampler parameter). A Sobol
// point's coordinate is a 32-bit binary fraction; each randomisation maps it to another one so
// that every point is uniform on [0, 1) while the net's stratification survives:
//   none           the points themselves (deterministic).
//   permutedigits  a random digital shift: every binary digit position is flipped or not, the
//                  same way for all points (Matousek 1998, "On the L2-discrepancy for anchored
//                  boxes", random linear scrambling without the matrix part).
//   owen           nested uniform scrambling (Owen 1995, "Randomly permuted (t,m,s)-nets and
//                  (t,s)-sequences"): digit k is flipped or not by a coin that depends on the
//                  digits above it, so each node of the binary tree of intervals gets its own
//                  coin. The coins are bits of hashes of (seed, node), so no tree is stored.
//                  The first 24 digits are scrambled, all that a float keeps.
//   fastowen       the same nesting structure, with the coins produced by a few invertible
//                  integer operations on the bit-reversed value (the construction of Laine and
//                  Karras 2011, "Stratified sampling for stochastic transparency", as used by
//                  Burley 2020, "Practical hash-based Owen scrambling"): cheaper, less random.
// Each keeps elementary intervals intact as sets: two values that share their first k binary
// digits map to two values that share exactly their first k digits, so a (t,m,s)-net stays one.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace caustica {

enum class Randomization { None, PermuteDigits, FastOwen, Owen };

// pbrt's names: "none", "permutedigits", "fastowen", "owen"; nullopt for anything else.
std::optional<Randomization> parse_randomization(const std::string &name);

inline uint32_t reverse_bits(uint32_t v) {
    v = (v << 16) | (v >> 16);
    v = ((v & 0x00ff00ffu) << 8) | ((v & 0xff00ff00u) >> 8);
    v = ((v & 0x0f0f0f0fu) << 4) | ((v & 0xf0f0f0f0u) >> 4);
    v = ((v & 0x33333333u) << 2) | ((v & 0xccccccccu) >> 2);
    v = ((v & 0x55555555u) << 1) | ((v & 0xaaaaaaaau) >> 1);
    return v;
}

uint32_t owen_scramble(uint32_t bits, uint64_t seed);

// The constants that a seed gives the fast Owen scramble, which a sampler can keep for every value
// it scrambles with that seed.
struct FastOwenKeys {
    uint32_t add0, multiply0, add1, multiply1;
};
FastOwenKeys fast_owen_keys(uint64_t seed);
uint32_t fast_owen_scramble(uint32_t bits, const FastOwenKeys &keys);
inline uint32_t fast_owen_scramble(uint32_t bits, uint64_t seed) {
    return fast_owen_scramble(bits, fast_owen_keys(seed));
}
uint32_t randomize(uint32_t bits, Randomization randomization, uint64_t seed);

// A 32-bit binary fraction as a float in [0, 1). The value is truncated to float's 24-bit
// significand first, so the conversion is exact: rounding to nearest could carry a value up to
// the next multiple of 2^-k and move it out of its elementary interval (or up to 1).
inline float bits_to_unit_float(uint32_t bits) { return float(bits >> 8) * 0x1p-24f; }

} // namespace caustica
