// pbrt-v4's "hair" material: the fibre scattering model of Chiang et al. 2016 (hair_bxdf.h)
// with textured parameters. The absorption inside the fibre comes from the first of
//   "sigma_a"                    the coefficient itself (per unit of fibre radius),
//   "color" (or "reflectance")   the colour the fibre takes after multiple scattering,
//   "eumelanin", "pheomelanin"   pigment concentrations (an absent one is 0),
// that is given, and else from eumelanin 1.3 (brown hair), as in pbrt-v4. The offset across the
// fibre is h = -1 + 2 v from the surface's uv, which pbrt-v4's curves run from 0 to 1 across
// their width.
#pragma once

#include "materials/material.h"
#include "spectral/spectrum.h"
#include "textures/texture.h"

namespace caustica {

class HairMaterial final : public Material {
  public:
    // Exactly one of sigma_a, color and the concentrations is set (either concentration may be
    // null when the other is set).
    struct Absorption {
        SpectrumTexturePtr sigma_a, color;
        FloatTexturePtr eumelanin, pheomelanin;
    };

    HairMaterial(Absorption absorption, FloatTexturePtr eta, FloatTexturePtr beta_m, FloatTexturePtr beta_n,
                 FloatTexturePtr alpha);
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool is_wavelength_independent() const override;

  private:
    SampledSpectrum sigma_a(const TextureEvalContext &ctx, const SampledWavelengths &lambda, float beta_n) const;

    Absorption absorption_;
    // The spectrum of constant concentrations, made once.
    SpectrumPtr concentration_sigma_a_;
    FloatTexturePtr eta_, beta_m_, beta_n_, alpha_;
};

} // namespace caustica
