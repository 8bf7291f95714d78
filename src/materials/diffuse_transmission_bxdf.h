// Lambertian reflection and Lambertian transmission together: a thin diffusing sheet (paper,
// a lampshade, a leaf) that scatters the fraction R of the light back into the hemisphere it came
// from and the fraction T into the other one, each with a constant radiance (pbrt-v4's
// DiffuseTransmissionBxDF, 4th ed. section 9.2). There is no refraction, so no eta: the BxDF is
// symmetric and the same in both transport modes.
#pragma once

#include "core/sampling.h"
#include "materials/bxdf.h"

namespace caustica {

class DiffuseTransmissionBxDF final : public BxDF {
  public:
    // r and t are clamped to [0, 1] per wavelength.
    DiffuseTransmissionBxDF(const SampledSpectrum &r, const SampledSpectrum &t) {
        for (int i = 0; i < NumWavelengths; ++i) {
            r_[i] = clamp(r[i], 0.f, 1.f);
            t_[i] = clamp(t[i], 0.f, 1.f);
        }
    }

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode) const override {
        return (same_hemisphere(wo, wi) ? r_ : t_) * InvPi;
    }
    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override {
        const Lobes l = lobes(flags);
        if (l.pr + l.pt == 0) return {};
        BSDFSample s;
        s.wi = sample_cosine_hemisphere(u);
        // The lobe is chosen by the larger lane of each (pbrt-v4 does the same).
        const bool reflect = uc < l.pr / (l.pr + l.pt);
        if ((wo.z < 0) == reflect) s.wi.z = -s.wi.z;
        s.pdf = cosine_hemisphere_pdf(std::abs(s.wi.z)) * (reflect ? l.pr : l.pt) / (l.pr + l.pt);
        if (s.pdf == 0) return {};
        s.f = f(wo, s.wi, mode);
        s.flags = reflect ? BxDFDiffuseReflection : BxDFDiffuseTransmission;
        return s;
    }
    float pdf(Vec3f wo, Vec3f wi, TransportMode, SampleFlags flags = SampleFlags::All) const override {
        const Lobes l = lobes(flags);
        if (l.pr + l.pt == 0) return 0;
        return cosine_hemisphere_pdf(std::abs(wi.z)) * (same_hemisphere(wo, wi) ? l.pr : l.pt) / (l.pr + l.pt);
    }
    BxDFFlags flags() const override {
        BxDFFlags f = BxDFUnset;
        if (!r_.is_black()) f = f | BxDFDiffuseReflection;
        if (!t_.is_black()) f = f | BxDFDiffuseTransmission;
        return f;
    }

  private:
    struct Lobes {
        float pr, pt;
    };
    Lobes lobes(SampleFlags flags) const {
        return {allows(flags, SampleFlags::Reflection) ? r_.max_value() : 0.f,
                allows(flags, SampleFlags::Transmission) ? t_.max_value() : 0.f};
    }

    SampledSpectrum r_, t_;
};

} // namespace caustica
