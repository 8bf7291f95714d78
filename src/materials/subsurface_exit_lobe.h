// The common shape of the exit lobes of profile subsurface scattering
// (profile_subsurface_material.h): light that the profile brings to a point leaves through the
// surface, so wo points inside (the light arrives through the interior; the caller puts wo
// there) and wi outside, flagged BxDFDiffuseTransmission. Each lobe is a Lambertian lobe shaped by
// a Fresnel factor of the exit direction, sampled by the cosine density; a lobe defines only its
// value for wi outside, exit_value(cos theta_i).
#pragma once

#include "core/sampling.h"
#include "materials/bxdf.h"

namespace caustica {

class SubsurfaceExitLobe : public BxDF {
  public:
    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode) const final {
        if (!(wo.z < 0 && wi.z > 0)) return {};
        return SampledSpectrum(exit_value(wi.z));
    }
    std::optional<BSDFSample> sample_f(Vec3f wo, float, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const final {
        if (!(wo.z < 0) || !allows(flags, SampleFlags::Transmission)) return {};
        BSDFSample s;
        s.wi = sample_cosine_hemisphere(u);
        if (s.wi.z == 0) return {};
        s.f = f(wo, s.wi, mode);
        s.pdf = cosine_hemisphere_pdf(s.wi.z);
        s.flags = BxDFDiffuseTransmission;
        return s;
    }
    float pdf(Vec3f wo, Vec3f wi, TransportMode, SampleFlags flags = SampleFlags::All) const final {
        if (!(wo.z < 0 && wi.z > 0) || !allows(flags, SampleFlags::Transmission)) return 0;
        return cosine_hemisphere_pdf(wi.z);
    }
    BxDFFlags flags() const final { return BxDFDiffuseTransmission; }

  protected:
    ~SubsurfaceExitLobe() = default;
    // The lobe's value towards an outside direction with cosine cos_i > 0.
    virtual float exit_value(float cos_i) const = 0;
};

} // namespace caustica
