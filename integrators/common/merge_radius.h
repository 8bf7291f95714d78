// The default initial radius of photon gathering and vertex merging.
#pragma once

namespace caustica {

class Scene;

// SmallVCM's default, 0.003 of the scene's bounding-sphere radius, is meant for 512-pixel
// images; the radius that balances bias against noise shrinks with the pixel footprint, so it is
// scaled by 512 over the larger image dimension. A scene whose bounds are far larger than what
// the camera sees (a ground plane to the horizon, a sky dome) would get a radius of many pixels,
// whose blur is a visible bias, most of all in media, where a sphere cut by a surface gathers
// too few photons; so the radius is at most three pixel footprints at the median distance of the
// surfaces the camera sees (on a Cornell box at 512 pixels the two rules agree to within a
// factor of three, and the bounding-sphere rule is the smaller). pbrt-v4's SPPM default, 1 scene
// unit, is meaningful only at one scene scale; Caustica uses this one for every photon
// integrator.
float default_merge_radius(const Scene &scene);

// The default radius of the spheres that gather photons in media: the surface radius, but at most
// a tenth of the shortest mean free path among the scene's media (at the largest extinction over
// the visible range). Within a mean free path the in-scattered radiance changes, and a dense
// medium's boundary (milk in a glass, smoke against a wall) cuts a sphere that reaches across it,
// so the sphere gathers too few photons there: a bias that the bounding-sphere and footprint
// rules, made for surfaces, do not see.
float default_medium_merge_radius(const Scene &scene, float surface_radius);

} // namespace caustica
