// The exit lobe of pbrt-v4's "subsurface" material, its BSSRDF's directional factor S_w (pbrt-v3
// section 11.4.1): light that the profile brings to a point of the surface leaves towards wi
// outside with
//     S_w(wi) = (1 - F(cos theta_i)) / (c pi),    c = 1 - 2 F_1(1 / eta),
// the Fresnel transmittance into the outside, normalised by its first moment F_1 (d'Eon and
// Irving 2011's fit) so that the lobe's cosine-weighted integral is 1: all the energy the profile
// brings leaves (subsurface_exit_lobe.h). Without pbrt-v4's factor eta^2 in radiance mode, which
// cancels against the entry's 1/eta^2 (subsurface_entry_bxdf.h).
#pragma once

#include "materials/fresnel.h"
#include "materials/subsurface_exit_lobe.h"

namespace caustica {

class NormalizedFresnelBxDF final : public SubsurfaceExitLobe {
  public:
    // eta: the index inside relative to outside; first_moment: F_1(1 / eta).
    NormalizedFresnelBxDF(float eta, float first_moment) : eta_(eta), scale_(InvPi / (1 - 2 * first_moment)) {}

  protected:
    float exit_value(float cos_i) const override { return (1 - fresnel_dielectric(cos_i, eta_)) * scale_; }

  private:
    float eta_, scale_;
};

} // namespace caustica
