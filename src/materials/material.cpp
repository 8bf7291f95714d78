#include "materials/material.h"

#include "geometry/interaction.h"
#include "materials/shading_perturbation.h"

namespace caustica {

BSDF shade(SurfaceInteraction &si, const SampledWavelengths &lambda, ScratchBuffer &scratch,
           ScratchBuffer *media_scratch) {
    const Material &material = si.material->resolve(si);
    if (const ShadingPerturbation *perturbation = material.shading_perturbation()) perturbation->apply(si);
    si.interior = si.material->interior_medium(si, lambda, media_scratch ? *media_scratch : scratch);
    return material.get_bsdf(si, lambda, scratch);
}

} // namespace caustica
