// pbrt-v4's "checkerboard" texture: alternating unit cells of "tex1" and "tex2" over the 2D
// texture coordinates, or over the 3D texture-space point ("dimension" 3). As in pbrt-v4 the
// checks are filtered over the pixel's footprint: the pattern convolved in closed form with a
// triangle filter 1.5 footprints wide per axis, which blends the two textures near edges and
// to their mean far away (without a footprint, the sharp pattern).
#pragma once

#include "textures/texture_evaluation.h"
#include "textures/texture_mapping.h"

#include <cstdint>
#include <variant>

namespace caustica {

// The checkerboard along one axis, +1 on even cells and -1 on odd ones, filtered by a triangle of
// half-width r: the second difference of its twice-integrated form (pbrt-v4's Checkerboard).
inline float filtered_check(float x, float r) {
    if (std::floor(x - r) == std::floor(x + r)) return (int64_t(std::floor(x)) & 1) ? -1.f : 1.f;
    const auto twice_integrated = [](float v) {
        const float y = v / 2 - std::floor(v / 2) - 0.5f;
        return v / 2 + y * (1 - 2 * std::abs(y));
    };
    return (twice_integrated(x + r) - 2 * twice_integrated(x) + twice_integrated(x - r)) / sqr(r);
}

// How much of tex2 shows: 0 inside cells whose integer coordinates have an even sum (tex1, pbrt's
// convention), 1 inside the others, between them where the footprint spans an edge.
inline float checkerboard_weight(const TexCoord2D &c) {
    const float ds = 1.5f * std::max(std::abs(c.dsdx), std::abs(c.dsdy));
    const float dt = 1.5f * std::max(std::abs(c.dtdx), std::abs(c.dtdy));
    return 0.5f - filtered_check(c.st.x, ds) * filtered_check(c.st.y, dt) / 2;
}
inline float checkerboard_weight(Vec3f p, Vec3f dpdx, Vec3f dpdy) {
    float product = 1;
    for (int i = 0; i < 3; ++i) product *= filtered_check(p[i], 1.5f * std::max(std::abs(dpdx[i]), std::abs(dpdy[i])));
    return 0.5f - product / 2;
}

template <typename Base>
class CheckerboardTexture final : public TextureAdapter<Base, CheckerboardTexture<Base>> {
  public:
    using Mapping = std::variant<TextureMapping2D, TextureMapping3D>;
    CheckerboardTexture(Mapping mapping, TexturePtr<Base> tex1, TexturePtr<Base> tex2)
        : mapping_(std::move(mapping)), tex1_(std::move(tex1)), tex2_(std::move(tex2)) {}

    TextureValue<Base> value(const TextureEvalContext &ctx, const SampledWavelengths *lambda) const {
        const float w = weight(ctx);
        if (w == 0) return evaluate_texture(*tex1_, ctx, lambda);
        if (w == 1) return evaluate_texture(*tex2_, ctx, lambda);
        return evaluate_texture(*tex1_, ctx, lambda) * (1 - w) + evaluate_texture(*tex2_, ctx, lambda) * w;
    }
    bool children_wavelength_independent() const {
        return wavelength_independent(*tex1_) && wavelength_independent(*tex2_);
    }

  private:
    float weight(const TextureEvalContext &ctx) const {
        if (const auto *m = std::get_if<TextureMapping2D>(&mapping_)) return checkerboard_weight(m->map(ctx));
        const auto &m = std::get<TextureMapping3D>(mapping_);
        return checkerboard_weight(m.map(ctx), m.map_vector(ctx.dpdx), m.map_vector(ctx.dpdy));
    }

    Mapping mapping_;
    TexturePtr<Base> tex1_, tex2_;
};

} // namespace caustica
