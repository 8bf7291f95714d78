// pbrt-v4's "diffusetransmission" material: Lambertian reflection and transmission
// (diffuse_transmission_bxdf.h), both scaled by "scale".
#pragma once

#include "materials/material.h"
#include "textures/texture.h"

namespace caustica {

class DiffuseTransmissionMaterial final : public Material {
  public:
    DiffuseTransmissionMaterial(SpectrumTexturePtr reflectance, SpectrumTexturePtr transmittance, float scale)
        : reflectance_(std::move(reflectance)), transmittance_(std::move(transmittance)), scale_(scale) {}
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool is_wavelength_independent() const override {
        return reflectance_->is_wavelength_independent() && transmittance_->is_wavelength_independent();
    }

  private:
    SpectrumTexturePtr reflectance_, transmittance_;
    float scale_;
};

} // namespace caustica
