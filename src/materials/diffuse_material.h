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

  private:
    SpectrumTexturePtr reflectance_;
};

} // namespace caustica
