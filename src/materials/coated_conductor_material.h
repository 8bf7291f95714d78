// pbrt-v4's "coatedconductor" material: a metal (smooth or rough; given by eta and k, or by a
// reflectance colour as in conductor_material.h) under a dielectric coat (layered_bxdf.h).
// The metal's index is relative to the coat it lies under, not to air: eta and k are divided by
// the coat's index (the fix of pbrt-v4 issue #342).
#pragma once

#include "materials/coating.h"
#include "materials/material.h"

namespace caustica {

class CoatedConductorMaterial final : public Material {
  public:
    // Either eta and k, or reflectance (the others null).
    CoatedConductorMaterial(SpectrumTexturePtr eta, SpectrumTexturePtr k, SpectrumTexturePtr reflectance,
                            MicrofacetRoughness roughness, Coating coating)
        : eta_(std::move(eta)), k_(std::move(k)), reflectance_(std::move(reflectance)),
          roughness_(std::move(roughness)), coating_(std::move(coating)) {}
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool is_dispersive() const override { return coating_.is_dispersive(); }
    bool has_specular_lobe() const override { return coating_.may_be_smooth() || roughness_.may_be_smooth(); }
    bool forms_caustics() const override { return coating_.may_focus_light() || roughness_.may_focus_light(); }
    bool has_non_specular_lobe() const override {
        return coating_.roughness.may_be_rough() || roughness_.may_be_rough() || coating_.may_scatter();
    }
    bool is_wavelength_independent() const override {
        for (const SpectrumTexturePtr &t : {eta_, k_, reflectance_})
            if (t && !t->is_wavelength_independent()) return false;
        return coating_.is_wavelength_independent();
    }

  private:
    SpectrumTexturePtr eta_, k_, reflectance_;
    MicrofacetRoughness roughness_;
    Coating coating_;
};

} // namespace caustica
