// Which surface a ray met, and where on it, in 20 bytes: enough for GeometryScene::interaction
// to rebuild the full SurfaceInteraction later, given the point and the direction it was reached
// from. A renderer that keeps many surface points (vcm's light vertices) can keep these and
// shade again the few it reads, instead of keeping every point's BSDF.
#pragma once

#include "core/vecmath.h"

#include <algorithm>
#include <cmath>
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

// A SurfaceHit in 12 bytes, for records kept by the million: the slot and the instance's shape
// as one index (GeometryScene::pack numbers every shape of the scene, an instance's as many times
// as it is placed), and (u, v) in 16-bit fixed point. (u, v) lie in [0, 1] for every kind of
// primitive, so they come back within 2^-17 of Embree's: the shading normal and texture
// coordinates rebuilt from them move by as little, while the point, kept apart, is exact.
struct PackedSurfaceHit {
    uint32_t shape = SurfaceHit::None;
    uint32_t primitive = 0;
    uint16_t u = 0, v = 0;

    static uint16_t quantise(float t) { return uint16_t(std::lround(std::clamp(t, 0.f, 1.f) * 65535.f)); }
    static float dequantise(uint16_t q) { return float(q) * (1.f / 65535.f); }
};
static_assert(sizeof(PackedSurfaceHit) == 12);

} // namespace caustica
