// pbrt-v4's "diffuse" material: Lambertian reflection with a textured reflectance.
#pragma once

#include "materials/material.h"
#include "textures/texture.h"

namespace caustica {

class DiffuseMaterial final : public Material {
  public:
    explicit DiffuseMaterial(SpectrumTexturePtr reflectance) : reflectance_(std::move(reflectance)) {}
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool is_wavelength_independent() const override { return reflectance_->is_wavelength_independent(); }

  private:
    SpectrumTexturePtr reflectance_;
};

} // namespace caustica
