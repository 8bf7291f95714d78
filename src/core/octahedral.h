// Unit vectors packed into integers with the octahedral map (Cigolle et al. 2014, "A survey of
// efficient representations for independent unit vectors"): the sphere is projected onto the
// octahedron |x| + |y| + |z| = 1, the lower half folded over the upper, and the resulting
// square quantised to a fixed number of bits per axis.
//
// Two precisions: 16 bits per axis (32 in all) for directions that BSDFs are evaluated in,
// worst-case angular error about 1e-4 radians; 8 bits per axis (16 in all) for normals that are
// only compared against a coarse threshold (photon_side.h), worst case about 0.017 radians (one
// degree).
#pragma once

#include "core/vecmath.h"

#include <cmath>
#include <cstdint>

namespace caustica {

namespace octahedral_detail {
inline float sign_not_zero(float v) { return v < 0 ? -1.f : 1.f; }

// The lower half of the octahedron reflected over the diagonals onto the upper half's square,
// and back: the same map both ways.
inline void fold(float &x, float &y) {
    float fx = (1 - std::abs(y)) * sign_not_zero(x);
    float fy = (1 - std::abs(x)) * sign_not_zero(y);
    x = fx;
    y = fy;
}

template <int Bits> uint32_t quantise(float v) {
    constexpr float levels = float((1u << Bits) - 1);
    return uint32_t(std::lround((std::clamp(v, -1.f, 1.f) * 0.5f + 0.5f) * levels));
}
template <int Bits> float dequantise(uint32_t q) {
    constexpr float levels = float((1u << Bits) - 1);
    return float(q) / levels * 2 - 1;
}

template <int Bits> uint32_t encode(Vec3f v) {
    float l1 = std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
    float x = v.x / l1, y = v.y / l1;
    if (v.z < 0) fold(x, y);
    return quantise<Bits>(x) | (quantise<Bits>(y) << Bits);
}

template <int Bits> Vec3f decode(uint32_t packed) {
    constexpr uint32_t mask = (1u << Bits) - 1;
    float x = dequantise<Bits>(packed & mask), y = dequantise<Bits>(packed >> Bits);
    float z = 1 - std::abs(x) - std::abs(y);
    if (z < 0) fold(x, y);
    return normalize(Vec3f(x, y, z));
}
} // namespace octahedral_detail

inline uint32_t encode_octahedral(Vec3f v) { return octahedral_detail::encode<16>(v); }
inline Vec3f decode_octahedral(uint32_t packed) { return octahedral_detail::decode<16>(packed); }

inline uint16_t encode_octahedral_coarse(Vec3f v) { return uint16_t(octahedral_detail::encode<8>(v)); }
inline Vec3f decode_octahedral_coarse(uint16_t packed) { return octahedral_detail::decode<8>(packed); }

} // namespace caustica
