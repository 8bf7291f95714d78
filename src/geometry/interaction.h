// What an intersection or a sampled point on a surface knows about it.
#pragma once

#include "core/vecmath.h"
#include "geometry/ray.h"
#include "geometry/surface_hit.h"

namespace caustica {

class Material;
class Light;
class Medium;
struct MediumInterface;

struct SurfaceInteraction {
    Vec3f p;        // on the surface (not o + t d), as robust spawning requires
    // The magnitude of the coordinates p was computed from, when larger than p's own (a
    // triangle's vertices, an instance's placement), 0 otherwise: rays leave p by an offset that
    // grows with it (rounding_scale, geometry/ray.h).
    float error_scale = 0;
    Vec3f n;        // geometric normal, unit; flipped by ReverseOrientation / handedness
    Vec2f uv;
    Vec3f wo;       // towards the ray origin, unit
    Vec3f dpdu, dpdv;
    struct {
        Vec3f n;    // shading normal, unit, in the hemisphere of n
        Vec3f dpdu, dpdv;
    } shading;
    // How the point moves from pixel to pixel on the film (camera/camera_footprint.h), set before
    // shading; zero when unknown, which makes texture lookups use their finest level.
    Vec3f dpdx, dpdy;
    float dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
    float t = 0;    // ray parameter of the hit
    float time = 0; // the ray's time (geometry/ray.h), which rays spawned here keep
    int face_index = 0;
    // The fraction of the surface that is there around the hit: the alpha of a partly
    // transparent cut-out (alpha_mask.h), 1 elsewhere. Rays meet such a surface only that often,
    // so photon density estimates here are divided by it.
    float coverage = 1;

    // What the ray met, for GeometryScene::interaction to rebuild this record later; left
    // without a slot for points that no ray found (sampled points on lights).
    SurfaceHit hit;

    const Material *material = nullptr;      // null: a boundary between media only
    const Light *area_light = nullptr;       // emitter attached to this primitive, if any
    const MediumInterface *medium_interface = nullptr;
    // The participating medium inside the material here, set with the BSDF (shade(), material.h).
    const Medium *interior = nullptr;

    Ray spawn_ray(Vec3f d) const { return caustica::spawn_ray(p, n, error_scale, d, time); }
    // Towards p_to on a surface with normal n_to and its error scale (n_to zero: not on a surface).
    Ray spawn_ray_to(Vec3f p_to, Vec3f n_to = {}, float error_scale_to = 0) const {
        return caustica::spawn_ray_to(p, n, error_scale, p_to, n_to, error_scale_to, time);
    }
    // Replaces the shading frame; keeps the shading normal on the geometric normal's side.
    void set_shading(Vec3f ns, Vec3f dpdus, Vec3f dpdvs) {
        shading.n = face_forward(ns, n);
        shading.dpdu = dpdus;
        shading.dpdv = dpdvs;
    }
    // The shading frame of an interpolated unit normal ns (meshes, patches): ns, with the tangent
    // along dp/du made orthogonal to it (any tangent where dp/du lies along ns).
    void set_shading_normal(Vec3f ns) {
        Vec3f ss = dpdu;
        Vec3f ts = cross(ns, ss);
        if (length_squared(ts) > 0) {
            ss = cross(ts, ns);
        } else {
            coordinate_system(ns, &ss, &ts);
        }
        set_shading(ns, ss, ts);
    }
};

} // namespace caustica
