#include "materials/material.h"

#include "geometry/interaction.h"
#include "materials/shading_perturbation.h"

namespace caustica {

BSDF shade(SurfaceInteraction &si, const SampledWavelengths &lambda, ScratchBuffer &scratch) {
    const Material &material = si.material->resolve(si);
    if (const ShadingPerturbation *perturbation = material.shading_perturbation()) perturbation->apply(si);
    si.interior = si.material->interior_medium(si, lambda, scratch);
    return material.get_bsdf(si, lambda, scratch);
}

} // namespace caustica
