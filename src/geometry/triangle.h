// One triangle of a TriangleMesh seen as a Shape, so that an area light can be attached to each
// triangle of an emissive mesh.
#pragma once

#include "geometry/shape.h"
#include "geometry/triangle_mesh.h"
#include "geometry/vec3d.h"

#include <memory>

namespace caustica {

class Triangle : public Shape {
  public:
    Triangle(std::shared_ptr<const TriangleMesh> mesh, int index);

    float area() const override { return area_; }
    Bounds3f bounds() const override;
    DirectionCone normal_bounds() const override;
    std::optional<ShapeSample> sample(Vec2f u) const override;
    // Uniform over the subtended solid angle (spherical triangle sampling) when the triangle
    // covers a sizeable solid angle; area sampling otherwise, where the two nearly agree.
    std::optional<ShapeSample> sample(Vec3f ref, Vec2f u) const override;
    float pdf(Vec3f ref, Vec3f wi) const override;
    std::optional<Hit> intersect(Vec3f o, Vec3f d, float t_max) const override;

    // Solid angle subtended at ref.
    float solid_angle(Vec3f ref) const;
    const TriangleMesh &mesh() const { return *mesh_; }
    int index() const { return index_; }

  private:
    // Barycentrics where the line o + t d crosses the triangle's plane, with t; no range checks.
    bool plane_crossing(Vec3d o, Vec3d d, double *t, double b[3]) const;
    static bool uses_spherical_sampling(double omega);
    // Solid angle at ref in double, and the unit directions to the vertices (0 if ref is one).
    double subtended(Vec3f ref, Vec3d directions[3]) const;
    ShapeSample sample_at(const double b[3]) const;

    std::shared_ptr<const TriangleMesh> mesh_;
    int index_;
    float area_;
};

} // namespace caustica
