// Unit vectors packed into 32 bits with the octahedral map (Cigolle et al. 2014, "A survey of
// efficient representations for independent unit vectors"): the sphere is projected onto the
// octahedron |x| + |y| + |z| = 1, the lower half folded over the upper, and the resulting
// square quantised to 16 bits per axis. The worst-case angular error is about 1e-4 radians.
#pragma once

#include "core/vecmath.h"

#include <cmath>
#include <cstdint>

namespace caustica {

namespace octahedral_detail {
inline float sign_not_zero(float v) { return v < 0 ? -1.f : 1.f; }
inline uint32_t quantise(float v) { return uint32_t(std::lround((std::clamp(v, -1.f, 1.f) * 0.5f + 0.5f) * 65535.f)); }
inline float dequantise(uint32_t q) { return float(q) / 65535.f * 2 - 1; }
} // namespace octahedral_detail

inline uint32_t encode_octahedral(Vec3f v) {
    using namespace octahedral_detail;
    float l1 = std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
    float x = v.x / l1, y = v.y / l1;
    if (v.z < 0) {
        float fx = (1 - std::abs(y)) * sign_not_zero(x);
        float fy = (1 - std::abs(x)) * sign_not_zero(y);
        x = fx;
        y = fy;
    }
    return quantise(x) | (quantise(y) << 16);
}

inline Vec3f decode_octahedral(uint32_t packed) {
    using namespace octahedral_detail;
    float x = dequantise(packed & 0xffff), y = dequantise(packed >> 16);
    float z = 1 - std::abs(x) - std::abs(y);
    if (z < 0) {
        float fx = (1 - std::abs(y)) * sign_not_zero(x);
        float fy = (1 - std::abs(x)) * sign_not_zero(y);
        x = fx;
        y = fy;
    }
    return normalize(Vec3f(x, y, z));
}

} // namespace caustica
