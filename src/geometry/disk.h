// pbrt's disk: an annulus of radii [inner_radius, radius] in the plane z = height of object space,
// optionally cut to phi in [0, phi_max]; its normal faces +z.
#pragma once

#include "geometry/analytic_shape.h"

namespace caustica {

class Disk : public AnalyticShape {
  public:
    Disk(const Transform &render_from_object, bool reverse_orientation, float height,
         float radius, float inner_radius, float phi_max_degrees);

    float area() const override { return float(render_area_); }
    Bounds3f bounds() const override;
    // Uniform by area (an affine map scales a plane's area by a constant factor).
    std::optional<ShapeSample> sample(Vec2f u) const override;
    // A plane has one normal: the one its hits and samples carry.
    DirectionCone normal_bounds() const override { return {render_normal({0, 0, 1}), 1.f}; }

    std::optional<float> nth_hit(Vec3f o, Vec3f d, float t_max, int n) const override;
    SurfaceInteraction interaction(const Ray &ray, float t) const override;

  private:
    double height_, radius_, inner_radius_, phi_max_;
    double render_area_;
};

} // namespace caustica
