#include "textures/texture.h"

#include "geometry/interaction.h"

namespace caustica {

TextureEvalContext::TextureEvalContext(const SurfaceInteraction &si)
    : p(si.p), n(si.shading.n), uv(si.uv) {}

} // namespace caustica
