#include "materials/coated_conductor_material.h"

#include "geometry/interaction.h"
#include "materials/conductor_bxdf.h"
#include "materials/conductor_material.h"

namespace caustica {

BSDF CoatedConductorMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                       ScratchBuffer &scratch) const {
    const TextureEvalContext ctx(si);
    // The metal lies under the coat, so its index is relative to the coat's (pbrt-v4).
    const ConductorIndex index = conductor_index(eta_, k_, reflectance_, ctx, lambda);
    const float coat_eta = coating_.hero_eta(lambda);
    auto *base = scratch.make<ConductorBxDF>(roughness_.distribution(ctx), index.eta / coat_eta, index.k / coat_eta);
    return BSDF(si.shading.n, si.shading.dpdu, coating_.over(base, ctx, lambda, scratch));
}

} // namespace caustica
