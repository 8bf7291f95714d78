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
    // A medium point's medium. A surface point keeps none: rebuilt, the media on its two sides
    // are its medium interface's, or none, whatever surrounded it. Those who join a vertex to a
    // rebuilt one (vcm's connections) trace the segment between them through the medium on
    // their own side.
    const Medium *medium = nullptr;

    bool in_medium() const { return hit.slot == SurfaceHit::None; }
};
static_assert(sizeof(StoredScatteringPoint) <= 56);

} // namespace caustica
