// pbrt-v4's procedural noise textures (pbrt-v4 section 10.6), over Perlin noise:
//  - "fbm": fractional Brownian motion of the texture-space point;
//  - "wrinkled": turbulence, the sum of |noise| octaves;
//  - "windy": waves whose height (6 octaves) is scaled by a slowly varying wind strength
//    (3 octaves at a tenth of the frequency);
//  - "marble": a spectrum, bands of sin(y + variation * fbm) coloured by pbrt-v4's cubic Bezier
//    spline of greys and a dark blue;
//  - "dots": polka dots, one randomly placed dot of radius 0.35 in about half the unit cells of
//    the 2D texture coordinates.
#pragma once

#include "spectral/color_space.h"
#include "textures/perlin_noise.h"
#include "textures/texture_evaluation.h"
#include "textures/texture_mapping.h"

namespace caustica {

// "fbm" and "wrinkled": a sum of octaves of noise at the texture-space point, by fractional
// Brownian motion or by turbulence.
class OctaveNoiseTexture final : public FloatTexture {
  public:
    using OctaveSum = float (*)(Vec3f p, float omega, int octaves, Vec3f dpdx, Vec3f dpdy);
    OctaveNoiseTexture(TextureMapping3D mapping, OctaveSum sum, float omega, int octaves)
        : mapping_(mapping), sum_(sum), omega_(omega), octaves_(octaves) {}
    float evaluate(const TextureEvalContext &ctx) const override {
        return sum_(mapping_.map(ctx), omega_, octaves_, mapping_.map_vector(ctx.dpdx), mapping_.map_vector(ctx.dpdy));
    }

  private:
    TextureMapping3D mapping_;
    OctaveSum sum_;
    float omega_;
    int octaves_;
};

class WindyTexture final : public FloatTexture {
  public:
    explicit WindyTexture(TextureMapping3D mapping) : mapping_(mapping) {}
    float evaluate(const TextureEvalContext &ctx) const override {
        const Vec3f p = mapping_.map(ctx), dpdx = mapping_.map_vector(ctx.dpdx), dpdy = mapping_.map_vector(ctx.dpdy);
        const float wind_strength = fractional_brownian_motion(0.1f * p, 0.5f, 3, 0.1f * dpdx, 0.1f * dpdy);
        const float wave_height = fractional_brownian_motion(p, 0.5f, 6, dpdx, dpdy);
        return std::abs(wind_strength) * wave_height;
    }

  private:
    TextureMapping3D mapping_;
};

class MarbleTexture final : public SpectrumTexture {
  public:
    MarbleTexture(TextureMapping3D mapping, float omega, int octaves, float scale, float variation)
        : mapping_(mapping), omega_(omega), octaves_(octaves), scale_(scale), variation_(variation) {}
    SampledSpectrum evaluate(const TextureEvalContext &ctx,
                             const SampledWavelengths &lambda) const override;
    // The albedo (sRGB) at the texture-space point p, before scaling.
    RGB colour(Vec3f p, Vec3f dpdx, Vec3f dpdy) const;

  private:
    TextureMapping3D mapping_;
    float omega_;
    int octaves_;
    float scale_, variation_;
};

// Whether st lies in a dot. Cells are centred on integer points; a cell holds a dot where the
// noise at its centre is positive, shifted off-centre by up to 0.15 by two more noise values.
bool inside_polka_dot(Vec2f st);

// pbrt-v4's constructor takes (outside, inside) while its scene reader passes ("inside",
// "outside"), so in pbrt-v4 the dots show "outside" (default 0) and the rest "inside" (default
// 1). Scenes are written against that behaviour, so it is kept.
template <typename Base>
class DotsTexture final : public TextureAdapter<Base, DotsTexture<Base>> {
  public:
    DotsTexture(TextureMapping2D mapping, TexturePtr<Base> in_dots, TexturePtr<Base> between_dots)
        : mapping_(mapping), in_dots_(std::move(in_dots)), between_dots_(std::move(between_dots)) {}

    TextureValue<Base> value(const TextureEvalContext &ctx, const SampledWavelengths *lambda) const {
        return evaluate_texture(inside_polka_dot(mapping_.map(ctx).st) ? *in_dots_ : *between_dots_,
                                ctx, lambda);
    }
    bool children_wavelength_independent() const {
        return wavelength_independent(*in_dots_) && wavelength_independent(*between_dots_);
    }

  private:
    TextureMapping2D mapping_;
    TexturePtr<Base> in_dots_, between_dots_;
};

} // namespace caustica
