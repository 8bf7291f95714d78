#include "materials/random_walk_albedo.h"

#include "core/vecmath.h"
#include "materials/subsurface_coefficients.h"

#include <array>
#include <cmath>

namespace caustica {

namespace {

// R at alpha = 1 - s^2 for s = i / 64 (scripts/tabulate-random-walk-albedo.cpp; standard error
// below 4e-4 per entry). Tabulating over s = sqrt(1 - alpha) spreads the entries evenly in R,
// which near alpha = 1 falls like 1 - c sqrt(1 - alpha) (diffusion theory).
constexpr std::array<float, 65> ReflectanceTable = {
    1.000000, 0.963762, 0.928975, 0.895676, 0.863350, 0.832000, 0.802399, 0.773411,
    0.745408, 0.718633, 0.692855, 0.668259, 0.643819, 0.620759, 0.597987, 0.575763,
    0.554749, 0.534675, 0.513957, 0.495158, 0.476472, 0.458215, 0.440852, 0.423415,
    0.407007, 0.390634, 0.375617, 0.360195, 0.345688, 0.331081, 0.317219, 0.303478,
    0.290158, 0.277158, 0.265174, 0.252596, 0.240601, 0.229043, 0.217696, 0.206803,
    0.196184, 0.185526, 0.175203, 0.165270, 0.155453, 0.145996, 0.136704, 0.127411,
    0.118650, 0.109961, 0.101483, 0.093203, 0.085016, 0.077155, 0.069236, 0.061807,
    0.054242, 0.046837, 0.039838, 0.032806, 0.026038, 0.019286, 0.012739, 0.006284,
    0.000000,
};
constexpr int Intervals = int(ReflectanceTable.size()) - 1;

float reflectance_at(float s) {
    float x = clamp(s, 0.f, 1.f) * Intervals;
    int i = std::min(int(x), Intervals - 1);
    return lerp(x - i, ReflectanceTable[i], ReflectanceTable[i + 1]);
}

} // namespace

float random_walk_reflectance(float single_scattering_albedo) {
    return reflectance_at(std::sqrt(std::max(0.f, 1 - single_scattering_albedo)));
}

float random_walk_single_scattering_albedo(float reflectance) {
    // R decreases with s: find the interval, then invert its linear piece.
    reflectance = clamp(reflectance, 0.f, 1.f);
    int i = 0;
    while (i < Intervals - 1 && ReflectanceTable[i + 1] > reflectance) ++i;
    float r0 = ReflectanceTable[i], r1 = ReflectanceTable[i + 1];
    float t = r0 > r1 ? clamp((r0 - reflectance) / (r0 - r1), 0.f, 1.f) : 0.f;
    float s = (i + t) / Intervals;
    return 1 - s * s;
}

float random_walk_mean_free_path(float scatter_distance, float albedo) {
    return scatter_distance * christensen_burley_scaling(albedo);
}

} // namespace caustica
