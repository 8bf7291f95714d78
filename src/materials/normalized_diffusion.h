// Burley's normalized diffusion profile (Burley 2015, "Extending the Disney BRDF to a BSDF with
// Integrated Subsurface Scattering", section 2.4, eqs. 5 and 6; Christensen and Burley 2015,
// "Approximate Reflectance Profiles for Efficient Subsurface Scattering"):
//
//     R(r) = A (e^{-r/d} + e^{-r/(3d)}) / (8 pi d r),
//
// a fit to Monte Carlo simulations of the full profile, single scattering included. It is
// normalised: 2 pi int_0^inf r R(r) dr = A exactly (eq. 6), so the surface's diffuse colour A is
// reached without albedo inversion, and as d -> 0 all the energy gathers at r = 0 and the
// profile becomes the diffuse BRDF's A.
//
// The shape parameter d is Disney's "scatterDistance", per colour, used as is: the notes "expose
// the parameter d directly to artists as scatterDistance". Christensen and Burley write the same
// profile as A s (e^{-s r/l} + e^{-s r/(3 l)}) / (8 pi l r) with a physical length l and a fitted
// s(A), which is d = l / s; subsurface_coefficients.h uses that relation to turn (A, d) into
// a medium for a random walk.
#pragma once

#include "materials/subsurface_profile.h"

namespace caustica {

class NormalizedDiffusionProfile final : public SubsurfaceProfile {
  public:
    // albedo: A per wavelength (the diffuse colour; [0, 1] for energy conservation).
    // scatter_distance: d >= 0 per wavelength, in scene units. A channel with d = 0 is not
    // diffusion but the BRDF limit, whose energy sits at r = 0 where no probe can find it: the
    // profile gives such a channel no energy (R = 0, albedo() 0, never sampled), and the caller
    // shades it with the diffuse BRDF, as Burley does for scatterDistance 0.
    NormalizedDiffusionProfile(const SampledSpectrum &albedo,
                               const SampledSpectrum &scatter_distance);

    SampledSpectrum evaluate(float r) const override;
    float sample_radius(int channel, float u) const override;
    SampledSpectrum pdf_area(float r) const override;
    SampledSpectrum albedo() const override;
    float max_radius(int channel) const override;

  private:
    // R(r) / A, the profile's own density per unit area, for one channel.
    float shape(int channel, float r) const;

    SampledSpectrum albedo_, d_;
};

} // namespace caustica
