// The normalisation of light-tracing splats, shared by every integrator that connects light
// paths to the lens (lt, bdpt, vcm).
#pragma once

#include "film/film.h"
#include "scene/scene.h"

#include <cstdint>

namespace caustica {

// The perspective camera's importance integrates to one over the lens and the whole image (the
// full resolution, whatever the crop window), so a splat summed into a pixel through the filter
// and divided by its integral (Film::get_image) estimates 1 / N_full of that pixel's value per
// light path. Dividing by the light paths traced per pixel of the full frame makes the splats
// an average; counting the paths actually traced, not whole iterations, keeps an interrupted
// render correctly normalised. With one light path per rendered pixel per iteration and no
// crop window this is 1 / iterations, as in pbrt-v4.
inline double light_path_splat_scale(const Scene &scene, uint64_t light_paths_traced) {
    if (light_paths_traced == 0) return 0;
    const Vec2i full = scene.film->resolution();
    return double(full.x) * full.y / double(light_paths_traced);
}

} // namespace caustica
