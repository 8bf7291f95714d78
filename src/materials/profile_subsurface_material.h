// A material whose subsurface scattering is a separable BSSRDF with a radial profile (pbrt-v3
// section 11.4, pbrt-v4 section 11.4): its BSDF reports light that it sends into the solid from
// outside as one discrete event, a sample flagged BxDFDiffuseTransmission straight into the
// surface (the profile does not depend on the direction light entered by); the integrators then
// sample where the light leaves with probe rays against the profile, and continue through the
// exit lobe there (integrators/common/profile_subsurface.h). The Disney material's diffusion and
// dipole models (disney_material.h) and pbrt-v4's "subsurface" (subsurface_material.h) are such
// materials.
#pragma once

#include "materials/material.h"
#include "materials/subsurface_profile.h"

namespace caustica {

class ProfileSubsurfaceMaterial : public Material {
  public:
    // The profile of light entering at si, for the path's wavelengths, made in scratch.
    virtual const SubsurfaceProfile &entry_profile(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                                   ScratchBuffer &scratch) const = 0;
    // The exit lobe at a point where light leaves (si.wo must point inside there), in scratch.
    virtual BSDF subsurface_exit_bsdf(const SurfaceInteraction &si, ScratchBuffer &scratch) const = 0;
    // A factor on the weight of an exit whose outward normal is exit_normal, for light that
    // entered where the normal is entry_normal (the Disney material's cavity fade); 1 unless a
    // material says otherwise.
    virtual float cavity_fade(Vec3f entry_normal, Vec3f exit_normal) const {
        (void)entry_normal, (void)exit_normal;
        return 1;
    }
    // True where the surface reflects only specularly besides the entry (a smooth boundary):
    // then nothing there can be estimated from photons, and sppm follows the reflection instead.
    virtual bool reflects_only_specularly(const SurfaceInteraction &si) const {
        (void)si;
        return false;
    }
};

} // namespace caustica
