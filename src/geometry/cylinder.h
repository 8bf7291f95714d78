// pbrt's cylinder: the surface x^2 + y^2 = radius^2 of object space for z in [z_min, z_max],
// optionally cut to phi in [0, phi_max], open at both ends; its normal faces away from the axis.
#pragma once

#include "geometry/analytic_shape.h"

namespace caustica {

class Cylinder : public AnalyticShape {
  public:
    // z_min and z_max are taken in increasing order; phi_max_degrees is clamped to [0, 360].
    Cylinder(const Transform &render_from_object, bool reverse_orientation, float radius,
             float z_min, float z_max, float phi_max_degrees);

    float area() const override { return float(render_area_); }
    Bounds3f bounds() const override;
    // Uniform in (z, phi), which is uniform by object-space area; the density is per
    // render-space area at the sampled point.
    std::optional<ShapeSample> sample(Vec2f u) const override;
    using Shape::sample;
    // The density of sample(ref, u) at the first point along wi.
    float pdf(Vec3f ref, Vec3f wi) const override;

    std::optional<float> nth_hit(Vec3f o, Vec3f d, float t_max, int n) const override;
    SurfaceInteraction interaction(const Ray &ray, float t) const override;

  private:
    // Whether the object-space point (on the infinite cylinder) lies on the cut surface.
    bool on_surface(Vec3d p) const;
    Vec2f uv_of(Vec3d p) const;
    // The object-space ray parameter of hit n (0: the first) in (0, t_max), or a negative
    // number.
    double hit_object(Vec3d o, Vec3d d, double t_max, int n = 0) const;
    double object_area() const { return radius_ * (z_max_ - z_min_) * phi_max_; }

    double radius_, z_min_, z_max_, phi_max_;
    double render_area_;
};

} // namespace caustica
