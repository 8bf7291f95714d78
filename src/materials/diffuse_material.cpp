#include "materials/diffuse_material.h"

#include "geometry/interaction.h"
#include "materials/diffuse_bxdf.h"

namespace caustica {

BSDF DiffuseMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                               ScratchBuffer &scratch) const {
    SampledSpectrum r = reflectance_->evaluate(TextureEvalContext(si), lambda);
    return BSDF(si.shading.n, si.shading.dpdu, scratch.make<DiffuseBxDF>(r));
}

} // namespace caustica
