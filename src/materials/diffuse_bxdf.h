// Lambertian reflection: radiance scattered equally in all directions of the hemisphere the
// light arrived from (Lambert 1760). Two-sided, as pbrt's: the lobe follows wo's hemisphere.
#pragma once

#include "core/sampling.h"
#include "materials/bxdf.h"

namespace caustica {

class DiffuseBxDF final : public BxDF {
  public:
    // reflectance is clamped to [0, 1] per wavelength so the BxDF never creates energy.
    explicit DiffuseBxDF(const SampledSpectrum &reflectance) {
        for (int i = 0; i < NumWavelengths; ++i) r_[i] = clamp(reflectance[i], 0.f, 1.f);
    }

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return {};
        return r_ * InvPi;
    }
    std::optional<BSDFSample> sample_f(Vec3f wo, float, Vec2f u, TransportMode,
                                       SampleFlags flags = SampleFlags::All) const override {
        if (!allows(flags, SampleFlags::Reflection) || r_.is_black()) return {};
        Vec3f wi = sample_cosine_hemisphere(u);
        if (wo.z < 0) wi.z = -wi.z;
        float pdf = cosine_hemisphere_pdf(std::abs(wi.z));
        if (pdf == 0) return {};
        BSDFSample s;
        s.f = r_ * InvPi;
        s.wi = wi;
        s.pdf = pdf;
        s.flags = BxDFDiffuseReflection;
        return s;
    }
    float pdf(Vec3f wo, Vec3f wi, TransportMode, SampleFlags flags = SampleFlags::All) const override {
        if (!allows(flags, SampleFlags::Reflection) || !same_hemisphere(wo, wi) || r_.is_black())
            return 0;
        return cosine_hemisphere_pdf(std::abs(wi.z));
    }
    BxDFFlags flags() const override { return r_.is_black() ? BxDFUnset : BxDFDiffuseReflection; }
    BxDFEvaluation evaluate(Vec3f wo, Vec3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi) || r_.is_black()) return {};
        return {r_ * InvPi, cosine_hemisphere_pdf(std::abs(wi.z)), cosine_hemisphere_pdf(std::abs(wo.z))};
    }

  private:
    SampledSpectrum r_;
};

} // namespace caustica
