#include "geometry/disk.h"

#include "core/sampling.h"

namespace caustica {

namespace {
constexpr double TwoPi = 2 * 3.14159265358979323846;
}

Disk::Disk(const Transform &render_from_object, bool reverse_orientation, float height,
           float radius, float inner_radius, float phi_max_degrees)
    : AnalyticShape(render_from_object, reverse_orientation), height_(height), radius_(radius),
      inner_radius_(std::clamp(double(inner_radius), 0.0, double(radius))),
      phi_max_(std::clamp(double(phi_max_degrees), 0.0, 360.0) * (TwoPi / 360)) {
    double object_area = 0.5 * phi_max_ * (radius_ * radius_ - inner_radius_ * inner_radius_);
    render_area_ = object_area * area_scale({0, 0, 1});
}

Bounds3f Disk::bounds() const {
    return render_bounds({-radius_, -radius_, height_}, {radius_, radius_, height_});
}

std::optional<float> Disk::nth_hit(Vec3f o_render, Vec3f d_render, float t_max, int n) const {
    Vec3d o = object_point(o_render), d = object_vector(d_render);
    if (d.z == 0 || n > 0) return std::nullopt; // a plane is met once
    double t = (height_ - o.z) / d.z;
    if (!(t > 0) || !(t < t_max)) return std::nullopt;
    double x = o.x + t * d.x, y = o.y + t * d.y;
    double dist2 = x * x + y * y;
    if (dist2 > radius_ * radius_ || dist2 < inner_radius_ * inner_radius_) return std::nullopt;
    if (phi_max_ < TwoPi) {
        double phi = std::atan2(y, x);
        if (phi < 0) phi += TwoPi;
        if (phi > phi_max_) return std::nullopt;
    }
    float tf = float(t);
    if (!(tf > 0)) tf = std::nextafter(0.f, 1.f);
    return std::min(tf, t_max);
}

SurfaceInteraction Disk::interaction(const Ray &ray, float t) const {
    Vec3d o = object_point(ray.o), d = object_vector(ray.d);
    // On the plane exactly: only x and y come from the ray.
    Vec3d p{o.x + double(t) * d.x, o.y + double(t) * d.y, height_};
    double r_hit = std::sqrt(p.x * p.x + p.y * p.y);
    // The parameterization is singular at the centre; derivatives use a point just off it.
    double x = r_hit > 0 ? p.x : 1e-5 * radius_, y = r_hit > 0 ? p.y : 0.0;
    double r_eff = r_hit > 0 ? r_hit : 1e-5 * radius_;
    double phi = std::atan2(y, x);
    if (phi < 0) phi += TwoPi;

    SurfaceInteraction si;
    si.p = render_point(p).to_float();
    si.n = render_normal({0, 0, 1});
    si.uv = {float(phi / phi_max_), float((radius_ - r_hit) / (radius_ - inner_radius_))};
    si.wo = -normalize(ray.d);
    si.dpdu = render_vector(Vec3d{-phi_max_ * y, phi_max_ * x, 0});
    si.dpdv = render_vector(Vec3d{x, y, 0} * ((inner_radius_ - radius_) / r_eff));
    si.shading.n = si.n;
    si.shading.dpdu = si.dpdu;
    si.shading.dpdv = si.dpdv;
    si.t = t;
    return si;
}

std::optional<ShapeSample> Disk::sample(Vec2f u) const {
    double x, y;
    if (inner_radius_ == 0 && phi_max_ >= TwoPi) {
        // The concentric map keeps the sampler's stratification.
        Vec2f pd = sample_uniform_disk_concentric(u);
        x = pd.x * radius_;
        y = pd.y * radius_;
    } else {
        // Uniform on the annulus sector: r^2 uniform between the radii squared.
        double r = std::sqrt(inner_radius_ * inner_radius_ +
                             double(u.x) * (radius_ * radius_ - inner_radius_ * inner_radius_));
        double phi = double(u.y) * phi_max_;
        x = r * std::cos(phi);
        y = r * std::sin(phi);
    }
    double r_hit = std::sqrt(x * x + y * y);
    double phi = std::atan2(y, x);
    if (phi < 0) phi += TwoPi;
    ShapeSample ss;
    ss.p = render_point({x, y, height_}).to_float();
    ss.n = render_normal({0, 0, 1});
    ss.uv = {float(phi / phi_max_), float((radius_ - r_hit) / (radius_ - inner_radius_))};
    ss.pdf = float(1 / render_area_);
    return ss;
}

} // namespace caustica
