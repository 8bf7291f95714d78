// pbrt-v4's "mix" material: at each surface point, one of two materials, the second with
// probability "amount". The choice is a hash of the point and the outgoing direction (as in
// pbrt-v4), so every evaluation at one vertex sees the same material, and over the pixels'
// samples the image is that of the amount-weighted average of the two BSDFs.
//
// The integrators ask the material at a vertex about its interior (a medium, Beer-Lambert
// absorption, a subsurface profile) without knowing the point's choice, so the two materials
// must have none of these: the factory rejects such mixes.
#pragma once

#include "materials/material.h"
#include "textures/texture.h"

namespace caustica {

class MixMaterial final : public Material {
  public:
    MixMaterial(MaterialPtr first, MaterialPtr second, FloatTexturePtr amount)
        : materials_{std::move(first), std::move(second)}, amount_(std::move(amount)) {}
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    // The material chosen at si.
    const Material &choose(const SurfaceInteraction &si) const;
    const Material &resolve(const SurfaceInteraction &si) const override { return choose(si).resolve(si); }

    bool is_dispersive() const override { return either(&Material::is_dispersive); }
    bool has_specular_lobe() const override { return either(&Material::has_specular_lobe); }
    bool forms_caustics() const override { return either(&Material::forms_caustics); }
    bool has_non_specular_lobe() const override { return either(&Material::has_non_specular_lobe); }
    bool is_fluorescent() const override { return either(&Material::is_fluorescent); }
    bool is_wavelength_independent() const override {
        return materials_[0]->is_wavelength_independent() && materials_[1]->is_wavelength_independent();
    }

  private:
    bool either(bool (Material::*property)() const) const {
        return (*materials_[0].*property)() || (*materials_[1].*property)();
    }

    MaterialPtr materials_[2];
    FloatTexturePtr amount_;
};

} // namespace caustica
