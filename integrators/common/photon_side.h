// Which photons a gather point may use. A photon is found by distance alone, so near a corner
// or on the two faces of a thin wall the gather disk reaches photons of another surface: a
// point on the outside of a wall would collect the light that fell on its inside, a floor
// point light that fell on the wall beside it. Comparing the surfaces' normals, each turned
// towards the side its light arrived from or its camera path left by, rejects those (the usual
// photon-mapping test; pbrt-v4 does not make it and leaks light through thin walls). On smooth
// curved surfaces the normals within a merge radius agree far better than the threshold, so no
// legitimate photon is lost.
#pragma once

#include "core/vecmath.h"

namespace caustica {

// The geometric normal ng turned to the side of direction w.
inline Vec3f side_normal(Vec3f ng, Vec3f w) { return dot(ng, w) < 0 ? -ng : ng; }

// True if a photon on a surface with side normal photon_side may be gathered at a point whose
// side normal is gather_side (within 60 degrees).
inline bool same_surface_side(Vec3f photon_side, Vec3f gather_side) {
    return dot(photon_side, gather_side) > 0.5f;
}

} // namespace caustica
