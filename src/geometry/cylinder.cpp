#include "geometry/cylinder.h"

#include <algorithm>
#include <cmath>

namespace caustica {

namespace {
constexpr double TwoPi = 2 * 3.14159265358979323846;
}

Cylinder::Cylinder(const Transform &render_from_object, bool reverse_orientation, float radius,
                   float z_min, float z_max, float phi_max_degrees)
    : AnalyticShape(render_from_object, reverse_orientation), radius_(radius),
      z_min_(std::min(z_min, z_max)), z_max_(std::max(z_min, z_max)),
      phi_max_(std::clamp(double(phi_max_degrees), 0.0, 360.0) * (TwoPi / 360)) {
    // Object area is r dz dphi; the area scale depends on the normal, so on phi alone.
    if (is_similarity()) {
        render_area_ = object_area() * area_scale({1, 0, 0});
    } else {
        constexpr int steps = 4096;
        double dphi = phi_max_ / steps, sum = 0;
        for (int j = 0; j < steps; ++j) {
            double phi = (j + 0.5) * dphi;
            sum += area_scale({std::cos(phi), std::sin(phi), 0});
        }
        render_area_ = sum * dphi * radius_ * (z_max_ - z_min_);
    }
}

Bounds3f Cylinder::bounds() const {
    return render_bounds({-radius_, -radius_, z_min_}, {radius_, radius_, z_max_});
}

bool Cylinder::on_surface(Vec3d p) const {
    if (p.z < z_min_ || p.z > z_max_) return false;
    if (phi_max_ < TwoPi) {
        double phi = std::atan2(p.y, p.x);
        if (phi < 0) phi += TwoPi;
        if (phi > phi_max_) return false;
    }
    return true;
}

Vec2f Cylinder::uv_of(Vec3d p) const {
    double phi = std::atan2(p.y, p.x);
    if (phi < 0) phi += TwoPi;
    return {float(phi / phi_max_), float((p.z - z_min_) / (z_max_ - z_min_))};
}

double Cylinder::hit_object(Vec3d o, Vec3d d, double t_max, int n) const {
    // (o + t d)_xy on the circle: a t^2 + b t + c = 0.
    double a = d.x * d.x + d.y * d.y;
    if (a == 0) return -1; // along the axis
    double b = 2 * (d.x * o.x + d.y * o.y), c = o.x * o.x + o.y * o.y - radius_ * radius_;
    double discriminant = b * b - 4 * a * c;
    if (discriminant < 0) return -1;
    // The stable pair of roots (no cancellation between b and the root).
    double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a, t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    for (double t : {t0, t1})
        if (t > 0 && t < t_max && on_surface(o + d * t) && n-- == 0) return t;
    return -1;
}

std::optional<float> Cylinder::nth_hit(Vec3f o_render, Vec3f d_render, float t_max, int n) const {
    double t = hit_object(object_point(o_render), object_vector(d_render), t_max, n);
    if (!(t > 0)) return std::nullopt;
    float tf = float(t);
    if (!(tf > 0)) tf = std::nextafter(0.f, 1.f);
    return std::min(tf, t_max);
}

float Cylinder::pdf(Vec3f ref, Vec3f wi) const {
    Vec3d ref_object = object_point(ref), d = object_vector(wi);
    double t = hit_object(ref_object, d, Infinity);
    if (!(t > 0)) return 0;
    Vec3d p = ref_object + d * t;
    Vec3d n_object{p.x / radius_, p.y / radius_, 0};
    double pdf = render_area_to_solid_angle_pdf(1 / (object_area() * area_scale(n_object)), ref_object, p,
                                                n_object);
    return std::isfinite(pdf) ? float(pdf) : 0;
}

SurfaceInteraction Cylinder::interaction(const Ray &ray, float t) const {
    Vec3d o = object_point(ray.o), d = object_vector(ray.d);
    Vec3d p = o + d * double(t);
    // Onto the surface exactly: scale the point's distance from the axis to the radius.
    double r_hit = std::sqrt(p.x * p.x + p.y * p.y);
    if (r_hit > 0) {
        p.x *= radius_ / r_hit;
        p.y *= radius_ / r_hit;
    }
    SurfaceInteraction si;
    si.p = render_point(p).to_float();
    si.n = render_normal({p.x / radius_, p.y / radius_, 0});
    si.uv = uv_of(p);
    si.wo = -normalize(ray.d);
    si.dpdu = render_vector(Vec3d{-phi_max_ * p.y, phi_max_ * p.x, 0});
    si.dpdv = render_vector(Vec3d{0, 0, z_max_ - z_min_});
    si.shading.n = si.n;
    si.shading.dpdu = si.dpdu;
    si.shading.dpdv = si.dpdv;
    si.t = t;
    return si;
}

std::optional<ShapeSample> Cylinder::sample(Vec2f u) const {
    double z = z_min_ + double(u.x) * (z_max_ - z_min_);
    double phi = double(u.y) * phi_max_;
    Vec3d p{radius_ * std::cos(phi), radius_ * std::sin(phi), z};
    Vec3d n_object{std::cos(phi), std::sin(phi), 0};
    ShapeSample ss;
    ss.p = render_point(p).to_float();
    ss.n = render_normal(n_object);
    ss.uv = uv_of(p);
    ss.pdf = float(1 / (object_area() * area_scale(n_object)));
    return ss;
}

} // namespace caustica
