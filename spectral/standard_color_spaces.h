// The RGB colour spaces pbrt-v4 scenes can name (`ColorSpace "srgb"` etc.): primaries and white
// illuminant. Shared by RGBColorSpace and by tools/rgb2spec_gen.cpp, which optimises one
// RGB-to-spectrum table per entry at build time, so both always agree on the definitions.
#pragma once

#include "spectral/color.h"

#include <array>
#include <string_view>

namespace caustica {

struct ColorSpaceDefinition {
    std::string_view name;
    Chromaticity red, green, blue;
    // A named spectrum (named_spectra.h); normalised to luminance 1. Its XYZ is the white point.
    std::string_view illuminant;
};

inline constexpr std::array<ColorSpaceDefinition, 4> StandardColorSpaces = {{
    // ITU-R BT.709 primaries with D65 white (IEC 61966-2-1).
    {"srgb", {0.64f, 0.33f}, {0.30f, 0.60f}, {0.15f, 0.06f}, "stdillum-D65"},
    // ACES AP0 primaries (SMPTE ST 2065-1) with the ACES white, CIE daylight at 6000 K.
    {"aces2065-1", {0.7347f, 0.2653f}, {0.0f, 1.0f}, {0.0001f, -0.077f}, "illum-acesD60"},
    // ITU-R BT.2020 primaries with D65 white.
    {"rec2020", {0.708f, 0.292f}, {0.170f, 0.797f}, {0.131f, 0.046f}, "stdillum-D65"},
    // DCI-P3 primaries (SMPTE RP 431-2) with D65 white, as pbrt-v4 defines "dci-p3".
    {"dci-p3", {0.680f, 0.320f}, {0.265f, 0.690f}, {0.150f, 0.060f}, "stdillum-D65"},
}};

} // namespace caustica
