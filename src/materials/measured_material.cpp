#include "materials/measured_material.h"

#include "geometry/interaction.h"

namespace caustica {

BSDF MeasuredMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                ScratchBuffer &scratch) const {
    return BSDF(si.shading.n, si.shading.dpdu, scratch.make<MeasuredBxDF>(brdf_.get(), lambda));
}

} // namespace caustica
