// A ScatteringPoint kept in 56 bytes, without its BSDF: where it is, the direction the path
// reached it from, what the ray met there (SurfaceHit) and the medium around it.
// SubpathWalk::rebuild shades it again when it is needed, which costs one material evaluation and
// no ray, so that an integrator can keep every vertex of many subpaths (vcm's light vertices,
// read once each by the camera subpath of their pixel) without keeping their BSDFs.
#pragma once

#include "core/vecmath.h"
#include "geometry/surface_hit.h"

namespace caustica {

class Medium;

struct StoredScatteringPoint {
    Vec3f p, wo;
    SurfaceHit hit;           // without a slot: a point in a medium
    bool exit_lobe = false;   // the exit of a jump through a profile solid: its BSDF is the exit lobe
    bool regularized = false; // its BSDF was regularized (SubpathWalk::regularize_after_non_specular_bounces)
    // A medium point's medium; a surface point's, the medium the path arrived in, from which
    // the media on its two sides follow (ScatteringPoint::on_surface).
    const Medium *medium = nullptr;

    bool in_medium() const { return hit.slot == SurfaceHit::None; }
};
static_assert(sizeof(StoredScatteringPoint) <= 56);

} // namespace caustica
