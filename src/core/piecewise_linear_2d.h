// A density over the unit square that is bilinear between the values of a regular grid, and that
// may depend on up to three parameters (such as the incident direction of a measured BRDF), over
// which the grid values are interpolated linearly. Sampling inverts its marginal CDF in y and
// then its conditional CDF in x, both exact for the bilinear density (each step solves a
// quadratic), so the mapping is continuous, invertible and keeps stratification.
//
// This is the warp of Dupuy and Jakob 2018, "An Adaptive Parameterization for Efficient Material
// Acquisition and Rendering" (section 5 and its supplement), which their RGL BSDF files are
// tabulated for (see materials/measured_bxdf.h); Mitsuba calls it Marginal2D, pbrt-v4
// PiecewiseLinear2D. A parameter's slices are blended by interpolating their CDFs and their
// (separately normalised) densities with the same weights, so the blend is itself a normalised
// bilinear density that the CDFs sample exactly.
#pragma once

#include "core/vecmath.h"

#include <cstdint>
#include <span>
#include <vector>

namespace caustica {

class PiecewiseLinear2D {
  public:
    static constexpr int MaxParameters = 3;

    struct Sample {
        Vec2f p;
        float pdf = 0;  // density over the unit square at p
    };

    // data: one ny x nx grid (row y, column x, x fastest) per combination of the parameters'
    // values, the first parameter's index slowest. parameters[i] lists the values of parameter i
    // (ascending; a single value makes the density independent of it). nx, ny >= 2.
    // As a Density, each slice is normalised to integrate to 1 and can be sampled and inverted;
    // as an Interpolant, evaluate() returns the bilinear interpolation of the values as given.
    // Throws std::invalid_argument when a Density has a slice that is zero everywhere, or values
    // that are negative or not finite.
    enum class Kind { Density, Interpolant };
    PiecewiseLinear2D(std::span<const float> data, int nx, int ny, std::vector<std::vector<float>> parameters,
                      Kind kind);

    // Warps a uniform u to the distribution for the given parameter values (clamped to the range
    // tabulated), with the density there. A Density only.
    Sample sample(Vec2f u, std::span<const float> parameters = {}) const;
    // The inverse of sample(): the u that sample() maps to p, with the density at p.
    Sample invert(Vec2f p, std::span<const float> parameters = {}) const;
    // The interpolated value (a Density's density) at p.
    float evaluate(Vec2f p, std::span<const float> parameters = {}) const;

  private:
    // The slices that the parameters fall between, and their weights.
    struct Blend {
        int count = 0;
        uint32_t slice[1 << MaxParameters];
        float weight[1 << MaxParameters];
    };
    Blend blend(std::span<const float> parameters) const;
    // The blend of table[slice * stride + i] over the slices.
    static float lookup(const std::vector<float> &table, uint32_t stride, uint32_t i, const Blend &b);
    // The grid cell that p lies in (the last one for p on the far edges), p's position (s, t)
    // within it, and the values along its left and right edges interpolated at t.
    struct Cell {
        uint32_t row, col;
        float s, t, left, right;
    };
    Cell cell(Vec2f p, const Blend &b) const;

    int nx_, ny_;
    std::vector<std::vector<float>> parameters_;
    // Density per grid cell as stored (a Density's normalised so that the sum of its cells'
    // mean values is 1); to_unit_square turns it into a density over the unit square.
    std::vector<float> data_;
    float to_unit_square_ = 1;
    // Per slice: conditional_cdf_[y][x], the integral of row y from column 0 to x, and
    // marginal_cdf_[y], that of the rows' totals from 0 to y, in cells (Density only).
    std::vector<float> conditional_cdf_, marginal_cdf_;
};

} // namespace caustica
