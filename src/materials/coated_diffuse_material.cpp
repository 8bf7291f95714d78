#include "materials/coated_diffuse_material.h"

#include "geometry/interaction.h"
#include "materials/diffuse_bxdf.h"

namespace caustica {

BSDF CoatedDiffuseMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                     ScratchBuffer &scratch) const {
    TextureEvalContext ctx(si);
    auto *base = scratch.make<DiffuseBxDF>(reflectance_->evaluate(ctx, lambda));
    return BSDF(si.shading.n, si.shading.dpdu, coating_.over(base, ctx, lambda, scratch));
}

} // namespace caustica
