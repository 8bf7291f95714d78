#include "materials/conductor_material.h"

#include "geometry/interaction.h"
#include "materials/conductor_bxdf.h"

namespace caustica {

ConductorIndex conductor_index(const SpectrumTexturePtr &eta, const SpectrumTexturePtr &k,
                               const SpectrumTexturePtr &reflectance, const TextureEvalContext &ctx,
                               const SampledWavelengths &lambda) {
    if (!reflectance) return {eta->evaluate(ctx, lambda), k->evaluate(ctx, lambda)};
    // r = 1 would need k = infinity; 0.9999 keeps k finite (pbrt clamps the same way).
    const SampledSpectrum r = reflectance->evaluate(ctx, lambda);
    ConductorIndex index{SampledSpectrum(1), SampledSpectrum(0)};
    for (int i = 0; i < NumWavelengths; ++i) {
        const float ri = clamp(r[i], 0.f, 0.9999f);
        index.k[i] = 2 * std::sqrt(ri) / std::sqrt(1 - ri);
    }
    return index;
}

BSDF ConductorMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                 ScratchBuffer &scratch) const {
    const TextureEvalContext ctx(si);
    const ConductorIndex index = conductor_index(eta_, k_, reflectance_, ctx, lambda);
    auto *bxdf = scratch.make<ConductorBxDF>(roughness_.distribution(ctx), index.eta, index.k, film_.at(ctx, lambda));
    return BSDF(si.shading.n, si.shading.dpdu, bxdf);
}

} // namespace caustica
