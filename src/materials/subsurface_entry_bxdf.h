// The boundary of pbrt-v4's "subsurface" material (subsurface_material.h): a dielectric interface
// (smooth or rough) whose transmitted light does not refract into a volume but enters the
// separable BSSRDF, to leave elsewhere by the profile (profile_subsurface_material.h).
//
// From outside, sampling draws from the dielectric. A reflection is returned as the dielectric
// returns it. A transmission is the entry: the profile ignores the direction light entered by,
// so it is returned straight into the surface, flagged BxDFDiffuseTransmission, with f |cos| /
// pdf the dielectric's transmission weight without its 1/eta^2: the radiance's spreading at
// entry and its gathering at the exit cancel (pbrt-v4 divides by eta^2 here and multiplies the
// exit lobe by eta^2 again), so the entry carries (1 - F(wo)) in both transport modes, and the
// exit lobe (normalized_fresnel_bxdf.h) carries (1 - F(wi)): the BSSRDF is symmetric. f() and
// pdf() are the dielectric's reflection alone: no light scatters into a direction inside.
// From inside (a ray that reached the back of an open surface), it is the plain dielectric.
#pragma once

#include "materials/dielectric_bxdf.h"

namespace caustica {

class SubsurfaceEntryBxDF final : public BxDF {
  public:
    explicit SubsurfaceEntryBxDF(const DielectricBxDF &boundary) : boundary_(boundary) {}

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode mode) const override;
    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override;
    float pdf(Vec3f wo, Vec3f wi, TransportMode mode, SampleFlags flags = SampleFlags::All) const override;
    BxDFFlags flags() const override { return boundary_.flags() | BxDFDiffuseTransmission; }

  private:
    DielectricBxDF boundary_;
};

} // namespace caustica
