// The colour map of `caustica compare`'s error images: a sequential map whose CIELAB lightness
// L* rises linearly with the value, so equal steps in the value look like equal steps in
// brightness (it also reads correctly in greyscale and for colour-blind viewers), while the hue
// turns from dark blue-violet through teal and green to yellow, like matplotlib's viridis. The
// map is defined here by its construction, not by a table.
#pragma once

#include "spectral/color.h"

namespace caustica {

// Lightness L* of the map at t = 0 and t = 1 (t is clamped to [0, 1]).
constexpr double kErrorMapLightnessMin = 15, kErrorMapLightnessMax = 92;

// The colour at t in [0, 1], in linear sRGB (Rec. 709 primaries, D65 white), every component
// within [0, 1].
RGB error_colour(double t);

} // namespace caustica
