// The neighbouring floats of v, as std::nextafter(v, +-infinity) gives them, but inline: ray
// spawning and Embree's open interval call these for every ray, and the library call cost 1.5%
// of a vcm render's instructions. (pbrt-v4's NextFloatUp and NextFloatDown.)
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace caustica {

// The smallest float greater than v; infinity and NaN are returned unchanged.
inline float next_float_up(float v) {
    if (std::isinf(v) && v > 0) return v;
    if (v == 0) v = 0.f; // -0 steps to the smallest positive float, as +0 does
    uint32_t bits = std::bit_cast<uint32_t>(v);
    bits = v >= 0 ? bits + 1 : bits - 1;
    return std::isnan(v) ? v : std::bit_cast<float>(bits);
}

// The largest float less than v; -infinity and NaN are returned unchanged.
inline float next_float_down(float v) {
    if (std::isinf(v) && v < 0) return v;
    if (v == 0) v = -0.f;
    uint32_t bits = std::bit_cast<uint32_t>(v);
    bits = v > 0 ? bits - 1 : bits + 1;
    return std::isnan(v) ? v : std::bit_cast<float>(bits);
}

} // namespace caustica
