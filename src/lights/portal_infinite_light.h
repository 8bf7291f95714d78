// An environment light seen only through a portal, a rectangle such as a window (pbrt-v4's
// "infinite" light with "portal"; Bitterli, Novak and Jarosz 2015, "Portal-masked environment map
// sampling"). The environment is resampled into the portal's own directional parameterisation,
// u = (atan(x / z) + pi / 2) / pi and v likewise in y, in which the directions from any point
// through the rectangle form an axis-aligned window; next-event estimation samples that window
// alone, by the image's luminance. Radiance arrives only along directions that pass through the
// portal from the receiving point, as in pbrt-v4, so a portal in a wall lights the room
// through it and nothing outside. Light paths start on the portal, so every integrator renders
// the same image (pbrt-v4's own light paths start anywhere and disagree with its path tracer).
#pragma once

#include "core/transform.h"
#include "core/windowed_distribution.h"
#include "lights/light.h"
#include "lights/rgb_image.h"
#include "lights/scene_disk.h"

#include <array>

namespace caustica {

class RGBColorSpace;

class PortalInfiniteLight final : public Light {
  public:
    // `equal_area` is a square equal-area environment map in light space (RGB illuminant values
    // in color_space, which must outlive the light), scaled by `scale`; `portal` holds the
    // rectangle's corners in render space, in order around it: directions through it from the
    // scene have a positive component along cross(p3 - p0, p1 - p0). Throws
    // std::invalid_argument for a portal that is not a rectangle or an image that is not square.
    PortalInfiniteLight(const Transform &render_from_light, const RGBImage &equal_area,
                        const RGBColorSpace &color_space, float scale, const std::array<Vec3f, 4> &portal);

    LightType type() const override { return LightType::Infinite; }
    void preprocess(const Bounds3f &scene_bounds) override;
    SampledSpectrum phi(const SampledWavelengths &lambda) const override;
    std::optional<LightLiSample> sample_li(const LightSampleContext &ctx, Vec2f u,
                                           const SampledWavelengths &lambda) const override;
    float pdf_li(const LightSampleContext &ctx, Vec3f wi) const override;
    SampledSpectrum Le(const Ray &ray, const SampledWavelengths &lambda) const override;
    std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2,
                                           const SampledWavelengths &lambda) const override;
    void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const override;

    // The parameterisation: the render-space direction of uv and its solid angle per unit uv
    // area, and the uv of a direction (empty for directions away from the portal's outside).
    Vec3f direction_at(Vec2f uv, float *solid_angle_per_uv = nullptr) const;
    std::optional<Vec2f> uv_of(Vec3f w, float *solid_angle_per_uv = nullptr) const;
    // The window of uv through which p sees the portal; empty behind it.
    std::optional<UVWindow> window_from(Vec3f p) const;

  private:
    SampledSpectrum radiance(Vec2f uv, const SampledWavelengths &lambda) const;
    float area() const;

    std::array<Vec3f, 4> portal_;
    Frame frame_;
    RGBImage image_;  // the environment in the portal's parameterisation
    const RGBColorSpace *color_space_;
    float scale_;
    WindowedDistribution2D distribution_;
    SceneSphere scene_;
};

}  // namespace caustica
