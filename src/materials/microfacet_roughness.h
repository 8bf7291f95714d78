// The roughness parameters shared by rough materials ("uroughness", "vroughness", or
// "roughness" for both, and "remaproughness"), turned into a GGX distribution at a surface point.
#pragma once

#include "materials/microfacet.h"
#include "textures/texture.h"

namespace caustica {

struct MicrofacetRoughness {
    FloatTexturePtr u, v;
    // pbrt-v4's remaproughness: roughness values are mapped to alpha by roughness_to_alpha;
    // otherwise they are alpha directly.
    bool remap = true;

    TrowbridgeReitzDistribution distribution(const TextureEvalContext &ctx) const {
        float ru = std::max(0.f, u->evaluate(ctx)), rv = std::max(0.f, v->evaluate(ctx));
        if (remap) {
            ru = TrowbridgeReitzDistribution::roughness_to_alpha(ru);
            rv = TrowbridgeReitzDistribution::roughness_to_alpha(rv);
        }
        return {ru, rv};
    }
    // Whether some point may be effectively smooth (a delta lobe): known exactly for constant
    // roughness, conservatively true for textured roughness.
    bool may_be_smooth() const {
        if (!u->constant_value() || !v->constant_value()) return true;
        return distribution(TextureEvalContext()).effectively_smooth();
    }
    // Whether some point may be smooth enough to focus light into a caustic: a delta lobe, or a
    // lobe so narrow (alpha below NearSpecularAlpha) that the paths through it are, for light
    // transport, nearly specular: camera paths reach the light behind it by chance alone, and
    // connections through it are almost always zero.
    static constexpr float NearSpecularAlpha = 0.05f;
    bool may_focus_light() const {
        if (!u->constant_value() || !v->constant_value()) return true;
        const TrowbridgeReitzDistribution d = distribution(TextureEvalContext());
        return std::max(d.alpha_x(), d.alpha_y()) < NearSpecularAlpha;
    }
    bool may_be_rough() const {
        if (!u->constant_value() || !v->constant_value()) return true;
        return !distribution(TextureEvalContext()).effectively_smooth();
    }
};

} // namespace caustica
