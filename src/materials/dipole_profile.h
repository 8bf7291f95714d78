// The classical dipole diffusion profile of Jensen, Marschner, Levoy and Hanrahan 2001, "A
// Practical Model for Subsurface Light Transport" (section 2.4): multiple scattering in a
// semi-infinite medium with absorption sigma_a, reduced scattering sigma_s' = sigma_s (1 - g) and
// relative index of refraction eta, from a real source at depth z_r below the surface and a
// negative virtual source at height z_v above it, placed so that the fluence meets the
// boundary condition of the index mismatch:
//
//     sigma_t' = sigma_a + sigma_s'          alpha' = sigma_s' / sigma_t'   (reduced albedo)
//     sigma_tr = sqrt(3 sigma_a sigma_t')    (effective transport coefficient)
//     A = (1 + F_dr) / (1 - F_dr)            F_dr = diffuse Fresnel reflectance (fit below)
//     z_r = 1 / sigma_t'                     z_v = z_r (1 + 4 A / 3)
//     d_r = sqrt(r^2 + z_r^2)                d_v = sqrt(r^2 + z_v^2)
//
//     R_d(r) = alpha' / (4 pi) [ z_r (sigma_tr d_r + 1) e^{-sigma_tr d_r} / d_r^3
//                              + z_v (sigma_tr d_v + 1) e^{-sigma_tr d_v} / d_v^3 ],
//
// whose integral over the plane is Jensen's total diffuse reflectance
// R_d = (alpha' / 2) (1 + e^{-(4/3) A sqrt(3 (1 - alpha'))}) e^{-sqrt(3 (1 - alpha'))}.
//
// Sampling inverts the exact radial CDF. Each pole's term integrates in closed form: with
// r dr = d dd, 2 pi int z (sigma d + 1) e^{-sigma d} / d^3 r dr = 2 pi z [-e^{-sigma d} / d], so
// the energy beyond r is (alpha' / 2) sum_poles (z / d) e^{-sigma_tr d}, a decreasing function of
// r that a safeguarded Newton iteration inverts to double precision. The pdf is then exactly
// R_d(r) / R_d per unit area, for every material, with no fitted sampling density.
#pragma once

#include "materials/subsurface_profile.h"

#include <array>

namespace caustica {

// Diffuse Fresnel reflectance of a boundary seen from the inside of a medium of relative index
// eta > 1: the fraction of diffuse (cosine-weighted) light inside that the boundary reflects back.
// Egan and Hilgeman's polynomial fit (1979, "Optical Properties of Inhomogeneous Materials"),
// F_dr = -1.440 / eta^2 + 0.710 / eta + 0.668 + 0.0636 eta, as used by Jensen et al. 2001; within
// 0.002 of the exact hemispherical integral of the Fresnel equations for eta in [1.1, 2].
float diffuse_fresnel_reflectance(float eta);

class DipoleProfile final : public SubsurfaceProfile {
  public:
    // sigma_a and sigma_s_reduced (sigma_s') per unit length, >= 0, per wavelength; eta is the
    // medium's index relative to the outside. A channel with sigma_s' = 0 reflects nothing.
    DipoleProfile(const SampledSpectrum &sigma_a, const SampledSpectrum &sigma_s_reduced,
                  float eta);

    SampledSpectrum evaluate(float r) const override;
    float sample_radius(int channel, float u) const override;
    SampledSpectrum pdf_area(float r) const override;
    SampledSpectrum albedo() const override;
    float max_radius(int channel) const override;

  private:
    struct Channel {
        double sigma_tr = 0;
        double z[2] = {0, 0};          // distances of the real (below) and virtual (above) sources
        double pole_total[2] = {0, 0}; // each pole's share of the total
        double total = 0;              // R_d, the integral over the plane
        double max_radius = 0;
    };
    struct PoleSums {
        double density = 0; // R_d(r)
        double tail = 0;    // the energy beyond r
    };
    static PoleSums evaluate_poles(const Channel &ch, double r);
    // The radius beyond which the fraction `tail` (in (0, 1]) of the energy lies.
    static double radius_with_tail(const Channel &ch, double tail);

    std::array<Channel, NumWavelengths> channels_;
};

} // namespace caustica
