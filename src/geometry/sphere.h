// pbrt's sphere: radius, optionally cut to z in [z_min, z_max] and phi in [0, phi_max], centred
// at the object-space origin.
#pragma once

#include "geometry/analytic_shape.h"

namespace caustica {

class Sphere : public AnalyticShape {
  public:
    // z_min/z_max are clamped to [-radius, radius]; phi_max_degrees to [0, 360].
    Sphere(const Transform &render_from_object, bool reverse_orientation, float radius,
           float z_min, float z_max, float phi_max_degrees);

    float radius() const { return float(radius_); }
    bool is_full() const { return is_full_; }

    float area() const override { return float(render_area_); }
    Bounds3f bounds() const override;
    // Uniform over the object-space surface: z and phi are uniform on a sphere's zone
    // (Archimedes' hat-box theorem); the pdf accounts for any area distortion by the transform.
    std::optional<ShapeSample> sample(Vec2f u) const override;
    // From outside a full sphere: uniform over the cone of directions it subtends in object
    // space; otherwise area sampling.
    std::optional<ShapeSample> sample(Vec3f ref, Vec2f u) const override;
    float pdf(Vec3f ref, Vec3f wi) const override;

    std::optional<float> nth_hit(Vec3f o, Vec3f d, float t_max, int n) const override;
    SurfaceInteraction interaction(const Ray &ray, float t) const override;

  private:
    // Object-space hit n (0: the first) with 0 < t < t_max (object point projected onto the
    // sphere).
    std::optional<double> hit_object(Vec3d o, Vec3d d, double t_max, Vec3d *p_hit, int n = 0) const;
    // Whether the line through o along d certainly misses a ball around the whole sphere, decided
    // in float with a margin far above float's rounding: most rays tested never come near the
    // sphere, and this spares them the exact test in double (which it never contradicts).
    bool surely_missed(Vec3f o, Vec3f d) const;
    Vec3d project_to_surface(Vec3d p) const;
    Vec2f uv_of(Vec3d p_object) const;
    bool uses_cone_sampling(Vec3d ref_object) const;
    double object_area() const { return phi_max_ * radius_ * (z_max_ - z_min_); }

    double radius_, z_min_, z_max_, theta_z_min_, theta_z_max_, phi_max_;
    bool is_full_;
    double render_area_;
    // A ball in render space that holds the sphere: its centre (and that centre's largest
    // coordinate magnitude), and its radius widened by a relative 1e-4 (see surely_missed).
    Vec3f bound_center_;
    float bound_center_extent_, bound_radius_;
};

} // namespace caustica
