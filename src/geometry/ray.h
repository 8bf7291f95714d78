// Rays and robust ray spawning.
#pragma once

#include "core/vecmath.h"

#include <bit>
#include <cstring>

namespace caustica {

struct Ray {
    Vec3f o, d;
    float t_max = Infinity;
    Vec3f at(float t) const { return o + d * t; }
};

// Moves p off the surface along the geometric normal n, to the side of direction w, by a few
// hundred ulps of p's coordinates (Wächter and Binder 2019, "A Fast and Robust Method for
// Avoiding Self-Intersection", Ray Tracing Gems ch. 6). The offset scales with the magnitude of
// p, so it holds at large coordinates; near the origin a small absolute offset takes over.
// p must be computed on the surface (barycentric interpolation or reprojection), not as o + t d.
inline Vec3f offset_ray_origin(Vec3f p, Vec3f n, Vec3f w) {
    constexpr float origin = 1.0f / 32.0f;
    constexpr float float_scale = 1.0f / 65536.0f;
    constexpr float int_scale = 256.0f;
    if (dot(n, w) < 0) n = -n;
    Vec3f r;
    for (int i = 0; i < 3; ++i) {
        int of = int(int_scale * n[i]);
        int32_t bits;
        std::memcpy(&bits, &p[i], sizeof(float));
        bits += (p[i] < 0) ? -of : of;
        float pi;
        std::memcpy(&pi, &bits, sizeof(float));
        r[i] = std::abs(p[i]) < origin ? p[i] + float_scale * n[i] : pi;
    }
    return r;
}

inline Ray spawn_ray(Vec3f p, Vec3f n, Vec3f d) { return {offset_ray_origin(p, n, d), d, Infinity}; }

// A ray from surface point p (normal n) towards point p_to, stopping just short of it so that an
// occlusion test does not hit the target surface itself. n_to is the target's normal, or a zero
// vector for points not on a surface.
inline Ray spawn_ray_to(Vec3f p, Vec3f n, Vec3f p_to, Vec3f n_to = {}) {
    Vec3f o = offset_ray_origin(p, n, p_to - p);
    Vec3f target = (n_to == Vec3f{}) ? p_to : offset_ray_origin(p_to, n_to, o - p_to);
    Vec3f d = target - o;
    return {o, d, 1 - 1e-4f};
}

} // namespace caustica
