// Spotlight: a point light whose intensity is scale * I inside a cone of half-angle
// (coneangle - conedelta) around light-space +z, falling off smoothly (Hermite smoothstep in
// cos theta, as pbrt-v4) to zero at coneangle.
#pragma once

#include "core/transform.h"
#include "lights/point_source_light.h"
#include "spectral/spectrum.h"

namespace caustica {

class SpotLight final : public PointSourceLight {
  public:
    // Angles in degrees; falloff_start <= total_width.
    SpotLight(const Transform &render_from_light, SpectrumPtr intensity, float scale,
              float total_width_degrees, float falloff_start_degrees);

    const Spectrum *emission_spectrum() const override { return intensity_.get(); }
    SampledSpectrum phi(const SampledWavelengths &lambda) const override;
    SampledSpectrum intensity_towards(Vec3f w, const SampledWavelengths &lambda) const override {
        return intensity(normalize(light_from_render_.apply_vector(w)), lambda);
    }
    std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2,
                                           const SampledWavelengths &lambda) const override;
    void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const override;
    // pbrt-v4's SpotLight::Bounds: full intensity within the falloff start around the axis, and
    // light up to theta_e beyond it (the falloff's width), widened by 1e-3 rad so that rounding
    // never leaves out a direction the falloff still lights.
    EmissionDirections emission_directions() const override;

    // Radiant intensity towards light-space direction w (unit).
    SampledSpectrum intensity(Vec3f w_light, const SampledWavelengths &lambda) const;

  private:
    // Probabilities (unnormalised) of sampling the full-intensity cone and the falloff ring:
    // their solid-angle integrals of the angular profile divided by 2 pi.
    float cone_weight() const { return 1 - cos_falloff_start_; }
    float falloff_weight() const { return (cos_falloff_start_ - cos_falloff_end_) / 2; }

    Transform render_from_light_, light_from_render_;
    SpectrumPtr intensity_;
    float scale_;
    float cos_falloff_end_, cos_falloff_start_;
};

// Hermite smoothstep of x between a and b, and its normalised density and sampling over [a, b].
float smooth_step(float x, float a, float b);
float smooth_step_pdf(float x, float a, float b);
float sample_smooth_step(float u, float a, float b);

}  // namespace caustica
