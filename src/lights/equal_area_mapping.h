// Clarberg's equal-area octahedral mapping between the unit square and the unit sphere
// (P. Clarberg, "Fast Equal-Area Mapping of the (Hemi)Sphere using SIMD", JGT 13(3), 2008).
// pbrt-v4 stores environment maps and goniometric diagrams in this parameterisation: every pixel
// of a square image covers the same solid angle, 4 pi / (width * height), so a density p(u, v)
// over the square is the density p(u, v) / (4 pi) over directions.
//
// Layout: the square's centre is +z, its four corners are -z; the diamond |u'| + |v'| = 1
// (u' = 2u - 1, v' = 2v - 1) is the equator, with +x towards u' = 1 and +y towards v' = 1.
#pragma once

#include "core/vecmath.h"

namespace caustica {

inline Vec3f equal_area_square_to_sphere(Vec2f p) {
    float u = 2 * p.x - 1, v = 2 * p.y - 1;
    float au = std::abs(u), av = std::abs(v);
    // Signed distance from the equator diamond: positive inside (upper hemisphere).
    float signed_distance = 1 - (au + av);
    // r is the distance from the nearer pole along the octahedron, in [0, 1]; the area between
    // a pole and r is pi r^2 on the square and 2 pi (1 - |z|) on the sphere, so 1 - |z| = r^2.
    float r = 1 - std::abs(signed_distance);
    // Within the quadrant, the position along the diamond's edge gives the azimuth linearly.
    float phi = (r == 0 ? 1 : (av - au) / r + 1) * PiOver4;
    float z = std::copysign(1 - r * r, signed_distance);
    float cos_phi = std::copysign(std::cos(phi), u);
    float sin_phi = std::copysign(std::sin(phi), v);
    float s = r * safe_sqrt(2 - r * r);  // sin(theta), since sin^2 = 1 - (1 - r^2)^2
    return {cos_phi * s, sin_phi * s, z};
}

// Inverse of equal_area_square_to_sphere for a unit vector d.
inline Vec2f equal_area_sphere_to_square(Vec3f d) {
    float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    float r = safe_sqrt(1 - az);
    // Azimuth within the first quadrant, as a fraction of a quarter turn.
    float t = (ax == 0 && ay == 0) ? 0 : std::atan2(ay, ax) * (2 / Pi);
    float v = r * t;
    float u = r - v;
    if (d.z < 0) {
        // Lower hemisphere: reflect across the quadrant's edge of the diamond.
        float tmp = u;
        u = 1 - v;
        v = 1 - tmp;
    }
    u = std::copysign(u, d.x);
    v = std::copysign(v, d.y);
    return {clamp(0.5f * (u + 1), 0.f, 1.f), clamp(0.5f * (v + 1), 0.f, 1.f)};
}

}  // namespace caustica
