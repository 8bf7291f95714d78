// Rays and robust ray spawning.
#pragma once

#include "core/next_float.h"
#include "core/vecmath.h"

#include <cmath>

namespace caustica {

struct Ray {
    Vec3f o, d;
    float t_max = Infinity;
    // When along the shutter the ray travels (scene time, as in TransformTimes and the camera's
    // shutteropen/shutterclose): moving geometry is intersected where it is at this time. Every
    // ray of a path, and of the subpaths joined to it, has the path's time.
    float time = 0;
    Vec3f at(float t) const { return o + d * t; }
};

// The offset rays of a camera ray (Igehy 1999): through the film position a step to the right (x)
// and a step down (y) from the ray's (camera/camera_footprint.h).
struct RayDifferential {
    Vec3f rx_origin, rx_direction, ry_origin, ry_direction;
};

// The coordinate magnitude that the rounding error of a surface point p is proportional to: p's
// largest coordinate, or more where p was interpolated or transformed from larger coordinates (a
// triangle's vertices, an instance's placement). Shapes that compute p from nothing larger leave
// `from` at 0.
inline float rounding_scale(Vec3f p, float from) { return std::max(max_component(abs(p)), from); }

// Moves p off the surface along the geometric normal n, to the side of direction w, by more than
// the rounding error p can carry: 2^-18 (32 to 64 ulps) of rounding_scale(p, scale). (Grazing rays in
// tests/geometry first re-hit surfaces at 2^-22 of it.) The offset follows the point's own
// coordinates, with no floor in absolute units: a fixed floor is too large for small features
// (a glass edge a few micrometres thick at a lens's rim, which a ray entering there would cross
// before it starts) and too small for large ones. Moving exactly along n, rather than by a number
// of ulps per axis as Wachter and Binder 2019 (Ray Tracing Gems ch. 6) do, keeps the offset
// parallel to the surface's neighbours: per-axis ulps differ when coordinates differ in
// magnitude, and the tilted offset then pushes origins near a concave edge through the adjacent
// wall. The rounded result is nudged one more ulp away from the surface per axis, as in
// pbrt-v3/v4 (Pharr et al., "Physically Based Rendering", section 3.9.5).
// p must be computed on the surface (barycentric interpolation or reprojection), not as o + t d.
inline Vec3f offset_ray_origin(Vec3f p, Vec3f n, float scale, Vec3f w) {
    const float offset = 0x1p-18f * rounding_scale(p, scale);
    if (dot(n, w) < 0) n = -n;
    Vec3f o = p + n * offset;
    for (int i = 0; i < 3; ++i) {
        if (n[i] > 0) o[i] = next_float_up(o[i]);
        else if (n[i] < 0) o[i] = next_float_down(o[i]);
    }
    return o;
}

inline Ray spawn_ray(Vec3f p, Vec3f n, float scale, Vec3f d, float time) {
    return {offset_ray_origin(p, n, scale, d), d, Infinity, time};
}

// A ray from surface point p (normal n, rounding scale `scale` as in offset_ray_origin) towards
// point p_to. n_to is the target's normal, or a zero vector for points not on a surface. A target
// on a surface is offset like an origin and the ray stops just short of it, so that an occlusion
// test does not hit the target surface itself. A target off surfaces (a vertex inside a medium,
// a point light, the lens) is reached exactly: stopping short by a fraction of the distance there
// would miss a surface just in front of it (a boundary that a medium vertex lies just inside,
// which would then be seen through), and would leave that fraction out of the transmittance.
inline Ray spawn_ray_to(Vec3f p, Vec3f n, float scale, Vec3f p_to, Vec3f n_to, float scale_to, float time) {
    Vec3f o = offset_ray_origin(p, n, scale, p_to - p);
    Vec3f target = (n_to == Vec3f{}) ? p_to : offset_ray_origin(p_to, n_to, scale_to, o - p_to);
    Vec3f d = target - o;
    return {o, d, n_to == Vec3f{} ? 1.f : 1 - 1e-4f, time};
}

} // namespace caustica
