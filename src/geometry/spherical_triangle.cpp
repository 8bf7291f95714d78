#include "geometry/spherical_triangle.h"

namespace caustica {

namespace {

// Component of v orthogonal to unit vector axis, normalized.
Vec3d orthogonal_direction(Vec3d v, Vec3d axis) { return normalize(v - axis * dot(v, axis)); }

} // namespace

double spherical_triangle_area(Vec3d a, Vec3d b, Vec3d c) {
    double triple = std::abs(dot(a, cross(b, c)));
    double denominator = 1 + dot(a, b) + dot(b, c) + dot(c, a);
    return 2 * std::atan2(triple, denominator);
}

std::optional<Vec3d> sample_spherical_triangle(Vec3d a, Vec3d b, Vec3d c, double area, Vec2f u) {
    // Interior angle at a: between the great circles through a-b and a-c, measured by the
    // normals of their planes.
    // Its cosine and sine come from the dot and cross products of the unit normals, each accurate
    // where the other is not (near 0 and pi, the sine; near pi/2, the cosine), without the angle
    // itself: the sub-triangle's angles below then need one sine and cosine, not three.
    Vec3d n_ab = cross(a, b), n_ac = cross(a, c);
    if (length_squared(n_ab) == 0 || length_squared(n_ac) == 0) return std::nullopt;
    n_ab = normalize(n_ab);
    n_ac = normalize(n_ac);
    double cos_alpha = std::clamp(dot(n_ab, n_ac), -1.0, 1.0), sin_alpha = std::min(1.0, length(cross(n_ab, n_ac)));
    double cos_c = dot(a, b); // cosine of the arc a-b

    // Sub-triangle a, b, c' with area u.x * area: Arvo's closed form for cos of arc a-c', with
    // s and t the sine and cosine of (sub_area - alpha).
    double sub_area = double(u.x) * area;
    double sin_area = std::sin(sub_area), cos_area = std::cos(sub_area);
    double s = sin_area * cos_alpha - cos_area * sin_alpha, t = cos_area * cos_alpha + sin_area * sin_alpha;
    double uu = t - cos_alpha;
    double vv = s + sin_alpha * cos_c;
    double q = ((vv * t - uu * s) * cos_alpha - vv) / ((vv * s + uu * t) * sin_alpha);
    if (!std::isfinite(q)) return std::nullopt;
    q = std::clamp(q, -1.0, 1.0);
    Vec3d c_sub = q * a + std::sqrt(1 - q * q) * orthogonal_direction(c, a);

    // Along the arc from b to c', cos of the angle from b is uniform in [cos(b, c'), 1].
    double z = 1 - double(u.y) * (1 - dot(c_sub, b));
    z = std::clamp(z, -1.0, 1.0);
    // When c' coincides with b (u.x = 0) the arc is a point and every u.y maps to b.
    Vec3d perpendicular = c_sub - b * dot(c_sub, b);
    double perpendicular_length = length(perpendicular);
    Vec3d w = perpendicular_length > 0
                  ? z * b + perpendicular * (std::sqrt(1 - z * z) / perpendicular_length)
                  : b;
    if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) return std::nullopt;
    return normalize(w);
}

} // namespace caustica
