// Which surface a ray met, and where on it, in 20 bytes: enough for GeometryScene::interaction
// to rebuild the full SurfaceInteraction later, given the point and the direction it was reached
// from. A renderer that keeps many surface points (vcm's light vertices) can keep these and
// shade again the few it reads, instead of keeping every point's BSDF.
#pragma once

#include "core/vecmath.h"

#include <cstdint>

namespace caustica {

struct SurfaceHit {
    static constexpr uint32_t None = ~0u;
    uint32_t slot = None;       // the top-level Embree geometry: a shape, or an instance
    uint32_t geometry = None;   // an instance's: the shape within its prototype
    uint32_t primitive = 0;     // triangle, bilinear patch or curve segment; 0 for analytic shapes
    // Embree's (u, v): barycentric weights of a triangle's vertices 1 and 2, a patch's
    // parameters, a curve segment's parameter u. Unused for analytic shapes, which rebuild the
    // record from the point.
    Vec2f uv;
};
static_assert(sizeof(SurfaceHit) == 20);

} // namespace caustica
