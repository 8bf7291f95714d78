// The "disney" material: Burley 2015's Disney BSDF (disney_bxdf.h) with every parameter a value
// or a texture. docs/disney.md lists the parameters, their defaults and the model's choices.
//
// Solids may have Beer-Lambert absorption inside ("transmittance" at "atDistance", as the
// dielectric material), which integrators apply to paths that refracted in. A solid with a
// non-zero "scatterDistance" has path-traced subsurface scattering (Burley 2015, section 2.5):
// its interior is a homogeneous medium, isotropic, whose single-scattering albedo makes the
// surface reflect baseColor (random_walk_albedo.h) and whose mean free path gives the walk the
// spread of the normalised diffusion profile with d = scatterDistance; the BxDF's Lambertian
// part becomes the crossing into it (disney_bxdf.h). The interior absorption, if any, adds to the
// medium's. The volume is one per object, so baseColor and scatterDistance must then be
// constants (a texture is an error).
#pragma once

#include "materials/disney_bxdf.h"
#include "materials/material.h"
#include "media/medium.h"
#include "spectral/spectrum.h"
#include "textures/texture.h"

namespace caustica {

class ParameterDictionary;

struct DisneyTextures {
    SpectrumTexturePtr base_color;
    FloatTexturePtr metallic, roughness, anisotropic, specular_tint, sheen, sheen_tint, clearcoat,
        clearcoat_gloss, spec_trans;
    // Thin surfaces only (null for solids).
    FloatTexturePtr diff_trans, flatness;
};

class DisneyMaterial final : public Material {
  public:
    // eta: index of the inside relative to the outside (a constant or a dispersion curve).
    // sigma_a: interior absorption per unit length, or null (always null for thin surfaces).
    // subsurface: the random-walk interior medium, or null (no subsurface scattering).
    DisneyMaterial(DisneyTextures textures, SpectrumPtr eta, bool thin, SpectrumPtr sigma_a, MediumPtr subsurface);

    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool is_dispersive() const override { return dispersive_; }
    bool has_specular_lobe() const override { return specular_; }
    SampledSpectrum interior_sigma_a(const SampledWavelengths &lambda) const override {
        return sigma_a_ ? sigma_a_->sample(lambda) : SampledSpectrum();
    }
    bool has_interior_absorption() const override { return sigma_a_ != nullptr; }
    bool has_subsurface() const override { return subsurface_ != nullptr; }
    const Medium *interior_medium() const override { return subsurface_.get(); }

    bool is_thin() const { return thin_; }
    // The BxDF's inputs at a point: textures evaluated and clamped to their ranges.
    DisneyParameters parameters(const TextureEvalContext &ctx, const SampledWavelengths &lambda) const;

  private:
    DisneyTextures textures_;
    SpectrumPtr eta_;
    float reference_eta_;
    bool thin_;
    SpectrumPtr sigma_a_;
    MediumPtr subsurface_;
    // The base colour's luminance when the base colour is a constant (else negative: computed
    // per point, and only when a tint needs it).
    float constant_luminance_ = -1;
    bool dispersive_ = false, specular_ = false;
};

// The random-walk interior for baseColor `albedo` and `scatter_distance` (both reflectances /
// lengths per wavelength), with the solid's Beer-Lambert absorption (or null) added.
MediumPtr create_random_walk_medium(SpectrumPtr albedo, SpectrumPtr scatter_distance, SpectrumPtr interior_sigma_a);

// Reads the "disney" parameters (see docs/disney.md). The index of refraction and the interior
// absorption are read by the material factory, as for "dielectric" (so "eta" may be a float, a
// named glass or any spectrum, or Sellmeier/Cauchy coefficients). Throws InputError at a
// parameter whose constant value is out of range.
MaterialPtr create_disney_material(const ParameterDictionary &params, const NamedTextures &textures,
                                   SpectrumPtr eta, SpectrumPtr interior_sigma_a);

} // namespace caustica
