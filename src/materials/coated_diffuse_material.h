// pbrt-v4's "coateddiffuse" material: a Lambertian base under a dielectric coat (layered_bxdf.h).
#pragma once

#include "materials/coating.h"
#include "materials/material.h"

namespace caustica {

class CoatedDiffuseMaterial final : public Material {
  public:
    CoatedDiffuseMaterial(SpectrumTexturePtr reflectance, Coating coating)
        : reflectance_(std::move(reflectance)), coating_(std::move(coating)) {}
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool is_dispersive() const override { return coating_.is_dispersive(); }
    bool has_specular_lobe() const override { return coating_.may_be_smooth(); }
    bool forms_caustics() const override { return coating_.may_focus_light(); }
    bool has_non_specular_lobe() const override { return true; }
    bool is_wavelength_independent() const override {
        return reflectance_->is_wavelength_independent() && coating_.is_wavelength_independent();
    }

  private:
    SpectrumTexturePtr reflectance_;
    Coating coating_;
};

} // namespace caustica
