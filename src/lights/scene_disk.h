// Emission from lights at infinity (distant and environment lights) for light paths: all light
// that can reach the scene crosses its bounding sphere, so for a direction w it suffices to start
// rays uniformly on the disk of the sphere's radius, perpendicular to w, placed one radius behind
// the centre (Veach's thesis, sec. 10.4; pbrt-v4 sec. 12.5). The positional density is uniform
// over that disk, 1 / (pi r^2), measured on the plane perpendicular to w.
#pragma once

#include "core/sampling.h"
#include "core/vecmath.h"
#include "geometry/ray.h"

namespace caustica {

struct SceneSphere {
    Vec3f center;
    float radius = 0;

    static SceneSphere from_bounds(const Bounds3f &b) {
        SceneSphere s;
        b.bounding_sphere(&s.center, &s.radius);
        return s;
    }
    float disk_area() const { return Pi * radius * radius; }
    float disk_pdf() const { return radius > 0 ? 1 / disk_area() : 0; }

    // A ray travelling along unit direction w that starts on the disk (sample u).
    Ray ray_into(Vec3f w, Vec2f u) const {
        Frame frame = Frame::from_z(w);
        Vec2f d = sample_uniform_disk_concentric(u);
        Vec3f p = center + radius * frame.from_local({d.x, d.y, 0}) - radius * w;
        return {p, w, Infinity};
    }
};

}  // namespace caustica
