// Shared plumbing for textures that exist in a float and a spectrum flavour (scale, mix,
// checkerboard, bilerp): each is written once as a template over the texture base class, with
// a value(ctx, lambda) function that the adapter below turns into the base's virtual evaluate.
#pragma once

#include "textures/texture.h"

#include <memory>

namespace caustica {

template <typename Base> using TexturePtr = std::shared_ptr<const Base>;
// float for FloatTexture, SampledSpectrum for SpectrumTexture.
template <typename Base> struct TextureValueOf;
template <> struct TextureValueOf<FloatTexture> { using type = float; };
template <> struct TextureValueOf<SpectrumTexture> { using type = SampledSpectrum; };
template <typename Base> using TextureValue = typename TextureValueOf<Base>::type;

// Evaluates a child texture; lambda is null for float textures, which ignore it.
inline float evaluate_texture(const FloatTexture &t, const TextureEvalContext &ctx,
                              const SampledWavelengths *) {
    return t.evaluate(ctx);
}
inline SampledSpectrum evaluate_texture(const SpectrumTexture &t, const TextureEvalContext &ctx,
                                        const SampledWavelengths *lambda) {
    return t.evaluate(ctx, *lambda);
}
inline bool wavelength_independent(const FloatTexture &) { return true; }
inline bool wavelength_independent(const SpectrumTexture &t) { return t.is_wavelength_independent(); }

// Impl provides value(ctx, lambda) and, for spectra, children_wavelength_independent().
template <typename Base, typename Impl> class TextureAdapter;

template <typename Impl> class TextureAdapter<FloatTexture, Impl> : public FloatTexture {
  public:
    float evaluate(const TextureEvalContext &ctx) const override {
        return static_cast<const Impl &>(*this).value(ctx, nullptr);
    }
};

template <typename Impl> class TextureAdapter<SpectrumTexture, Impl> : public SpectrumTexture {
  public:
    SampledSpectrum evaluate(const TextureEvalContext &ctx,
                             const SampledWavelengths &lambda) const override {
        return static_cast<const Impl &>(*this).value(ctx, &lambda);
    }
    bool is_wavelength_independent() const override {
        return static_cast<const Impl &>(*this).children_wavelength_independent();
    }
};

} // namespace caustica
