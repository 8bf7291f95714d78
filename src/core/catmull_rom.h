// Catmull-Rom splines through values tabulated at ascending, not necessarily uniform nodes: on each
// interval [x_i, x_i+1] the cubic Hermite interpolant whose end derivatives are the finite
// differences across the neighbouring nodes, (f_i+1 - f_i-1) / (x_i+1 - x_i-1), or the one-sided
// difference over the interval itself at the table's ends. The spline is C1, reproduces linear
// data exactly, and is linear in the values, so a spline of splines (a table over two variables)
// is the same whichever variable is interpolated first.
//
// These are the spline tools pbrt-v4 uses for its tabulated subsurface profiles
// (materials/photon_beam_diffusion.h), and they follow its conventions (the sampler's and the
// inversion's Newton tolerances, the clamping at the table's ends) so that the tables interpolate
// to the same numbers.
#pragma once

#include <array>
#include <optional>
#include <span>

namespace caustica {

// The spline at x as sum_i weights[i] * values[offset + i]. At the table's first and last
// intervals offset + 0 or offset + 3 lies outside the table, with weight 0.
struct CatmullRomWeights {
    int offset = 0;
    std::array<float, 4> weights{};
};
// Empty when x lies outside [nodes.front(), nodes.back()] (or is NaN). nodes.size() >= 2.
std::optional<CatmullRomWeights> catmull_rom_weights(std::span<const float> nodes, float x);

// Integral of the spline from nodes[0] to nodes[i] into cdf[i] (cdf.size() == nodes.size());
// returns the integral over the whole table. Exact: each interval's cubic integrates to
// width ((f0 + f1) / 2 + (d0 - d1) / 12) with d the end derivatives per unit of the interval.
float integrate_catmull_rom(std::span<const float> nodes, std::span<const float> values,
                            std::span<float> cdf);

// The x at which the spline of increasing values equals y; nodes.front() for y at or below
// values.front(), nodes.back() for y at or above values.back().
float invert_catmull_rom(std::span<const float> nodes, std::span<const float> values, float y);

// Draws x2 with density proportional to the spline of values(alpha, x2) over nodes2, for u in
// [0, 1). values and cdf are tables over nodes1 x nodes2 (x2 fastest), cdf each row's running
// integral from integrate_catmull_rom; the row for alpha is the Catmull-Rom blend of the rows in
// nodes1. Returns 0 when alpha lies outside nodes1.
float sample_catmull_rom_2d(std::span<const float> nodes1, std::span<const float> nodes2,
                            std::span<const float> values, std::span<const float> cdf, float alpha,
                            float u);

} // namespace caustica
