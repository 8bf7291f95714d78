// Textures that are one value everywhere: what a plain "float roughness" 0.1 or
// "rgb reflectance" [.5 .5 .5] parameter becomes when a material asks for a texture.
#pragma once

#include "spectral/spectrum.h"
#include "textures/texture.h"

#include <utility>

namespace caustica {

class ConstantFloatTexture final : public FloatTexture {
  public:
    explicit ConstantFloatTexture(float value) : value_(value) {}
    float evaluate(const TextureEvalContext &) const override { return value_; }
    const float *constant_value() const override { return &value_; }

  private:
    float value_;
};

class ConstantSpectrumTexture final : public SpectrumTexture {
  public:
    explicit ConstantSpectrumTexture(SpectrumPtr spectrum) : spectrum_(std::move(spectrum)) {}
    SampledSpectrum evaluate(const TextureEvalContext &,
                             const SampledWavelengths &lambda) const override {
        return spectrum_->sample(lambda);
    }
    bool is_wavelength_independent() const override { return spectrum_->is_constant(); }
    const SpectrumPtr &spectrum() const { return spectrum_; }

  private:
    SpectrumPtr spectrum_;
};

} // namespace caustica
