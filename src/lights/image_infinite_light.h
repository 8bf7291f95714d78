// Environment light whose radiance comes from an RGB image around the scene, importance-sampled
// by the image's luminance.
#pragma once

#include "core/sampling.h"
#include "core/transform.h"
#include "lights/light.h"
#include "lights/rgb_image.h"
#include "lights/scene_disk.h"
#include "spectral/color.h"

namespace caustica {

class RGBColorSpace;

// How the image covers the sphere of light-space directions.
enum class EnvironmentMapping {
    // pbrt-v4's format: a square image in Clarberg's equal-area octahedral parameterisation
    // (equal_area_mapping.h), every pixel the same solid angle.
    EqualArea,
    // Caustica extension: a 2:1 latitude-longitude image, pbrt-v3's convention: u = phi / 2 pi
    // with phi measured from +x towards +y, v = theta / pi with theta from +z (v = 0 at the top
    // row is the +z pole).
    Equirectangular,
};

class ImageInfiniteLight final : public Light {
  public:
    // The image's RGB values are illuminant RGB in color_space (which must outlive the light),
    // scaled by `scale`. EqualArea needs a square image, Equirectangular a 2:1 one.
    ImageInfiniteLight(const Transform &render_from_light, RGBImage image,
                       EnvironmentMapping mapping, const RGBColorSpace &color_space, float scale);

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

    // The parameterisation, in light space.
    Vec3f direction_at(Vec2f uv) const;
    Vec2f uv_of(Vec3f w_light) const;
    // Solid angle per unit area of the image square at uv: a density over the square divided by
    // it is a density over directions (4 pi everywhere for EqualArea).
    float solid_angle_per_uv(Vec2f uv) const;

    // Half the illuminance (in Y) that the image, as given (scale 1), sheds on a surface facing
    // light-space +z. pbrt-v4 normalises "illuminance" by this quantity: its sum over the upper
    // hemisphere's equal-area pixels weights each by 2 pi / N instead of the pixel's solid angle
    // 4 pi / N. We keep that factor so that scenes render as in pbrt-v4.
    static float pbrt_illuminance_normalization(const RGBImage &image, EnvironmentMapping mapping,
                                                RGB luminance_weights);

  private:
    RGB pixel(Vec2f uv) const;
    SampledSpectrum radiance(Vec2f uv, const SampledWavelengths &lambda) const;

    Transform render_from_light_, light_from_render_;
    RGBImage image_;
    EnvironmentMapping mapping_;
    const RGBColorSpace *color_space_;
    float scale_;
    PiecewiseConstant2D distribution_;
    SceneSphere scene_;
};

}  // namespace caustica
