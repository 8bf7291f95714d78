// pbrt-v4's projection light: a point light that projects an image like a slide projector. Light
// leaves the light's origin through a window on the plane z = 1 of light space, of field of view
// "fov" across the image's shorter side; a direction's intensity is the RGB (an illuminant
// spectrum in sRGB) of the image pixel it passes through, times scale. As in pbrt-v4, light space
// is flipped in y so that the image appears upright. Light paths leave in directions drawn from
// the image weighted by cos^3 (the solid angle a pixel of the window subtends).
#pragma once

#include "core/sampling.h"
#include "core/transform.h"
#include "lights/point_source_light.h"
#include "lights/rgb_image.h"
#include "spectral/color_space.h"

namespace caustica {

class ProjectionLight final : public PointSourceLight {
  public:
    // render_from_light is the CTM at the LightSource directive (the y flip is added here).
    ProjectionLight(const Transform &render_from_light, RGBImage image, float scale, float fov_degrees);

    SampledSpectrum phi(const SampledWavelengths &lambda) const override;
    SampledSpectrum intensity_towards(Vec3f w, const SampledWavelengths &lambda) const override;
    std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2, const SampledWavelengths &lambda) const override;
    void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const override;
    // The cone around the axis through the window's corners (the widest directions of the
    // window: a linear map keeps the window a parallelogram around the axis's image), with a
    // hard edge (theta_e of 1e-3 rad, for rounding).
    EmissionDirections emission_directions() const override;

    // pbrt-v4's "power" normalisation: the luminous power of unit scale.
    float unit_luminous_power() const;

  private:
    // Where light-space direction w crosses the window, in [0, 1]^2 (x right, y from the window's
    // bottom), or nothing outside it or behind the light.
    std::optional<Vec2f> window_point(Vec3f w) const;
    Vec3f window_direction(Vec2f unit) const; // light space, unit length
    SampledSpectrum intensity(Vec2f unit, const SampledWavelengths &lambda) const;

    Transform render_from_light_, light_from_render_;
    RGBImage image_;
    float scale_;
    float tan_half_fov_;
    Vec2f window_min_, window_max_; // in units of tan(fov / 2)
    float window_area_;             // on the plane z = 1
    PiecewiseConstant2D distribution_;
};

}  // namespace caustica
