// pbrt-v4's "bilerp" texture: bilinear interpolation of four constant values "v00", "v10",
// "v01", "v11" at the corners (s, t) = (0,0), (1,0), (0,1), (1,1) of texture space.
#pragma once

#include "textures/texture_evaluation.h"
#include "textures/texture_mapping.h"

namespace caustica {

template <typename Base> class BilerpTexture final : public TextureAdapter<Base, BilerpTexture<Base>> {
  public:
    BilerpTexture(TextureMapping2D mapping, TexturePtr<Base> v00, TexturePtr<Base> v10,
                  TexturePtr<Base> v01, TexturePtr<Base> v11)
        : mapping_(mapping), v00_(std::move(v00)), v10_(std::move(v10)), v01_(std::move(v01)),
          v11_(std::move(v11)) {}

    TextureValue<Base> value(const TextureEvalContext &ctx, const SampledWavelengths *lambda) const {
        Vec2f st = mapping_.map(ctx).st;
        float s = st.x, t = st.y;
        return evaluate_texture(*v00_, ctx, lambda) * ((1 - s) * (1 - t)) +
               evaluate_texture(*v10_, ctx, lambda) * (s * (1 - t)) +
               evaluate_texture(*v01_, ctx, lambda) * ((1 - s) * t) +
               evaluate_texture(*v11_, ctx, lambda) * (s * t);
    }
    bool children_wavelength_independent() const {
        return wavelength_independent(*v00_) && wavelength_independent(*v10_) &&
               wavelength_independent(*v01_) && wavelength_independent(*v11_);
    }

  private:
    TextureMapping2D mapping_;
    TexturePtr<Base> v00_, v10_, v01_, v11_;
};

} // namespace caustica
