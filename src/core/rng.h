// PCG32 random number generator (O'Neill 2014) and integer hashing used to derive independent,
// reproducible streams per pixel and sample, so images do not depend on the thread count.
#pragma once

#include "core/vecmath.h"

#include <cstdint>
#include <cstring>

namespace caustica {

// 64-bit finaliser from MurmurHash3 / splitmix: a bijection with good avalanche.
inline uint64_t mix_bits(uint64_t v) {
    v ^= v >> 31;
    v *= 0x7fb5d329728ea185ULL;
    v ^= v >> 27;
    v *= 0x81dadef4bc2dd44dULL;
    v ^= v >> 33;
    return v;
}

template <typename... Args> uint64_t hash_values(Args... args) {
    uint64_t h = 0x9e3779b97f4a7c15ULL;
    ((h = mix_bits(h ^ (uint64_t(args) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)))), ...);
    return h;
}

class Rng {
  public:
    Rng() = default;
    Rng(uint64_t sequence, uint64_t seed) { set_sequence(sequence, seed); }
    void set_sequence(uint64_t sequence, uint64_t seed) {
        state_ = 0;
        inc_ = (sequence << 1u) | 1u;
        next_uint32();
        state_ += seed;
        next_uint32();
    }
    uint32_t next_uint32() {
        uint64_t old = state_;
        state_ = old * 0x5851f42d4c957f2dULL + inc_;
        uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
    }
    // Uniform in [0, 1).
    float uniform() { return std::min(OneMinusEpsilon, float(next_uint32()) * 0x1p-32f); }
    Vec2f uniform2() { float a = uniform(); return {a, uniform()}; }

  private:
    uint64_t state_ = 0x853c49e6748fea9bULL;
    uint64_t inc_ = 0xda3e39cb94b95bdbULL;
};

} // namespace caustica
