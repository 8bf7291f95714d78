#include "spectral/rgb_to_spectrum_table.h"

#include <algorithm>
#include <cmath>

namespace caustica {

RGBToSpectrumTable::RGBToSpectrumTable(const RGBToSpectrumTableData &data)
    : resolution_(data.resolution), scale_(data.scale), coefficients_(data.coefficients) {}

SigmoidPolynomial RGBToSpectrumTable::operator()(const RGB &rgb) const {
    // Greys are constant spectra: sigmoid(c2) = v for c2 = (v - 1/2) / sqrt(v (1 - v)).
    if (rgb.r == rgb.g && rgb.g == rgb.b) {
        float v = rgb.r;
        return {0, 0, (v - 0.5f) / std::sqrt(v * (1 - v))};
    }

    // The table is parametrised by the largest component (its slice index and the brightness z)
    // and the other two relative to it, which keeps every lookup inside the unit cube.
    int largest = rgb.r > rgb.g ? (rgb.r > rgb.b ? 0 : 2) : (rgb.g > rgb.b ? 1 : 2);
    float z = rgb[largest];
    float x = rgb[(largest + 1) % 3] * float(resolution_ - 1) / z;
    float y = rgb[(largest + 2) % 3] * float(resolution_ - 1) / z;

    int xi = std::min(int(x), resolution_ - 2), yi = std::min(int(y), resolution_ - 2);
    int zi = int(std::upper_bound(scale_, scale_ + resolution_, z) - scale_) - 1;
    zi = std::clamp(zi, 0, resolution_ - 2);
    float dx = x - float(xi), dy = y - float(yi);
    float dz = (z - scale_[zi]) / (scale_[zi + 1] - scale_[zi]);

    auto entry = [&](int k, int j, int i) {
        size_t n = size_t(resolution_);
        return coefficients_ +
               3 * (((size_t(largest) * n + size_t(k)) * n + size_t(j)) * n + size_t(i));
    };
    float c[3];
    for (int m = 0; m < 3; ++m) {
        auto lerp = [](float t, float a, float b) { return (1 - t) * a + t * b; };
        float c00 = lerp(dx, entry(zi, yi, xi)[m], entry(zi, yi, xi + 1)[m]);
        float c01 = lerp(dx, entry(zi, yi + 1, xi)[m], entry(zi, yi + 1, xi + 1)[m]);
        float c10 = lerp(dx, entry(zi + 1, yi, xi)[m], entry(zi + 1, yi, xi + 1)[m]);
        float c11 = lerp(dx, entry(zi + 1, yi + 1, xi)[m], entry(zi + 1, yi + 1, xi + 1)[m]);
        c[m] = lerp(dz, lerp(dy, c00, c01), lerp(dy, c10, c11));
    }
    return {c[0], c[1], c[2]};
}

} // namespace caustica
