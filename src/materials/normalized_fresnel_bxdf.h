// The exit lobe of pbrt-v4's "subsurface" material, its BSSRDF's directional factor S_w (pbrt-v3
// section 11.4.1): light that the profile brings to a point of the surface leaves towards wi
// outside with
//     S_w(wi) = (1 - F(cos theta_i)) / (c pi),    c = 1 - 2 F_1(1 / eta),
// the Fresnel transmittance into the outside, normalised by its first moment F_1 (d'Eon and
// Irving 2011's fit) so that the lobe's cosine-weighted integral is 1: all the energy the profile
// brings leaves. As the Disney exit lobe, wo points inside (the light arrives through the
// interior), wi outside; it is sampled by the cosine. Without pbrt-v4's factor eta^2 in radiance
// mode, which cancels against the entry's 1/eta^2 (subsurface_entry_bxdf.h).
#pragma once

#include "core/sampling.h"
#include "materials/bxdf.h"
#include "materials/fresnel.h"

namespace caustica {

class NormalizedFresnelBxDF final : public BxDF {
  public:
    // eta: the index inside relative to outside; first_moment: F_1(1 / eta).
    NormalizedFresnelBxDF(float eta, float first_moment) : eta_(eta), scale_(InvPi / (1 - 2 * first_moment)) {}

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode) const override {
        if (!(wo.z < 0 && wi.z > 0)) return {};
        return SampledSpectrum((1 - fresnel_dielectric(wi.z, eta_)) * scale_);
    }
    std::optional<BSDFSample> sample_f(Vec3f wo, float, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override {
        if (!(wo.z < 0) || !allows(flags, SampleFlags::Transmission)) return {};
        BSDFSample s;
        s.wi = sample_cosine_hemisphere(u);
        if (s.wi.z == 0) return {};
        s.f = f(wo, s.wi, mode);
        s.pdf = cosine_hemisphere_pdf(s.wi.z);
        s.flags = BxDFDiffuseTransmission;
        return s;
    }
    float pdf(Vec3f wo, Vec3f wi, TransportMode, SampleFlags flags = SampleFlags::All) const override {
        if (!(wo.z < 0 && wi.z > 0) || !allows(flags, SampleFlags::Transmission)) return 0;
        return cosine_hemisphere_pdf(wi.z);
    }
    BxDFFlags flags() const override { return BxDFDiffuseTransmission; }

  private:
    float eta_, scale_;
};

} // namespace caustica
