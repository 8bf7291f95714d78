#include "materials/conductor_material.h"

#include "geometry/interaction.h"
#include "materials/conductor_bxdf.h"

namespace caustica {

BSDF ConductorMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                 ScratchBuffer &scratch) const {
    TextureEvalContext ctx(si);
    SampledSpectrum eta, k;
    if (reflectance_) {
        // r = 1 would need k = infinity; 0.9999 keeps k finite (pbrt clamps the same way).
        SampledSpectrum r = reflectance_->evaluate(ctx, lambda);
        eta = SampledSpectrum(1);
        for (int i = 0; i < NumWavelengths; ++i) {
            float ri = clamp(r[i], 0.f, 0.9999f);
            k[i] = 2 * std::sqrt(ri) / std::sqrt(1 - ri);
        }
    } else {
        eta = eta_->evaluate(ctx, lambda);
        k = k_->evaluate(ctx, lambda);
    }
    auto *bxdf = scratch.make<ConductorBxDF>(roughness_.distribution(ctx), eta, k);
    return BSDF(si.shading.n, si.shading.dpdu, bxdf);
}

} // namespace caustica
