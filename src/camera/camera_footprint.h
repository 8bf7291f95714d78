// How much of a surface one pixel covers: the screen-space derivatives dp/dx, dp/dy and du/dx ...
// dv/dy at a vertex, which texture filtering (textures/mipmap.h), bump mapping and the noise
// textures' antialiasing need. These are Igehy's ray differentials (1999) where the camera ray is
// known, and pbrt-v4's approximation from the camera's smallest differentials elsewhere
// (CameraBase::Approximate_dp_dxy, pbrt-v4 10.1).
//
// As in pbrt-v4:
//   - a camera ray carries the rays through the pixel one step right and one step down, scaled by
//     max(1/8, 1/sqrt(spp)) pixels (more samples per pixel resolve more of the texture, so each
//     sample filters over less of it);
//   - its first surface uses them, also after crossing surfaces that only bound media;
//   - every other vertex, of camera and light subpaths alike, uses the approximation: the
//     footprint the camera's smallest differentials would have at that point and orientation.
// Differs from pbrt-v4 in one respect: pbrt-v4 also carries differentials through perfectly
// specular reflections and refractions, which needs the derivatives of the shading normal; here
// the vertex after such a bounce uses the approximation.
#pragma once

#include "camera/camera.h"
#include "core/transform.h"
#include "core/vecmath.h"

#include <optional>

namespace caustica {

struct SurfaceInteraction;

// The step of a camera ray's differentials in pixels, for spp samples per pixel.
float differential_scale(int spp);

// The camera ray for a sample with its differentials scaled by `scale` pixels (none when the
// camera cannot generate the shifted rays). The shifted rays come from finite differences of
// generate_ray, 1/20 pixel to either side, as pbrt-v4's CameraBase::GenerateRayDifferential.
std::optional<CameraRay> generate_ray_differential(const Camera &camera, const CameraSample &sample,
                                                   const SampledWavelengths &lambda, float scale);

// pbrt-v4's approximate footprint: the smallest position and direction differentials of the
// camera's rays, found once along the film's diagonal, then intersected with the tangent plane
// of each point.
class CameraFootprint {
  public:
    CameraFootprint(const Camera &camera, const Transform &camera_from_world, Vec2i full_resolution);
    // The approximate dp/dx and dp/dy at p with normal n, for spp samples per pixel.
    void approximate_dp_dxy(Vec3f p, Vec3f n, int spp, Vec3f *dpdx, Vec3f *dpdy) const;

  private:
    Transform camera_from_world_, world_from_camera_;
    Vec3f min_pos_x_, min_pos_y_, min_dir_x_, min_dir_y_;
};

// Sets si's screen-space derivatives: from the ray differential when there is one that meets
// the tangent plane, else from the footprint; none without a footprint (texture lookups then
// use the finest level). du/dx ... dv/dy solve dp/dx = dp/du du/dx + dp/dv dv/dx in the least-
// squares sense (pbrt-v4's SurfaceInteraction::ComputeDifferentials).
void compute_differentials(SurfaceInteraction &si, const RayDifferential *ray, const CameraFootprint *footprint,
                           int spp);

} // namespace caustica
