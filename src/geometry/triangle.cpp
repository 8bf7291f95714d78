#include "geometry/triangle.h"

#include "core/sampling.h"
#include "geometry/spherical_triangle.h"

namespace caustica {

namespace {
// Below about 1e-4 sr the triangle spans under a degree from the reference point: the
// area-to-solid-angle factor r^2 / cos is then nearly constant over it, and area sampling is
// both cheaper and as good. Close to 2 pi the reference point nearly lies in the triangle's
// plane and Arvo's formula divides by the sine of an interior angle near pi.
constexpr double MinSphericalSolidAngle = 1e-4;
constexpr double MaxSphericalSolidAngle = 2 * 3.14159265358979323846 - 0.1;
} // namespace

Triangle::Triangle(std::shared_ptr<const TriangleMesh> mesh, int index)
    : mesh_(std::move(mesh)), index_(index), area_(mesh_->area(index)) {}

Bounds3f Triangle::bounds() const {
    Bounds3f b;
    for (int v : mesh_->vertices(index_)) b.expand(mesh_->positions()[v]);
    return b;
}

DirectionCone Triangle::normal_bounds() const {
    // The oriented normal is the plane's, turned to the side of the interpolated normal; that
    // side's test is linear in the barycentrics, so if all three corners agree, every point does.
    const float corners[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const Vec3f n = mesh_->normal(index_, corners[0]);
    if (mesh_->normal(index_, corners[1]) == n && mesh_->normal(index_, corners[2]) == n) return {n, 1.f};
    return DirectionCone::entire_sphere();
}

ShapeSample Triangle::sample_at(const double b[3]) const {
    float bf[3] = {float(b[0]), float(b[1]), float(b[2])};
    ShapeSample ss;
    ss.p = mesh_->point(index_, bf);
    ss.error_scale = mesh_->error_scale(index_);
    ss.n = mesh_->normal(index_, bf);
    ss.uv = mesh_->uv(index_, bf);
    return ss;
}

std::optional<ShapeSample> Triangle::sample(Vec2f u) const {
    float b[3];
    sample_uniform_triangle(u, b);
    double bd[3] = {b[0], b[1], b[2]};
    ShapeSample ss = sample_at(bd);
    ss.pdf = 1 / area_;
    return ss;
}

bool Triangle::plane_crossing(Vec3d o, Vec3d d, double *t, double b[3]) const {
    // Moller and Trumbore 1997, in double: the line's parameters in the triangle's edge basis.
    auto v = mesh_->vertices(index_);
    Vec3d p0(mesh_->positions()[v[0]]), p1(mesh_->positions()[v[1]]),
        p2(mesh_->positions()[v[2]]);
    Vec3d e1 = p1 - p0, e2 = p2 - p0;
    Vec3d pvec = cross(d, e2);
    double det = dot(e1, pvec);
    if (det == 0) return false;
    double inv_det = 1 / det;
    Vec3d tvec = o - p0;
    Vec3d qvec = cross(tvec, e1);
    b[1] = dot(tvec, pvec) * inv_det;
    b[2] = dot(d, qvec) * inv_det;
    b[0] = 1 - b[1] - b[2];
    *t = dot(e2, qvec) * inv_det;
    return std::isfinite(*t);
}

std::optional<Shape::Hit> Triangle::intersect(Vec3f o, Vec3f d, float t_max) const {
    double t, b[3];
    if (!plane_crossing(Vec3d(o), Vec3d(d), &t, b)) return std::nullopt;
    if (b[0] < 0 || b[1] < 0 || b[2] < 0 || !(t > 0) || !(t < t_max)) return std::nullopt;
    ShapeSample ss = sample_at(b);
    return Hit{float(t), ss.p, ss.n, ss.uv};
}

double Triangle::subtended(Vec3f ref, Vec3d directions[3]) const {
    auto v = mesh_->vertices(index_);
    for (int i = 0; i < 3; ++i) {
        directions[i] = Vec3d(mesh_->positions()[v[i]]) - Vec3d(ref);
        if (length_squared(directions[i]) == 0) return 0;
        directions[i] = normalize(directions[i]);
    }
    return spherical_triangle_area(directions[0], directions[1], directions[2]);
}

float Triangle::solid_angle(Vec3f ref) const {
    Vec3d directions[3];
    return float(subtended(ref, directions));
}

bool Triangle::uses_spherical_sampling(double omega) {
    return omega >= MinSphericalSolidAngle && omega <= MaxSphericalSolidAngle;
}

std::optional<ShapeSample> Triangle::sample(Vec3f ref, Vec2f u) const {
    Vec3d directions[3];
    double omega = subtended(ref, directions);
    if (!uses_spherical_sampling(omega)) return Shape::sample(ref, u);

    std::optional<Vec3d> w =
        sample_spherical_triangle(directions[0], directions[1], directions[2], omega, u);
    if (!w) return std::nullopt;
    // The point on the triangle along w; rounding can put it a hair outside, so clamp the
    // barycentrics back onto the triangle.
    double t, bary[3];
    if (!plane_crossing(Vec3d(ref), *w, &t, bary)) return std::nullopt;
    for (double &x : bary) x = std::max(x, 0.0);
    double sum = bary[0] + bary[1] + bary[2];
    if (!(sum > 0)) return std::nullopt;
    for (double &x : bary) x /= sum;
    ShapeSample ss = sample_at(bary);
    if (ss.p == ref) return std::nullopt;
    ss.pdf = float(1 / omega);
    return ss;
}

float Triangle::pdf(Vec3f ref, Vec3f wi) const {
    Vec3d directions[3];
    double omega = subtended(ref, directions);
    if (!uses_spherical_sampling(omega)) return Shape::pdf(ref, wi);
    if (!intersect(ref, wi, Infinity)) return 0;
    return float(1 / omega);
}

} // namespace caustica
