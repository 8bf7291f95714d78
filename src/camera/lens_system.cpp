#include "camera/lens_system.h"

#include "core/error.h"

#include <cmath>

namespace caustica {

namespace {

// The intersection of the ray with the spherical interface of signed radius r whose vertex lies
// on the axis at vertex_z: of the sphere's two crossings, the one on the cap around the vertex.
std::optional<double> hit_spherical_interface(const LensRay &ray, double vertex_z, double r, Vec3d *normal) {
    const Vec3d centre{0, 0, vertex_z - r};
    const Vec3d oc = ray.o - centre;
    const double a = dot(ray.d, ray.d), b = 2 * dot(ray.d, oc), c = dot(oc, oc) - r * r;
    const double discriminant = b * b - 4 * a * c;
    if (!(discriminant >= 0) || !(a > 0)) return std::nullopt;
    const double root = std::sqrt(discriminant);
    const double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
    double t0 = q / a, t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    // A ray travelling towards the film (-z) meets a surface whose centre lies towards the film
    // (r > 0) at its near side, and one whose centre lies towards the scene at its far side; the
    // other way round for a ray travelling towards the scene.
    const bool nearer = (ray.d.z < 0) != (r < 0);
    const double t = nearer ? t0 : t1;
    if (!(t >= 0)) return std::nullopt;
    Vec3d n = normalize(ray.o + ray.d * t - centre);
    if (dot(n, ray.d) > 0) n = -n;
    *normal = n;
    return t;
}

// Snell's law for a direction d crossing an interface whose normal n faces d's origin, from
// index eta_i into eta_t; empty on total internal reflection.
std::optional<Vec3d> refract_direction(Vec3d d, Vec3d n, double eta_i, double eta_t) {
    const Vec3d wi = -normalize(d);
    const double eta = eta_t / eta_i;
    const double cos_i = dot(n, wi);
    const double sin2_t = std::max(0.0, 1 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1) return std::nullopt;
    const double cos_t = std::sqrt(1 - sin2_t);
    return -wi / eta + (cos_i / eta - cos_t) * n;
}

} // namespace

LensSystem LensSystem::from_description(const std::vector<float> &values_mm, double stop_diameter_mm,
                                        bool *clamped) {
    if (values_mm.size() % 4 != 0)
        throw InputError("a lens description holds four values per interface (radius, thickness, index of "
                         "refraction, aperture diameter), but this one holds " +
                         std::to_string(values_mm.size()));
    LensSystem lens;
    *clamped = false;
    for (size_t i = 0; i < values_mm.size(); i += 4) {
        const std::string row = "interface " + std::to_string(i / 4 + 1);
        LensInterface element;
        element.curvature_radius = values_mm[i] / 1000.0;
        element.thickness = values_mm[i + 1] / 1000.0;
        element.eta = values_mm[i + 2];
        double diameter = values_mm[i + 3] / 1000.0;
        if (!(element.thickness >= 0)) throw InputError(row + ": the thickness must not be negative");
        if (!(element.eta >= 0)) throw InputError(row + ": the index of refraction must not be negative");
        if (!(diameter > 0)) throw InputError(row + ": the aperture diameter must be positive");
        if (element.is_stop()) {
            if (stop_diameter_mm / 1000.0 > diameter) *clamped = true;
            else diameter = stop_diameter_mm / 1000.0;
        }
        element.aperture_radius = diameter / 2;
        lens.interfaces_.push_back(element);
    }
    return lens;
}

double LensSystem::front_z() const {
    double z = 0;
    for (const LensInterface &element : interfaces_) z += element.thickness;
    return z;
}

std::optional<LensRay> LensSystem::trace_from_film(LensRay ray, const ApertureMask *mask, float *weight) const {
    return trace(ray, true, mask, weight);
}

std::optional<LensRay> LensSystem::trace_from_scene(LensRay ray) const { return trace(ray, false, nullptr, nullptr); }

std::optional<LensRay> LensSystem::trace(LensRay ray, bool from_film, const ApertureMask *mask, float *weight) const {
    const int n = int(interfaces_.size());
    // The index of the gap behind interface i (towards the film); air is written 0 or 1.
    auto eta_behind = [&](int i) { return interfaces_[i].eta != 0 ? interfaces_[i].eta : 1.0; };
    auto eta_in_front = [&](int i) { return i > 0 ? eta_behind(i - 1) : 1.0; };
    if (weight) *weight = 1;
    double vertex_z = from_film ? 0 : front_z();
    for (int k = 0; k < n; ++k) {
        const int i = from_film ? n - 1 - k : k;
        const LensInterface &element = interfaces_[i];
        if (from_film) vertex_z += element.thickness;

        double t;
        Vec3d normal;
        if (element.is_stop()) {
            t = (vertex_z - ray.o.z) / ray.d.z;
            if (!(t >= 0)) return std::nullopt;
        } else {
            std::optional<double> hit = hit_spherical_interface(ray, vertex_z, element.curvature_radius, &normal);
            if (!hit) return std::nullopt;
            t = *hit;
        }
        const Vec3d p = ray.o + ray.d * t;
        if (element.is_stop() && mask && from_film) {
            const float w = mask->value({float((p.x / element.aperture_radius + 1) / 2),
                                         float((p.y / element.aperture_radius + 1) / 2)});
            if (w == 0) return std::nullopt;
            if (weight) *weight = w;
        } else if (p.x * p.x + p.y * p.y > element.aperture_radius * element.aperture_radius) {
            return std::nullopt;
        }
        ray.o = p;
        if (!element.is_stop()) {
            const double eta_from = from_film ? eta_behind(i) : eta_in_front(i);
            const double eta_to = from_film ? eta_in_front(i) : eta_behind(i);
            std::optional<Vec3d> d = refract_direction(ray.d, normal, eta_from, eta_to);
            if (!d) return std::nullopt;
            ray.d = *d;
        }
        if (!from_film) vertex_z -= element.thickness;
    }
    return ray;
}

void LensSystem::focus(double focus_distance, double film_diagonal) {
    // Cardinal points, as distances behind the film plane (negative camera z, pbrt-v4's lens
    // space), from a paraxial ray parallel to the axis on each side: where the outgoing ray meets
    // the axis is the focal point, where it meets the incoming ray's height the principal plane.
    auto cardinal_points = [](const LensRay &in, const LensRay &out, double *principal, double *focal) {
        const double t_focal = -out.o.x / out.d.x;
        *focal = -(out.o.z + t_focal * out.d.z);
        const double t_principal = (in.o.x - out.o.x) / out.d.x;
        *principal = -(out.o.z + t_principal * out.d.z);
    };
    const double height = 0.001 * film_diagonal;
    double principal[2], focal[2];
    const LensRay from_scene{{height, 0, front_z() + 1}, {0, 0, -1}};
    const LensRay from_film{{height, 0, rear_z() - 1}, {0, 0, 1}};
    std::optional<LensRay> to_film = trace_from_scene(from_scene);
    std::optional<LensRay> to_scene = trace_from_film(from_film);
    if (!to_film || !to_scene || to_film->d.x == 0 || to_scene->d.x == 0)
        throw InputError("no paraxial ray passes the lens system, so it cannot be focused (is the aperture "
                         "stop extremely small?)");
    cardinal_points(from_scene, *to_film, &principal[0], &focal[0]);
    cardinal_points(from_film, *to_scene, &principal[1], &focal[1]);

    // The film shift delta that images the plane at z = -focus_distance (film side negative) by
    // the thick-lens equation 1/z' - 1/z = 1/f between the principal planes.
    const double f = focal[0] - principal[0];
    const double z = -focus_distance;
    const double c = (principal[1] - z - principal[0]) * (principal[1] - z - 4 * f - principal[0]);
    if (!(c > 0))
        throw InputError("the lens cannot focus at distance " + std::to_string(focus_distance) +
                         ": it is too short for this lens (effective focal length " + std::to_string(f) + " m)");
    const double delta = (principal[1] - z + principal[0] - std::sqrt(c)) / 2;
    interfaces_.back().thickness += delta;
    if (!(interfaces_.back().thickness > 0) || !std::isfinite(interfaces_.back().thickness))
        throw InputError("focused at distance " + std::to_string(focus_distance) +
                         ", the film would lie at or inside the lens's rear element");
}

} // namespace caustica
