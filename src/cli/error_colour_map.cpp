#include "cli/error_colour_map.h"

#include "spectral/color_space.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace caustica {

namespace {

// Inverse of CIELAB's cube-root compression f (CIE 15:2004), with its linear segment near black.
double cielab_f_inverse(double f) {
    constexpr double delta = 6.0 / 29.0;
    return f > delta ? f * f * f : 3 * delta * delta * (f - 4.0 / 29.0);
}

} // namespace

RGB error_colour(double t) {
    t = std::clamp(t, 0.0, 1.0);
    // The path through CIELAB (LCh form): lightness rises linearly; the hue angle turns from
    // 300 degrees (blue-violet) down to 100 degrees (yellow); the chroma is lowest (25) around
    // t = 0.3, where the path passes the dark blue-teal region in which sRGB holds the least
    // saturated colours, and grows smoothly on both sides. The parabola was chosen to keep the
    // whole path inside the sRGB gamut (at least 1 unit of chroma to spare everywhere), so no
    // clipping bends the lightness ramp.
    const double lightness = kErrorMapLightnessMin + (kErrorMapLightnessMax - kErrorMapLightnessMin) * t;
    const double hue = (300.0 - 200.0 * t) * std::numbers::pi / 180.0;
    const double chroma = 25.0 + 100.0 * (t - 0.3) * (t - 0.3);
    const double a = chroma * std::cos(hue), b = chroma * std::sin(hue);

    const RGBColorSpace &srgb = RGBColorSpace::srgb();
    const XYZ white = srgb.whitepoint();
    const double fy = (lightness + 16) / 116;
    XYZ xyz{float(white.x * cielab_f_inverse(fy + a / 500)), float(white.y * cielab_f_inverse(fy)),
            float(white.z * cielab_f_inverse(fy - b / 200))};
    RGB rgb = srgb.rgb_from_xyz(xyz);
    // Only rounding can leave the gamut here.
    return {std::clamp(rgb.r, 0.f, 1.f), std::clamp(rgb.g, 0.f, 1.f), std::clamp(rgb.b, 0.f, 1.f)};
}

} // namespace caustica
