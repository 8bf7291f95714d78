// Textures: float and spectral functions over a surface.
#pragma once

#include "core/vecmath.h"
#include "spectral/sampled_wavelengths.h"

#include <map>
#include <memory>
#include <string>

namespace caustica {

struct SurfaceInteraction;

struct TextureEvalContext {
    Vec3f p;       // render-space point
    Vec3f n;       // shading normal
    Vec2f uv;
    // Screen-space derivatives of the point (camera/camera_footprint.h), for filtering.
    Vec3f dpdx, dpdy;
    float dudx = 0, dudy = 0, dvdx = 0, dvdy = 0;
    TextureEvalContext() = default;
    explicit TextureEvalContext(const SurfaceInteraction &si);
};

class FloatTexture {
  public:
    virtual ~FloatTexture() = default;
    virtual float evaluate(const TextureEvalContext &ctx) const = 0;
    // Non-null when the texture is one value everywhere (lets materials skip evaluation).
    virtual const float *constant_value() const { return nullptr; }
};

class SpectrumTexture {
  public:
    virtual ~SpectrumTexture() = default;
    virtual SampledSpectrum evaluate(const TextureEvalContext &ctx,
                                     const SampledWavelengths &lambda) const = 0;
    // True when every spectrum the texture can return is constant in wavelength.
    virtual bool is_wavelength_independent() const { return false; }
};

using FloatTexturePtr = std::shared_ptr<const FloatTexture>;
using SpectrumTexturePtr = std::shared_ptr<const SpectrumTexture>;

// How an RGB or spectrum value is turned into a spectrum (pbrt-v4's SpectrumType).
enum class SpectrumType { Albedo, Unbounded, Illuminant };

// Textures declared so far with `Texture "name" "float"|"spectrum" ...`. Spectrum textures are
// kept once per SpectrumType because an RGB texel means a different spectrum for each.
struct NamedTextures {
    std::map<std::string, FloatTexturePtr> float_textures;
    std::map<std::string, SpectrumTexturePtr> albedo, unbounded, illuminant;
    const std::map<std::string, SpectrumTexturePtr> &spectrum(SpectrumType t) const {
        return t == SpectrumType::Albedo ? albedo : (t == SpectrumType::Unbounded ? unbounded : illuminant);
    }
};

} // namespace caustica
