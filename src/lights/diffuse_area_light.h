// Diffuse area light: radiance scale * L leaving every point of a shape, on the side of its
// (oriented) normal, or on both sides when two-sided. L is one spectrum, or an emission image's
// (pbrt-v4's "filename", lights/emission_image.h). A shape with an alpha cut-out emits
// only where it is there: points that the mask removes are never sampled as emitting, and rays
// pass them without seeing their emission (geometry/alpha_mask.h).
//
// A shape whose alpha is the constant 0 is an invisible lamp, as in pbrt-v4 (kroken's sun is
// one): no ray meets it, yet it lights the scene fully, and is sampled by next-event estimation
// and by light paths as if it had no alpha. Since no ray can hit it, it is a DeltaPosition light
// for every strategy's MIS weight, as pbrt-v4 marks it: the strategies that would find it along a
// ray (a camera path hitting it, a light path's start joined to the lens) take no part, and those
// that sample it carry the whole estimate, which stays unbiased.
#pragma once

#include "geometry/alpha_mask.h"
#include "geometry/shape.h"
#include "lights/emission_image.h"
#include "lights/light.h"
#include "spectral/spectrum.h"

#include <memory>

namespace caustica {

class DiffuseAreaLight final : public Light {
  public:
    DiffuseAreaLight(std::shared_ptr<const Shape> shape, SpectrumPtr radiance, float scale,
                     bool two_sided, std::shared_ptr<const AlphaMask> alpha = nullptr,
                     std::shared_ptr<const EmissionImage> image = nullptr);

    LightType type() const override { return invisible_ ? LightType::DeltaPosition : LightType::Area; }
    const Spectrum *emission_spectrum() const override { return image_ ? nullptr : radiance_.get(); }
    SampledSpectrum phi(const SampledWavelengths &lambda) const override;
    std::optional<Bounds3f> spatial_bounds() const override {
        return shape_->bounds();
    }
    // About the shape's normals, diffusely.
    EmissionDirections emission_directions() const override {
        return {shape_->normal_bounds(), 0.f, two_sided_};
    }
    std::optional<LightLiSample> sample_li(const LightSampleContext &ctx, Vec2f u,
                                           const SampledWavelengths &lambda) const override;
    float pdf_li(const LightSampleContext &ctx, Vec3f wi) const override;
    SampledSpectrum L(Vec3f p, Vec3f n, Vec2f uv, Vec3f w,
                      const SampledWavelengths &lambda) const override;
    std::optional<LightLeSample> sample_le(Vec2f u1, Vec2f u2,
                                           const SampledWavelengths &lambda) const override;
    void pdf_le(const Ray &ray, Vec3f n, float *pdf_pos, float *pdf_dir) const override;

    const Shape &shape() const { return *shape_; }
    bool two_sided() const { return two_sided_; }

  private:
    // Whether the alpha mask removes the sampled point (decided by a hash of the point, as
    // pbrt-v4 does).
    bool masked(const ShapeSample &s) const;

    std::shared_ptr<const Shape> shape_;
    std::shared_ptr<const AlphaMask> alpha_;
    std::shared_ptr<const EmissionImage> image_;
    float area_;
    bool uniform_by_area_; // the shape's samples are uniform by area (pdf_le needs no query)
    SpectrumPtr radiance_;
    float scale_;
    bool two_sided_;
    bool invisible_; // alpha is the constant 0 (see the head of this file)
};

}  // namespace caustica
