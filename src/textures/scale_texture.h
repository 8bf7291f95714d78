// pbrt-v4's "scale" texture: "tex" times the float texture "scale".
#pragma once

#include "textures/texture_evaluation.h"

namespace caustica {

template <typename Base>
class ScaleTexture final : public TextureAdapter<Base, ScaleTexture<Base>> {
  public:
    ScaleTexture(TexturePtr<Base> tex, FloatTexturePtr scale)
        : tex_(std::move(tex)), scale_(std::move(scale)) {}

    TextureValue<Base> value(const TextureEvalContext &ctx, const SampledWavelengths *lambda) const {
        float s = scale_->evaluate(ctx);
        // Skips the child where the product is known to vanish (pbrt does the same).
        if (s == 0) return TextureValue<Base>(0.f);
        return evaluate_texture(*tex_, ctx, lambda) * s;
    }
    bool children_wavelength_independent() const { return wavelength_independent(*tex_); }

  private:
    TexturePtr<Base> tex_;
    FloatTexturePtr scale_;
};

} // namespace caustica
