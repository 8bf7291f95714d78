// pbrt-v4's "measured" material: reflectance tabulated in an RGL BSDF file ("string filename"),
// evaluated and sampled by MeasuredBxDF (measured_bxdf.h). It has no other parameters besides
// the shading perturbations every material takes ("displacement", "normalmap").
#pragma once

#include "materials/material.h"
#include "materials/measured_bxdf.h"

#include <memory>

namespace caustica {

class MeasuredMaterial final : public Material {
  public:
    explicit MeasuredMaterial(std::shared_ptr<const MeasuredBRDF> brdf) : brdf_(std::move(brdf)) {}
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;

  private:
    std::shared_ptr<const MeasuredBRDF> brdf_;
};

} // namespace caustica
