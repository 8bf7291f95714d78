#include "textures/texture.h"

#include "geometry/interaction.h"

namespace caustica {

TextureEvalContext::TextureEvalContext(const SurfaceInteraction &si)
    : p(si.p), n(si.shading.n), uv(si.uv), dpdx(si.dpdx), dpdy(si.dpdy), dudx(si.dudx), dudy(si.dudy),
      dvdx(si.dvdx), dvdy(si.dvdy) {}

} // namespace caustica
