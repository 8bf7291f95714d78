// The photon beam diffusion (PBD) profile of Habel, Christensen and Jarosz 2013, "Photon Beam
// Diffusion: A Hybrid Monte Carlo Method for Subsurface Scattering", tabulated as pbrt-v4's
// "subsurface" material tabulates it ("Physically Based Rendering", 3rd ed., section 15.5).
//
// Light entering a semi-infinite medium at normal incidence is followed along its refracted beam:
// single scattering is integrated exactly along the beam, and the light scattered more than once
// is the sum of diffusion dipoles placed at points along the beam, each with the boundary
// condition of the index mismatch. Both depend on the medium only through its single-scattering
// albedo rho = sigma_s / sigma_t once distances are measured in mean free paths ("optical" radius
// r sigma_t), and the profile of radius r scales as sigma_t^2 R(r sigma_t). So one table over
// (rho, optical radius), made for the material's g and eta, serves every sigma_a and sigma_s; a
// bicubic Catmull-Rom spline (core/catmull_rom.h) interpolates it.
#pragma once

#include "materials/subsurface_profile.h"

#include <array>
#include <vector>

namespace caustica {

// The first and second moments int_0^1 F(mu) mu^i dmu of the Fresnel reflectance F(mu) of light
// meeting the boundary from inside a medium of relative index eta (d'Eon and Irving's polynomial
// fits, 2011, "A Quantized-Diffusion Model for Rendering Translucent Materials"; within 0.002 of
// the integrals for eta in [1.1, 2]). They set the diffusion boundary condition.
float fresnel_moment1(float eta);
float fresnel_moment2(float eta);

// The two terms of the profile, per unit area at distance r from where a unit of power entered
// (normally) a medium with absorption and scattering coefficients sigma_a, sigma_s, Henyey-
// Greenstein asymmetry g and relative index eta. Each is a 100-point stratified estimate of an
// integral along the refracted beam, as pbrt-v4 computes them.
float beam_diffusion_single_scattering(float sigma_a, float sigma_s, float g, float eta, float r);
float beam_diffusion_multiple_scattering(float sigma_a, float sigma_s, float g, float eta,
                                         float r);

// The profile of a medium with sigma_t = 1, tabulated over its single-scattering albedo and the
// radius (pbrt-v4's BSSRDFTable).
struct BeamDiffusionTable {
    static constexpr int RhoCount = 100, RadiusCount = 64;
    // rho from 0 to 1, denser towards 1, where the profile changes fastest.
    std::vector<float> rho;
    // Optical radii 0, 0.0025 and then growing by 1.2 per step, to 203 mean free paths.
    std::vector<float> radius;
    // 2 pi r R(r) at (rho[i], radius[j]) in entry i * RadiusCount + j: the radial density, which
    // the spline interpolates better than R(r) itself (it is 0 at r = 0 where R is infinite).
    std::vector<float> profile;
    // Each rho's total diffuse reflectance: the integral of the spline of its row.
    std::vector<float> rho_eff;
    // Each row's running integral, for sampling the radius.
    std::vector<float> profile_cdf;
};

// The table for asymmetry g and relative index eta (pbrt-v4's ComputeBeamDiffusionBSSRDF).
BeamDiffusionTable compute_beam_diffusion_table(float g, float eta);

// The coefficients that give a profile of total diffuse reflectance `reflectance` (in [0, 1];
// above the table's largest rho_eff it is that one) and mean free path mfp > 0, per wavelength:
// the rho whose rho_eff is the reflectance, and sigma_t = 1 / mfp (pbrt-v4's
// SubsurfaceFromDiffuse).
void beam_diffusion_from_diffuse(const BeamDiffusionTable &table,
                                 const SampledSpectrum &reflectance, const SampledSpectrum &mfp,
                                 SampledSpectrum *sigma_a, SampledSpectrum *sigma_s);

// The tabulated profile of a medium with coefficients sigma_a, sigma_s (per unit length, >= 0)
// per wavelength (pbrt-v4's TabulatedBSSRDF). Holds a pointer to the table, which must outlive
// it, and nothing that needs destroying, so it can live in a ScratchBuffer.
class BeamDiffusionProfile final : public SubsurfaceProfile {
  public:
    BeamDiffusionProfile(const BeamDiffusionTable &table, const SampledSpectrum &sigma_a,
                         const SampledSpectrum &sigma_s);

    SampledSpectrum evaluate(float r) const override;
    float sample_radius(int channel, float u) const override;
    SampledSpectrum pdf_area(float r) const override;
    SampledSpectrum albedo() const override;
    float max_radius(int channel) const override;

  private:
    // R(r) per unit area for channel c, in the units of the coefficients; 0 beyond the table.
    float profile_per_area(int c, float r) const;

    const BeamDiffusionTable *table_;
    std::array<float, NumWavelengths> sigma_t_{}, rho_{}, albedo_{}, max_radius_{};
};

} // namespace caustica
