// Pixel reconstruction filters (pbrt-v4 section 8.8). The film weights each sample by the
// filter evaluated at its offset from the pixel centre. As in pbrt-v4, a camera sample's offset
// is drawn by importance sampling the filter and carries the weight f/pdf, so each sample adds
// only to the pixel it was taken for (no sharing between neighbouring pixels, hence no locks
// and no correlation between pixels); light-tracing splats instead evaluate the filter at every
// pixel they reach.
#pragma once

#include "core/error.h"
#include "core/sampling.h"
#include "core/vecmath.h"
#include "params/parameters.h"

#include <memory>
#include <string>
#include <vector>

namespace caustica {

// Larger radii are rejected: no real filter is wider, and the bound lets a splat keep its
// per-column and per-row weights on the stack.
inline constexpr float MaxFilterRadius = 32;

struct FilterSample {
    Vec2f p;          // offset from the pixel centre, within [-radius, radius]
    float weight = 1; // f(p) / pdf(p), up to a constant factor common to all samples
};

class Filter {
  public:
    virtual ~Filter() = default;
    // Half-widths of the support in x and y (pixels).
    virtual Vec2f radius() const = 0;
    // Every pbrt-v4 filter is separable, a product of one-dimensional profiles along x and y;
    // splats use that to evaluate one weight per column and per row of their footprint.
    virtual float evaluate_x(float x) const = 0;
    virtual float evaluate_y(float y) const = 0;
    float evaluate(Vec2f p) const { return evaluate_x(p.x) * evaluate_y(p.y); }
    // Integral of evaluate() over its support; splats are divided by it.
    virtual float integral() const = 0;
    virtual FilterSample sample(Vec2f u) const = 0;
};

// Importance sampling of any filter through a table of its values (pbrt-v4's FilterSampler):
// 32 cells per pixel of radius, sampled in proportion to |f|. The weight is the tabulated
// f / pdf: a constant whose sign follows f, so negative lobes (Mitchell, Lanczos) subtract.
class FilterSampler {
  public:
    FilterSampler() = default;
    explicit FilterSampler(const Filter &filter);
    FilterSample sample(Vec2f u) const;

  private:
    Vec2f radius_;
    int nx_ = 0, ny_ = 0;
    std::vector<float> f_;
    PiecewiseConstant2D distribution_;
    float abs_integral_ = 0; // of |f| over the support: f / pdf up to sign
};

// Constant over [-r, r]^2 (radius 0.5: each sample counts for its pixel only).
class BoxFilter final : public Filter {
  public:
    explicit BoxFilter(Vec2f radius = {0.5f, 0.5f}) : radius_(radius) {}
    Vec2f radius() const override { return radius_; }
    float evaluate_x(float x) const override;
    float evaluate_y(float y) const override;
    float integral() const override { return 4 * radius_.x * radius_.y; }
    FilterSample sample(Vec2f u) const override;

  private:
    Vec2f radius_;
};

// A Gaussian shifted down by its value at the radius so that it reaches zero there (pbrt-v4's
// default filter: radius 1.5, sigma 0.5).
class GaussianFilter final : public Filter {
  public:
    explicit GaussianFilter(Vec2f radius = {1.5f, 1.5f}, float sigma = 0.5f);
    Vec2f radius() const override { return radius_; }
    float evaluate_x(float x) const override;
    float evaluate_y(float y) const override;
    float integral() const override;
    FilterSample sample(Vec2f u) const override { return sampler_.sample(u); }

  private:
    Vec2f radius_;
    float sigma_, value_at_radius_x_, value_at_radius_y_;
    FilterSampler sampler_;
};

// Separable tent: (r_x - |x|)(r_y - |y|), sampled exactly.
class TriangleFilter final : public Filter {
  public:
    explicit TriangleFilter(Vec2f radius = {2, 2}) : radius_(radius) {}
    Vec2f radius() const override { return radius_; }
    float evaluate_x(float x) const override;
    float evaluate_y(float y) const override;
    float integral() const override { return sqr(radius_.x) * sqr(radius_.y); }
    FilterSample sample(Vec2f u) const override;

  private:
    Vec2f radius_;
};

// Mitchell and Netravali 1988, "Reconstruction Filters in Computer Graphics": the separable
// cubic family with parameters B and C (1/3 each by default), scaled to the radius.
class MitchellFilter final : public Filter {
  public:
    explicit MitchellFilter(Vec2f radius = {2, 2}, float b = 1.f / 3, float c = 1.f / 3);
    Vec2f radius() const override { return radius_; }
    float evaluate_x(float x) const override;
    float evaluate_y(float y) const override;
    // Each 1D cubic integrates to 1 over [-2, 2] for any B and C; scaled to [-r, r] that is r/2.
    float integral() const override { return radius_.x * radius_.y / 4; }
    FilterSample sample(Vec2f u) const override { return sampler_.sample(u); }

  private:
    float mitchell_1d(float x) const;
    Vec2f radius_;
    float b_, c_;
    FilterSampler sampler_;
};

// sinc(x) windowed by sinc(x / tau) (Lanczos), truncated at the radius: pbrt-v4's "sinc".
class LanczosSincFilter final : public Filter {
  public:
    explicit LanczosSincFilter(Vec2f radius = {4, 4}, float tau = 3);
    Vec2f radius() const override { return radius_; }
    float evaluate_x(float x) const override;
    float evaluate_y(float y) const override;
    float integral() const override { return integral_; }
    FilterSample sample(Vec2f u) const override { return sampler_.sample(u); }

  private:
    Vec2f radius_;
    float tau_;
    float integral_;
    FilterSampler sampler_;
};

// pbrt-v4 names: "box", "gaussian", "triangle", "mitchell", "sinc" with "xradius"/"yradius"
// (defaults 0.5, 1.5, 2, 2, 4), "sigma" (gaussian), "B"/"C" (mitchell), "tau" (sinc). A scene
// without a PixelFilter directive uses "gaussian", as pbrt-v4 does.
std::unique_ptr<Filter> create_filter(const std::string &type, const ParameterDictionary &params,
                                      const SourceLocation &loc);

} // namespace caustica
