// Which photons a gather point may use. A photon is found by distance alone, so near a corner
// the gather disk reaches photons that lie on another surface: a point at the foot of a wall
// would collect light that fell on the floor beside it, and light that the floor reflects
// towards the wall then leaks through the corner. Comparing the two surfaces' geometric
// normals rejects those (the usual photon-mapping test; pbrt-v4 does not make it). The normals
// are compared up to sign: which side a photon arrived from is the BSDF's business (a
// reflecting surface gives zero for light from behind, so the two faces of a thin wall stay
// apart, and a transmitting one lets it through). On smooth curved surfaces the normals within
// a merge radius agree far better than the threshold, so no legitimate photon is lost.
#pragma once

#include "core/vecmath.h"

#include <cmath>

namespace caustica {

// True if a photon on a surface with geometric normal photon_normal may be gathered at a point
// whose geometric normal is gather_normal (the two within 60 degrees, up to sign).
inline bool same_surface(Vec3f photon_normal, Vec3f gather_normal) {
    return std::abs(dot(photon_normal, gather_normal)) > 0.5f;
}

} // namespace caustica
