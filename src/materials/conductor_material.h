// pbrt-v4's "conductor" material: a smooth or rough metal given by its spectral complex index
// of refraction (eta, k), or by an artist's "reflectance" colour r, which is turned into the
// index of a hypothetical metal with eta = 1 and k = 2 sqrt(r) / sqrt(1 - r): the conductor
// Fresnel term at normal incidence, ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2), is then exactly r
// (pbrt-v4's ConductorMaterial).
#pragma once

#include "materials/material.h"
#include "materials/microfacet_roughness.h"
#include "materials/thin_film.h"

namespace caustica {

struct TextureEvalContext;

// A metal's complex index at the wavelengths lambda: (eta, k) from their textures, or, where the
// reflectance texture is given instead, the eta = 1 metal whose normal-incidence reflectance it
// is. Shared by "conductor" and the base of "coatedconductor".
struct ConductorIndex {
    SampledSpectrum eta, k;
};
ConductorIndex conductor_index(const SpectrumTexturePtr &eta, const SpectrumTexturePtr &k,
                               const SpectrumTexturePtr &reflectance, const TextureEvalContext &ctx,
                               const SampledWavelengths &lambda);

class ConductorMaterial final : public Material {
  public:
    // Either eta and k, or reflectance (the others null).
    ConductorMaterial(SpectrumTexturePtr eta, SpectrumTexturePtr k, SpectrumTexturePtr reflectance,
                      MicrofacetRoughness roughness, FilmLayer film = {})
        : eta_(std::move(eta)), k_(std::move(k)), reflectance_(std::move(reflectance)),
          roughness_(std::move(roughness)), film_(std::move(film)) {}
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool has_specular_lobe() const override { return roughness_.may_be_smooth(); }
    bool forms_caustics() const override { return roughness_.may_focus_light(); }
    bool has_non_specular_lobe() const override { return roughness_.may_be_rough(); }
    bool is_wavelength_independent() const override {
        if (film_.may_be_present()) return false; // interference depends on the wavelength
        for (const SpectrumTexturePtr &t : {eta_, k_, reflectance_})
            if (t && !t->is_wavelength_independent()) return false;
        return true;
    }

  private:
    SpectrumTexturePtr eta_, k_, reflectance_;
    MicrofacetRoughness roughness_;
    FilmLayer film_;
};

} // namespace caustica
