// The raw RGB-to-spectrum tables. They are not in the source tree: tools/rgb2spec_gen.cpp
// optimises them at build time (cmake/SpectralTables.cmake) and writes the source file that
// defines rgb_to_spectrum_table_data() into the build directory.
#pragma once

#include <string_view>

namespace caustica {

struct RGBToSpectrumTableData {
    int resolution = 0;
    // `resolution` increasing values in [0, 1]: the brightness (largest RGB component) of each
    // table slice, denser near 0 and 1 where the coefficients change fastest.
    const float *scale = nullptr;
    // [3][resolution][resolution][resolution][3]: for the largest component l, brightness
    // index k, and the other two components relative to the largest (indices j, i: components
    // (l + 2) % 3 and (l + 1) % 3), the sigmoid-polynomial coefficients c0, c1, c2 (nm units).
    const float *coefficients = nullptr;
};

// The table optimised for a colour space of StandardColorSpaces; null for any other name.
const RGBToSpectrumTableData *rgb_to_spectrum_table_data(std::string_view color_space);

} // namespace caustica
