#include "materials/coated_conductor_material.h"

#include "geometry/interaction.h"
#include "materials/conductor_bxdf.h"

namespace caustica {

BSDF CoatedConductorMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                       ScratchBuffer &scratch) const {
    TextureEvalContext ctx(si);
    SampledSpectrum eta, k;
    if (reflectance_) {
        // As for the bare conductor (conductor_material.h): the metal with eta = 1 whose
        // normal-incidence reflectance is r.
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
    const float coat_eta = coating_.hero_eta(lambda);
    auto *base = scratch.make<ConductorBxDF>(roughness_.distribution(ctx), eta / coat_eta, k / coat_eta);
    return BSDF(si.shading.n, si.shading.dpdu, coating_.over(base, ctx, lambda, scratch));
}

} // namespace caustica
