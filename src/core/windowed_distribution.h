// A piecewise-constant density over [0,1]^2 that samples within any axis-aligned window of it,
// exactly and in constant time per window: a summed-area table gives the integral over a window
// with fractional edges (the table interpolated bilinearly, exact for a piecewise-constant
// function), and inverting it one axis at a time gives the sample. Portal-masked environment
// lights use it to sample only the directions that pass through the portal from a point
// (Bitterli et al. 2015, "Portal-masked environment map sampling"; pbrt-v4's
// WindowedPiecewiseConstant2D).
#pragma once

#include "core/vecmath.h"

#include <optional>
#include <vector>

namespace caustica {

struct UVWindow {
    Vec2f min, max;
    bool contains(Vec2f p) const { return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y; }
};

class WindowedDistribution2D {
  public:
    WindowedDistribution2D() = default;
    // f holds ny rows of nx non-negative values, row 0 at v = 0.
    WindowedDistribution2D(std::vector<float> f, int nx, int ny);

    // A point of the window with density f / (integral of f over the window); empty when f
    // vanishes there.
    std::optional<Vec2f> sample(Vec2f u, const UVWindow &window, float *pdf) const;
    float pdf(Vec2f p, const UVWindow &window) const;
    // The integral of f over the window (f's cells have area 1 / (nx ny)).
    double integral(const UVWindow &window) const;

  private:
    float value(Vec2f p) const;
    // The integral of f over [0, x] x [0, y].
    double cumulative(double x, double y) const;
    // The x in [lo, hi] where g, increasing and linear between the cell edges k / n, reaches
    // target.
    template <typename G> double invert(G g, double target, double lo, double hi, int n) const;

    int nx_ = 0, ny_ = 0;
    std::vector<float> f_;
    std::vector<double> table_;  // (nx + 1) x (ny + 1) partial sums, the integral below each corner
};

} // namespace caustica
