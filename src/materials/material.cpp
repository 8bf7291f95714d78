#include "materials/material.h"

#include "geometry/interaction.h"

namespace caustica {

BSDF shade(SurfaceInteraction &si, const SampledWavelengths &lambda, ScratchBuffer &scratch) {
    si.interior = si.material->interior_medium(si, lambda, scratch);
    return si.material->get_bsdf(si, lambda, scratch);
}

} // namespace caustica
