// The "disney" material: Burley 2015's Disney BSDF (disney_bxdf.h) with every parameter a value
// or a texture. docs/disney.md lists the parameters, their defaults and the model's choices.
//
// Solids may have Beer-Lambert absorption inside ("transmittance" at "atDistance", as the
// dielectric material), which integrators apply to paths that refracted in. "scatterDistance"
// is stored for the subsurface model (Burley 2015, section 2.4), which is not implemented yet:
// until it is, the diffuse BRDF stands in, which is what the notes use for scatterDistance 0.
#pragma once

#include "materials/disney_bxdf.h"
#include "materials/material.h"
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
    // scatter_distance: per-colour scatter distance d of the normalised diffusion profile, or
    // null.
    DisneyMaterial(DisneyTextures textures, SpectrumPtr eta, bool thin, SpectrumPtr sigma_a,
                   SpectrumTexturePtr scatter_distance);

    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool is_dispersive() const override { return dispersive_; }
    bool has_specular_lobe() const override { return specular_; }
    SampledSpectrum interior_sigma_a(const SampledWavelengths &lambda) const override {
        return sigma_a_ ? sigma_a_->sample(lambda) : SampledSpectrum();
    }
    bool has_interior_absorption() const override { return sigma_a_ != nullptr; }

    bool is_thin() const { return thin_; }
    const SpectrumTexturePtr &scatter_distance() const { return scatter_distance_; }
    // The BxDF's inputs at a point: textures evaluated and clamped to their ranges.
    DisneyParameters parameters(const TextureEvalContext &ctx, const SampledWavelengths &lambda) const;

  private:
    DisneyTextures textures_;
    SpectrumPtr eta_;
    float reference_eta_;
    bool thin_;
    SpectrumPtr sigma_a_;
    SpectrumTexturePtr scatter_distance_;
    // The base colour's luminance when the base colour is a constant (else negative: computed
    // per point, and only when a tint needs it).
    float constant_luminance_ = -1;
    bool dispersive_ = false, specular_ = false;
};

// Reads the "disney" parameters (see docs/disney.md). The index of refraction and the interior
// absorption are read by the material factory, as for "dielectric" (so "eta" may be a float, a
// named glass or any spectrum, or Sellmeier/Cauchy coefficients). Throws InputError at a
// parameter whose constant value is out of range.
MaterialPtr create_disney_material(const ParameterDictionary &params, const NamedTextures &textures,
                                   SpectrumPtr eta, SpectrumPtr interior_sigma_a);

} // namespace caustica
