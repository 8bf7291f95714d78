#include "geometry/sphere.h"

namespace caustica {

namespace {

constexpr double TwoPi = 2 * 3.14159265358979323846;

// Orthonormal basis around unit vector v (Duff et al. 2017), in double.
void coordinate_system_d(Vec3d v, Vec3d *a, Vec3d *b) {
    double sign = std::copysign(1.0, v.z);
    double s = -1 / (sign + v.z);
    double t = v.x * v.y * s;
    *a = {1 + sign * v.x * v.x * s, sign * t, -sign * v.x};
    *b = {t, sign + v.y * v.y * s, -v.y};
}

} // namespace

Sphere::Sphere(const Transform &render_from_object, bool reverse_orientation, float radius,
               float z_min, float z_max, float phi_max_degrees)
    : AnalyticShape(render_from_object, reverse_orientation), radius_(radius) {
    z_min_ = std::clamp(double(std::min(z_min, z_max)), -radius_, radius_);
    z_max_ = std::clamp(double(std::max(z_min, z_max)), -radius_, radius_);
    theta_z_min_ = std::acos(std::clamp(z_min_ / radius_, -1.0, 1.0));
    theta_z_max_ = std::acos(std::clamp(z_max_ / radius_, -1.0, 1.0));
    phi_max_ = std::clamp(double(phi_max_degrees), 0.0, 360.0) * (TwoPi / 360);
    is_full_ = z_min_ <= -radius_ && z_max_ >= radius_ && phi_max_ >= TwoPi;

    if (is_similarity()) {
        render_area_ = object_area() * area_scale({0, 0, 1});
    } else {
        // The transform stretches area unevenly: integrate its area scale over the surface with
        // the midpoint rule in (z, phi), where object area is r dz dphi. The integrand is smooth,
        // so this grid gives many correct digits.
        constexpr int nz = 256, nphi = 512;
        double dz = (z_max_ - z_min_) / nz, dphi = phi_max_ / nphi, sum = 0;
        for (int i = 0; i < nz; ++i) {
            double z = z_min_ + (i + 0.5) * dz;
            double rxy = std::sqrt(std::max(0.0, radius_ * radius_ - z * z));
            for (int j = 0; j < nphi; ++j) {
                double phi = (j + 0.5) * dphi;
                Vec3d n{rxy * std::cos(phi) / radius_, rxy * std::sin(phi) / radius_, z / radius_};
                sum += area_scale(n);
            }
        }
        render_area_ = sum * radius_ * dz * dphi;
    }

    // The transform stretches no direction by more than the root of its columns' squared lengths
    // (the Frobenius norm bounds the spectral norm); a similarity stretches every direction by
    // one column's length.
    const Vec3f columns[3] = {render_vector({1, 0, 0}), render_vector({0, 1, 0}), render_vector({0, 0, 1})};
    const double stretch2 = is_similarity() ? length_squared(Vec3d(columns[0]))
                                            : length_squared(Vec3d(columns[0])) + length_squared(Vec3d(columns[1])) +
                                                  length_squared(Vec3d(columns[2]));
    bound_center_ = render_point({0, 0, 0}).to_float();
    bound_center_extent_ = max_component(abs(bound_center_));
    bound_radius_ = float(radius_ * std::sqrt(stretch2) * (1 + 1e-4));
}

bool Sphere::surely_missed(Vec3f o, Vec3f d) const {
    // Float rounding moves o - c, and the distances computed from it, by a few 1e-7 times the
    // coordinates' magnitudes (c's own rounding included); the ball is widened by 3e-5 times them,
    // a hundredfold margin. NaNs and zero directions compare false: they are left to the exact test.
    const float reach = bound_radius_ + 3e-5f * (max_component(abs(o)) + bound_center_extent_);
    const float reach2 = reach * reach;
    const Vec3f oc = o - bound_center_;
    const float b = dot(oc, d);
    // Outside the ball and moving away from its centre.
    if (b > 0 && length_squared(oc) > reach2) return true;
    // The line's closest approach to the centre lies outside the ball.
    return length_squared(oc - d * (b / length_squared(d))) > reach2;
}

Bounds3f Sphere::bounds() const {
    return render_bounds({-radius_, -radius_, z_min_}, {radius_, radius_, z_max_});
}

Vec3d Sphere::project_to_surface(Vec3d p) const { return p * (radius_ / length(p)); }

Vec2f Sphere::uv_of(Vec3d p) const {
    double phi = std::atan2(p.y, p.x);
    if (phi < 0) phi += TwoPi;
    double theta = std::acos(std::clamp(p.z / radius_, -1.0, 1.0));
    return {float(phi / phi_max_), float((theta - theta_z_min_) / (theta_z_max_ - theta_z_min_))};
}

std::optional<double> Sphere::hit_object(Vec3d o, Vec3d d, double t_max, Vec3d *p_hit, int n) const {
    double a = length_squared(d);
    if (!(a > 0)) return std::nullopt;
    double b = 2 * dot(d, o);
    double c = length_squared(o) - radius_ * radius_;
    // b^2 - 4ac written through the distance l from the centre to the line, 4a (r^2 - l^2),
    // which does not cancel catastrophically for distant or grazing rays.
    double l = length(o - d * (b / (2 * a)));
    double discriminant = 4 * a * (radius_ + l) * (radius_ - l);
    if (discriminant < 0) return std::nullopt;
    double root = std::sqrt(discriminant);
    double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
    double t0 = q / a, t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    for (double t : {t0, t1}) {
        if (!(t > 0)) continue;
        if (!(t < t_max)) break;
        // The point only matters to a cut sphere and to callers that ask for it.
        if (is_full_ && !p_hit) {
            if (n-- > 0) continue;
            return t;
        }
        Vec3d p = project_to_surface(o + d * t);
        if (!is_full_) {
            double phi = std::atan2(p.y, p.x);
            if (phi < 0) phi += TwoPi;
            if ((z_min_ > -radius_ && p.z < z_min_) || (z_max_ < radius_ && p.z > z_max_) ||
                phi > phi_max_)
                continue;
        }
        if (n-- > 0) continue;
        if (p_hit) *p_hit = p;
        return t;
    }
    return std::nullopt;
}

std::optional<float> Sphere::nth_hit(Vec3f o, Vec3f d, float t_max, int n) const {
    if (surely_missed(o, d)) return std::nullopt;
    std::optional<double> t = hit_object(object_point(o), object_vector(d), t_max, nullptr, n);
    if (!t) return std::nullopt;
    float tf = float(*t);
    // Rounding to float must keep the hit inside the open interval.
    if (!(tf > 0)) tf = std::nextafter(0.f, 1.f);
    return std::min(tf, t_max);
}

SurfaceInteraction Sphere::interaction(const Ray &ray, float t) const {
    Vec3d p = project_to_surface(object_point(ray.o) + object_vector(ray.d) * double(t));
    // At the poles phi is undefined and dp/du vanishes; like pbrt, take the derivatives a hair
    // off the pole (the point itself stays exact).
    double x = p.x, y = p.y;
    if (x == 0 && y == 0) x = 1e-5 * radius_;
    double z_radius = std::sqrt(x * x + y * y);
    double cos_phi = x / z_radius, sin_phi = y / z_radius;
    double theta_range = theta_z_max_ - theta_z_min_;
    // The angles are needed for (u, v) alone, which are floats: float arithmetic computes them
    // to within a few float ulps at a fraction of the double library calls' cost. The
    // derivatives use sin theta = z_radius / r instead.
    float phi = std::atan2(float(y), float(x));
    if (phi < 0) phi += 2 * Pi;
    float theta = std::acos(std::clamp(float(p.z / radius_), -1.f, 1.f));

    SurfaceInteraction si;
    si.p = render_point(p).to_float();
    si.n = render_normal(p / radius_);
    si.uv = {std::min(1.f, float(phi / phi_max_)),
             std::clamp(float((theta - theta_z_min_) / theta_range), 0.f, 1.f)};
    si.wo = -normalize(ray.d);
    si.dpdu = render_vector(Vec3d{-phi_max_ * y, phi_max_ * x, 0});
    si.dpdv = render_vector(Vec3d{p.z * cos_phi, p.z * sin_phi, -std::min(z_radius, radius_)} * theta_range);
    si.shading.n = si.n;
    si.shading.dpdu = si.dpdu;
    si.shading.dpdv = si.dpdv;
    si.t = t;
    return si;
}

std::optional<ShapeSample> Sphere::sample(Vec2f u) const {
    double z = z_min_ + double(u.x) * (z_max_ - z_min_);
    double phi = double(u.y) * phi_max_;
    double rxy = std::sqrt(std::max(0.0, radius_ * radius_ - z * z));
    Vec3d p = project_to_surface({rxy * std::cos(phi), rxy * std::sin(phi), z});
    Vec3d n_object = p / radius_;
    ShapeSample ss;
    ss.p = render_point(p).to_float();
    ss.n = render_normal(n_object);
    ss.uv = uv_of(p);
    ss.pdf = float(1 / (object_area() * area_scale(n_object)));
    return ss;
}

bool Sphere::uses_cone_sampling(Vec3d ref_object) const {
    return is_full_ && length_squared(ref_object) > radius_ * radius_;
}

std::optional<ShapeSample> Sphere::sample(Vec3f ref, Vec2f u) const {
    Vec3d ref_object = object_point(ref);
    if (!uses_cone_sampling(ref_object)) return Shape::sample(ref, u);

    // Directions towards the sphere form a cone of half-angle theta_max around the axis to the
    // centre, sin theta_max = r / d. Sample it uniformly, then find the angle alpha at the centre
    // between the axis and the first point hit: in the triangle ref-centre-point the law of sines
    // gives the angle at the point, whose supplement with theta gives alpha (the first hit is
    // the near side, so that angle is obtuse).
    double dist2 = length_squared(ref_object), dist = std::sqrt(dist2);
    double sin2_theta_max = radius_ * radius_ / dist2;
    double sin_theta_max = std::sqrt(sin2_theta_max);
    // 1 - cos theta_max without cancellation for small cones.
    double one_minus_cos_max = sin2_theta_max / (1 + std::sqrt(1 - sin2_theta_max));
    double one_minus_cos = double(u.x) * one_minus_cos_max;
    double cos_theta = 1 - one_minus_cos;
    double sin2_theta = one_minus_cos * (2 - one_minus_cos);
    double cos_alpha = sin2_theta / sin_theta_max +
                       cos_theta * std::sqrt(std::max(0.0, 1 - sin2_theta / sin2_theta_max));
    cos_alpha = std::clamp(cos_alpha, -1.0, 1.0);
    double sin_alpha = std::sqrt(std::max(0.0, 1 - cos_alpha * cos_alpha));
    double phi = double(u.y) * TwoPi;

    Vec3d axis = ref_object / dist, x, y;
    coordinate_system_d(axis, &x, &y);
    Vec3d n_object = x * (sin_alpha * std::cos(phi)) + y * (sin_alpha * std::sin(phi)) +
                     axis * cos_alpha;
    Vec3d p = project_to_surface(n_object * radius_);
    n_object = p / radius_;

    ShapeSample ss;
    ss.p = render_point(p).to_float();
    ss.n = render_normal(n_object);
    ss.uv = uv_of(p);
    ss.pdf = float(object_to_render_solid_angle_pdf(1 / (TwoPi * one_minus_cos_max), ref_object,
                                                    p, n_object));
    if (!(ss.pdf > 0) || !std::isfinite(ss.pdf)) return std::nullopt;
    return ss;
}

float Sphere::pdf(Vec3f ref, Vec3f wi) const {
    Vec3d ref_object = object_point(ref);
    Vec3d p;
    if (!hit_object(ref_object, object_vector(wi), Infinity, &p)) return 0;
    Vec3d n_object = p / radius_;
    double pdf;
    if (uses_cone_sampling(ref_object)) {
        double sin2_theta_max = radius_ * radius_ / length_squared(ref_object);
        double one_minus_cos_max = sin2_theta_max / (1 + std::sqrt(1 - sin2_theta_max));
        pdf = object_to_render_solid_angle_pdf(1 / (TwoPi * one_minus_cos_max), ref_object, p,
                                               n_object);
    } else {
        double pdf_area = 1 / (object_area() * area_scale(n_object));
        pdf = render_area_to_solid_angle_pdf(pdf_area, ref_object, p, n_object);
    }
    return std::isfinite(pdf) ? float(pdf) : 0;
}

} // namespace caustica
