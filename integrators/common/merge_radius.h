// The default initial radius of photon gathering and vertex merging.
#pragma once

#include "film/film.h"
#include "scene/scene.h"

#include <algorithm>

namespace caustica {

// SmallVCM's default, 0.003 of the scene's bounding-sphere radius, is meant for 512-pixel
// images; the radius that balances bias against noise shrinks with the pixel footprint, so it is
// scaled by 512 over the larger image dimension. (pbrt-v4's SPPM default, 1 scene unit, is
// meaningful only at one scene scale; Caustica uses this one for every photon integrator.)
inline float default_merge_radius(const Scene &scene) {
    Vec3f center;
    float scene_radius = 0;
    scene.geometry.bounds().bounding_sphere(&center, &scene_radius);
    const Vec2i full = scene.film->resolution();
    return 0.003f * scene_radius * 512.f / float(std::max({full.x, full.y, 1}));
}

} // namespace caustica
