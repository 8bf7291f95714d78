// pbrt-v4's goniometric light: a point light whose intensity over directions is an image, the
// goniometric diagram of a real luminaire, stored in the equal-area octahedral parameterisation
// (equal_area_mapping.h; a square image). Intensity in direction w is scale * I * image(w), the
// image's RGB averaged to one value and looked up at the nearest pixel, as pbrt-v4 does. As in
// pbrt-v4, light space has its y and z swapped before the mapping, so the image's centre points
// along the light's +y. Light paths leave in directions drawn from the image (a piecewise-constant
// density over the square, which is a density over the sphere divided by 4 pi).
#pragma once

#include "core/sampling.h"
#include "core/transform.h"
#include "lights/point_source_light.h"
#include "lights/rgb_image.h"
#include "spectral/spectrum.h"

namespace caustica {

class GoniometricLight final : public PointSourceLight {
  public:
    GoniometricLight(const Transform &render_from_light, SpectrumPtr intensity, float scale, const RGBImage &image);

    const Spectrum *emission_spectrum() const override { return intensity_.get(); }
    SampledSpectrum phi(const SampledWavelengths &lambda) const override;
    SampledSpectrum intensity_towards(Vec3f w, const SampledWavelengths &lambda) const override {
        return scale_ * diagram(w) * intensity_->sample(lambda);
    }
    std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2, const SampledWavelengths &lambda) const override;
    void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const override;

    // The image's value (the RGB average) in the render-space direction w leaving the light.
    float diagram(Vec3f w) const;
    // The average of the image over the sphere, which pbrt-v4's "power" divides by.
    float mean() const { return mean_; }

  private:
    Vec3f to_diagram(Vec3f w_render) const;
    Vec3f from_diagram(Vec3f w_diagram) const;

    Transform render_from_light_, light_from_render_;
    SpectrumPtr intensity_;
    float scale_;
    int resolution_;
    std::vector<float> values_; // rows from the top, the RGB average of each pixel
    float mean_ = 0;
    PiecewiseConstant2D distribution_;
};

}  // namespace caustica
