// Spherical triangles: the solid angle a triangle subtends and uniform sampling of it.
#pragma once

#include "core/vecmath.h"
#include "geometry/vec3d.h"

#include <optional>

namespace caustica {

// Area of the spherical triangle with unit-vector vertices a, b, c, i.e. the solid angle of the
// planar triangle they point to (Van Oosterom and Strackee 1983, "The Solid Angle of a Plane
// Triangle": tan(omega / 2) = |a . (b x c)| / (1 + a.b + b.c + c.a)).
double spherical_triangle_area(Vec3d a, Vec3d b, Vec3d c);

// A unit direction uniformly distributed (in solid angle) over the spherical triangle a, b, c of
// the given area, by Arvo's inversion (Arvo 1995, "Stratified Sampling of Spherical Triangles"):
// u.x picks the sub-triangle a, b, c' of area u.x * area; u.y picks the point on arc b-c'.
std::optional<Vec3d> sample_spherical_triangle(Vec3d a, Vec3d b, Vec3d c, double area, Vec2f u);

} // namespace caustica
