// pbrt-v4's "subsurface" material: a dielectric boundary (smooth or rough, index eta) over a
// scattering solid rendered as a separable BSSRDF with the tabulated photon beam diffusion
// profile (Habel, Christensen and Jarosz 2013; photon_beam_diffusion.h), as pbrt-v4's
// SubsurfaceMaterial and TabulatedBSSRDF. The path enters through the boundary
// (subsurface_entry_bxdf.h), leaves at a point sampled against the profile, through the
// normalised Fresnel lobe (normalized_fresnel_bxdf.h).
//
// The solid's coefficients, per unit length, come from the first of these that is given:
//   "name"                 a measured medium (subsurface_coefficients.h), with g = 0 (the
//                          tables give reduced scattering);
//   "sigma_a", "sigma_s"   both, as spectrum textures;
//   "reflectance" ("mfp")  the diffuse reflectance the solid should have and its mean free path
//                          (default 1): the single-scattering albedo whose profile reflects it,
//                          and sigma_t = 1 / mfp;
// else pbrt-v4's default, the coefficients of whole milk in mm^-1. All are multiplied by
// "scale" (default 1), and "g" (default 0) is the phase function's asymmetry.
#pragma once

#include "materials/microfacet_roughness.h"
#include "materials/photon_beam_diffusion.h"
#include "materials/profile_subsurface_material.h"
#include "textures/texture.h"

#include <memory>

namespace caustica {

class SubsurfaceMaterial final : public ProfileSubsurfaceMaterial {
  public:
    struct Coefficients {
        SpectrumTexturePtr sigma_a, sigma_s;      // or
        SpectrumTexturePtr reflectance, mfp;
        float scale = 1;
    };
    SubsurfaceMaterial(Coefficients coefficients, float g, float eta, MicrofacetRoughness roughness);

    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool has_specular_lobe() const override { return roughness_.may_be_smooth(); }
    bool forms_caustics() const override { return has_specular_lobe() || roughness_.may_focus_light(); }
    bool has_subsurface() const override { return true; }
    bool has_profile_subsurface() const override { return true; }

    const SubsurfaceProfile &entry_profile(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                           ScratchBuffer &scratch) const override;
    BSDF subsurface_exit_bsdf(const SurfaceInteraction &si, ScratchBuffer &scratch) const override;
    bool reflects_only_specularly(const SurfaceInteraction &si) const override;

  private:
    Coefficients coefficients_;
    float eta_;
    MicrofacetRoughness roughness_;
    BeamDiffusionTable table_;
};

} // namespace caustica
