// "fluorescent" (a Caustica extension; pbrt-v4 has no fluorescence): a diffuse substrate under a
// fluorescent dye (fluorophore.h). Parameters:
//   "spectrum reflectance"  the substrate's (texture allowed; default 0.5)
//   "spectrum absorption"   the fraction of light the dye absorbs, in [0, 1] (required)
//   "spectrum emission"     the shape of the dye's emission spectrum (required)
//   "float quantumyield"    photons emitted per photon absorbed, in [0, 1] (default 1)
// Light the dye does not absorb reaches the substrate and is reflected by it; light it absorbs
// is re-emitted diffusely at longer wavelengths (FluorescentBxDF, ReradiationBxDF).
#pragma once

#include "materials/fluorophore.h"
#include "materials/material.h"
#include "textures/texture.h"

#include <memory>

namespace caustica {

class FluorescentMaterial final : public Material {
  public:
    FluorescentMaterial(SpectrumTexturePtr reflectance, std::shared_ptr<const Fluorophore> dye)
        : reflectance_(std::move(reflectance)), dye_(std::move(dye)) {}
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    const Fluorophore *fluorophore() const override { return dye_.get(); }

  private:
    SpectrumTexturePtr reflectance_;
    std::shared_ptr<const Fluorophore> dye_;
};

} // namespace caustica
