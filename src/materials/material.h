// Materials turn textures at a surface point into a BSDF for the path's wavelengths.
#pragma once

#include "core/scratch_buffer.h"
#include "materials/bsdf.h"
#include "spectral/sampled_wavelengths.h"

#include <memory>

namespace caustica {

class Fluorophore;
class Medium;
class ShadingPerturbation;
struct SurfaceInteraction;

class Material {
  public:
    virtual ~Material() = default;
    // The BxDF is allocated in scratch; lambda is not modified here (dispersion is reported by
    // BSDFSample::dispersive and acted on by the integrator).
    virtual BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                          ScratchBuffer &scratch) const = 0;
    // Scene analysis: does this material make the scattering direction depend on wavelength?
    virtual bool is_dispersive() const { return false; }
    // Does any of its lobes include a delta (perfectly specular) component?
    virtual bool has_specular_lobe() const { return false; }
    // Can it focus light into a caustic: a specular lobe, or a near-specular one
    // (MicrofacetRoughness::may_focus_light)?
    virtual bool forms_caustics() const { return has_specular_lobe(); }
    // Does any of its lobes scatter diffusely or glossily (so it can receive a caustic)?
    virtual bool has_non_specular_lobe() const { return true; }
    virtual bool has_subsurface() const { return false; }
    // Does it shift light to other wavelengths (fluorescent_material.h)? Its own dye, if it has one.
    virtual bool is_fluorescent() const { return fluorophore() != nullptr; }
    virtual const Fluorophore *fluorophore() const { return nullptr; }
    // Subsurface scattering by a diffusion profile (a BSSRDF), which the integrators sample with
    // probe rays (integrators/common/profile_subsurface.h) rather than as a BSDF lobe.
    virtual bool has_profile_subsurface() const { return false; }
    // Beer-Lambert absorption coefficient (per unit length) of the material's interior, for
    // dielectrics given sigma_a or a transmittance colour at a distance. Integrators track when a
    // path is inside and attenuate by exp(-sigma_a * distance). Zero when the interior is clear.
    virtual SampledSpectrum interior_sigma_a(const SampledWavelengths &lambda) const {
        (void)lambda;
        return {};
    }
    virtual bool has_interior_absorption() const { return false; }
    // Scene analysis: true when nothing the material evaluates (textures, indices, interior
    // coefficients) depends on wavelength, so that it scatters every wavelength alike. False
    // unless a material shows it (see SceneFeatures::achromatic).
    virtual bool is_wavelength_independent() const { return false; }
    // A participating medium that fills the material's interior (the random-walk subsurface
    // volume of the Disney material). Paths that cross the surface inwards enter it, whatever the
    // shape's MediumInterface says (medium_interface.h). When its coefficients come from textures
    // (a textured baseColor), the material makes one per entry point, for the path's wavelengths,
    // in scratch: then the first form is null, and the second gives the medium at si.
    virtual bool has_interior_medium() const { return false; }
    virtual const Medium *interior_medium() const { return nullptr; }
    virtual const Medium *interior_medium(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                          ScratchBuffer &scratch) const {
        (void)si, (void)lambda, (void)scratch;
        return interior_medium();
    }
    // The material that scatters at si: itself, except for a mix, which chooses one there.
    virtual const Material &resolve(const SurfaceInteraction &si) const {
        (void)si;
        return *this;
    }

    // Bump or normal mapping ("displacement", "normalmap"), which shade() applies to the
    // shading frame before the BSDF is made; null when the material has neither.
    const ShadingPerturbation *shading_perturbation() const { return shading_perturbation_.get(); }
    void set_shading_perturbation(std::shared_ptr<const ShadingPerturbation> perturbation) {
        shading_perturbation_ = std::move(perturbation);
    }

  private:
    std::shared_ptr<const ShadingPerturbation> shading_perturbation_;
};

using MaterialPtr = std::shared_ptr<const Material>;

// What a path meets at a surface point with a material: its BSDF, and (in si.interior) the
// medium inside, which medium_after() needs when the path crosses into it. Both live in scratch,
// unless media_scratch is given: a medium made for this point (a random walk's interior under a
// textured colour) then lives there, for a caller that keeps points inside it longer than their
// BSDFs. A bump or normal map of the material (of the chosen one, for a mix) first tilts
// si.shading.
BSDF shade(SurfaceInteraction &si, const SampledWavelengths &lambda, ScratchBuffer &scratch,
           ScratchBuffer *media_scratch = nullptr);

} // namespace caustica
