// Shapes as seen by lights: area, uniform area sampling and solid-angle sampling from a point.
// Intersection itself goes through Embree (geometry/embree_scene.h).
#pragma once

#include "core/vecmath.h"
#include "geometry/direction_cone.h"

#include <optional>

namespace caustica {

struct ShapeSample {
    Vec3f p, n;      // sampled point and its (oriented) geometric normal
    float error_scale = 0; // as SurfaceInteraction::error_scale
    Vec2f uv;
    float pdf = 0;   // area density from sample(u); solid-angle density from sample(ref, u)
};

class Shape {
  public:
    virtual ~Shape() = default;
    virtual float area() const = 0;
    virtual Bounds3f bounds() const = 0;
    // A cone holding the (oriented) normal of every point of the shape. Default: any direction.
    virtual DirectionCone normal_bounds() const { return DirectionCone::entire_sphere(); }
    // Uniform by area.
    virtual std::optional<ShapeSample> sample(Vec2f u) const = 0;
    // Sampled as seen from ref; pdf with respect to solid angle at ref. Default: area sampling
    // converted to solid angle.
    virtual std::optional<ShapeSample> sample(Vec3f ref, Vec2f u) const;
    // Solid-angle density of sample(ref, u) producing direction wi (hit found by ray casting
    // against this shape alone).
    virtual float pdf(Vec3f ref, Vec3f wi) const;
    // Area density of sample(u) at the point p of the shape. Default: uniform by area.
    virtual float pdf_area(Vec3f) const { return 1 / area(); }
    // Whether sample(u) is uniform by area, so that pdf_area is 1 / area() everywhere.
    virtual bool samples_uniformly_by_area() const { return true; }
    // Intersection of a ray with this shape alone (used by pdf and light tracing).
    struct Hit { float t; Vec3f p, n; Vec2f uv; };
    virtual std::optional<Hit> intersect(Vec3f o, Vec3f d, float t_max) const = 0;
};

} // namespace caustica
