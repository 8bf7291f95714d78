// Alpha cut-outs, pbrt-v4's "alpha" parameter of every shape (a float or a float texture).
//
// Where alpha is 0 the surface is not there: rays pass and it casts no shadow. Where alpha lies
// between 0 and 1 the surface is stochastically transparent (Enderton et al. 2010): a ray
// stops on it with probability alpha, decided by a number hashed from the ray and the hit, so
// that one ray always gets the same answer and different rays independent ones. In expectation
// the surface then covers the fraction alpha of what lies behind it, in every integrator,
// because every ray meets the same test.
#pragma once

#include "core/rng.h"
#include "textures/texture.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace caustica {

class AlphaMask {
  public:
    explicit AlphaMask(FloatTexturePtr alpha) : alpha_(std::move(alpha)) {}

    // Whether the surface at ctx stops a ray whose uniform number (uniform() below) is u.
    // As pbrt-v4: stopped when alpha >= 1, passed when alpha <= 0, else stopped when u <= alpha.
    bool stops(const TextureEvalContext &ctx, float u) const {
        const float a = alpha_->evaluate(ctx);
        if (a >= 1) return true;
        if (!(a > 0)) return false;
        return u <= a;
    }

    // Whether alpha is the constant 0: the surface is nowhere, and no ray ever stops on it.
    bool removes_everything() const {
        const float *a = alpha_->constant_value();
        return a && !(*a > 0);
    }

    // The alpha at a point where a ray stopped, in (0, 1] (see SurfaceInteraction::coverage).
    float coverage(const TextureEvalContext &ctx) const {
        return std::clamp(alpha_->evaluate(ctx), 0x1p-24f, 1.f);
    }

    // A uniform number in [0, 1) from the bits of the given floats (a ray's origin and
    // direction and where it met the surface).
    template <typename... Floats> static float uniform(Floats... values) {
        const uint64_t h = hash_values(bits(values)...);
        return float(h >> 40) * 0x1p-24f;
    }

  private:
    static uint32_t bits(float f) {
        uint32_t b;
        std::memcpy(&b, &f, sizeof b);
        return b;
    }

    FloatTexturePtr alpha_;
};

// The alpha of a Shape directive, or null when the shape is opaque everywhere ("float alpha" 1,
// pbrt-v4's default, or no parameter).
inline std::shared_ptr<const AlphaMask> make_alpha_mask(FloatTexturePtr alpha) {
    if (!alpha) return nullptr;
    if (const float *a = alpha->constant_value(); a && *a >= 1) return nullptr;
    return std::make_shared<AlphaMask>(std::move(alpha));
}

} // namespace caustica
