// What the camera and the lights see, estimated before rendering from a few thousand rays, for
// `caustica info` and `--integrator auto` (scene_builder.cpp). Material flags alone say whether
// caustic paths can exist; how much of the image they make up depends on the geometry:
//
// - view_emitters: the share of the image that shows an emitter directly (an area light, or an
//   infinite light where camera rays escape).
// - view_specular: the share of the image whose first surface is purely specular (glass, water,
//   mirrors). Whatever diffuse surface lies behind it is lit through specular-diffuse-specular
//   paths, which connections (bdpt, the connection half of vcm) cannot sample, only photon
//   merging.
// - lights_behind_specular: the share of emitted light whose first surface is purely specular
//   (a lamp behind a lens or inside a glass bulb, the sun above water): that light reaches
//   diffuse surfaces only through caustic paths.
#pragma once

namespace caustica {

class Scene;

struct SceneProbe {
    float view_emitters = 0;
    float view_specular = 0;
    float lights_behind_specular = 0;
};

// Traces a fixed grid of camera rays (rays_per_axis^2) and as many light rays, following media
// boundaries (shapes without a material) but no other surface. Deterministic.
SceneProbe probe_scene(const Scene &scene, int rays_per_axis = 48);

} // namespace caustica
