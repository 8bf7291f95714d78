// pbrt-v4's "mix" texture: (1 - amount) tex1 + amount tex2, with a float texture "amount"; and
// its "directionmix", the same mix with amount 1 - |n . dir|, so that tex1 shows where the
// surface faces along "dir" and tex2 where it is edge-on.
#pragma once

#include "textures/texture_evaluation.h"

#include <algorithm>
#include <cmath>

namespace caustica {

template <typename Base> class MixTexture final : public TextureAdapter<Base, MixTexture<Base>> {
  public:
    MixTexture(TexturePtr<Base> tex1, TexturePtr<Base> tex2, FloatTexturePtr amount)
        : tex1_(std::move(tex1)), tex2_(std::move(tex2)), amount_(std::move(amount)) {}

    TextureValue<Base> value(const TextureEvalContext &ctx, const SampledWavelengths *lambda) const {
        float amount = amount_->evaluate(ctx);
        // Only the textures with a non-zero weight are evaluated.
        TextureValue<Base> result(0.f);
        if (amount != 1) result = evaluate_texture(*tex1_, ctx, lambda) * (1 - amount);
        if (amount != 0) result = result + evaluate_texture(*tex2_, ctx, lambda) * amount;
        return result;
    }
    bool children_wavelength_independent() const {
        return wavelength_independent(*tex1_) && wavelength_independent(*tex2_);
    }

  private:
    TexturePtr<Base> tex1_, tex2_;
    FloatTexturePtr amount_;
};

// The amount of "directionmix": 1 - |n . direction|, direction a unit vector in render space.
class DirectionMixAmount final : public FloatTexture {
  public:
    explicit DirectionMixAmount(Vec3f direction) : direction_(direction) {}
    float evaluate(const TextureEvalContext &ctx) const override {
        return 1 - std::min(std::abs(dot(ctx.n, direction_)), 1.f);
    }

  private:
    Vec3f direction_;
};

} // namespace caustica
