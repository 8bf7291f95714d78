// pbrt-v4's "checkerboard" texture: alternating unit cells of "tex1" and "tex2" over the 2D
// texture coordinates, or over the 3D texture-space point ("dimension" 3). Evaluated at the
// point (pbrt box-filters over the ray differentials' footprint, which Caustica does not
// track; pixel sampling does the antialiasing).
#pragma once

#include "textures/texture_evaluation.h"
#include "textures/texture_mapping.h"

#include <variant>

namespace caustica {

// True where tex1 shows: cells whose integer coordinates have an even sum (pbrt's convention).
inline bool checkerboard_even(Vec2f st) {
    return ((int64_t(std::floor(st.x)) + int64_t(std::floor(st.y))) & 1) == 0;
}
inline bool checkerboard_even(Vec3f p) {
    return ((int64_t(std::floor(p.x)) + int64_t(std::floor(p.y)) + int64_t(std::floor(p.z))) & 1) == 0;
}

template <typename Base>
class CheckerboardTexture final : public TextureAdapter<Base, CheckerboardTexture<Base>> {
  public:
    using Mapping = std::variant<TextureMapping2D, TextureMapping3D>;
    CheckerboardTexture(Mapping mapping, TexturePtr<Base> tex1, TexturePtr<Base> tex2)
        : mapping_(std::move(mapping)), tex1_(std::move(tex1)), tex2_(std::move(tex2)) {}

    TextureValue<Base> value(const TextureEvalContext &ctx, const SampledWavelengths *lambda) const {
        bool even = std::visit([&](const auto &m) { return checkerboard_even(m.map(ctx)); }, mapping_);
        return evaluate_texture(even ? *tex1_ : *tex2_, ctx, lambda);
    }
    bool children_wavelength_independent() const {
        return wavelength_independent(*tex1_) && wavelength_independent(*tex2_);
    }

  private:
    Mapping mapping_;
    TexturePtr<Base> tex1_, tex2_;
};

} // namespace caustica
