#include "materials/diffuse_transmission_material.h"

#include "geometry/interaction.h"
#include "materials/diffuse_transmission_bxdf.h"

namespace caustica {

BSDF DiffuseTransmissionMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                           ScratchBuffer &scratch) const {
    TextureEvalContext ctx(si);
    auto *bxdf = scratch.make<DiffuseTransmissionBxDF>(reflectance_->evaluate(ctx, lambda) * scale_,
                                                       transmittance_->evaluate(ctx, lambda) * scale_);
    return BSDF(si.shading.n, si.shading.dpdu, bxdf);
}

} // namespace caustica
