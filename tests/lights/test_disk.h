// A disk Shape for the light tests, independent of the geometry module's shapes: centre c, unit
// normal n (the emitting side of a one-sided light), radius r.
#pragma once

#include "core/sampling.h"
#include "geometry/shape.h"

namespace caustica::testing {

class TestDisk final : public Shape {
  public:
    TestDisk(Vec3f center, Vec3f normal, float radius)
        : center_(center), frame_(Frame::from_z(normalize(normal))), radius_(radius) {}

    float area() const override { return Pi * radius_ * radius_; }
    Bounds3f bounds() const override {
        Bounds3f b;
        b.expand(center_ - Vec3f(radius_, radius_, radius_));
        b.expand(center_ + Vec3f(radius_, radius_, radius_));
        return b;
    }
    std::optional<ShapeSample> sample(Vec2f u) const override {
        Vec2f d = sample_uniform_disk_concentric(u);
        ShapeSample s;
        s.p = center_ + radius_ * frame_.from_local({d.x, d.y, 0});
        s.n = frame_.z;
        s.uv = u;
        s.pdf = 1 / area();
        return s;
    }
    std::optional<Hit> intersect(Vec3f o, Vec3f d, float t_max) const override {
        float denom = dot(d, frame_.z);
        if (denom == 0) return {};
        float t = dot(center_ - o, frame_.z) / denom;
        if (!(t > 0) || t > t_max) return {};
        Vec3f p = o + d * t;
        if (length_squared(p - center_) > radius_ * radius_) return {};
        return Hit{t, p, frame_.z, {}};
    }

  private:
    Vec3f center_;
    Frame frame_;
    float radius_;
};

}  // namespace caustica::testing
