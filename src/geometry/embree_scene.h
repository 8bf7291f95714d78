// The scene's geometry in Embree: shapes, prototypes (object instancing) and instances, and the
// closest-hit and any-hit queries that turn Embree's hits into SurfaceInteractions.
//
// Motion blur: a moving shape or instance is an Embree instance with two time steps, given as
// Embree's quaternion decompositions T R S of its start and end placements, with S upper
// triangular (scale and skew). Embree interpolates T and S linearly and R by slerp, and a hit is
// moved to render space by the very transform Embree traced it with (rtcGetGeometryTransform).
// pbrt-v4 interpolates a polar decomposition (S symmetric) instead; the two agree for every
// motion of translations, rotations and uniform scales, and for non-uniform scales applied
// after the rotation (nearest the object), and differ between the end points only when a
// non-uniform scale is applied before a rotation that changes.
#pragma once

#include "core/animated_transform.h"
#include "geometry/alpha_mask.h"
#include "geometry/interaction.h"
#include "geometry/shape_group.h"

#include <embree3/rtcore.h>

#include <memory>
#include <utility>
#include <vector>

namespace caustica {

class Material;
struct EmbreeCallbackData;
class Light;
struct MediumInterface;

// What the renderer attaches to the primitives of one shape directive.
struct PrimitiveAttributes {
    const Material *material = nullptr;
    const MediumInterface *medium_interface = nullptr;
    // Empty, or one per primitive of the group (ShapeGroup::shapes() order).
    std::vector<const Light *> area_lights;
    // Null for an opaque shape; rays pass where the mask lets them (alpha_mask.h).
    std::shared_ptr<const AlphaMask> alpha;
};

class GeometryScene {
  public:
    GeometryScene();
    ~GeometryScene();
    GeometryScene(const GeometryScene &) = delete;
    GeometryScene &operator=(const GeometryScene &) = delete;

    // Building (single-threaded, before commit()).
    void add(std::shared_ptr<const ShapeGroup> group, PrimitiveAttributes attributes);
    // An object that instances refer to, built as its own Embree scene. Returns its index.
    int add_prototype(
        std::vector<std::pair<std::shared_ptr<const ShapeGroup>, PrimitiveAttributes>> shapes);
    void add_instance(int prototype, const AnimatedTransform &render_from_instance);
    // A shape whose group is built in its object space, placed by a moving transform.
    void add_moving(std::shared_ptr<const ShapeGroup> group, PrimitiveAttributes attributes,
                    const AnimatedTransform &render_from_object);
    // When moving placements are at their start and end (rays' times are scene times).
    void set_transform_times(TransformTimes times) { times_ = times; }
    bool moves() const { return moving_instances_ > 0; }
    // Builds the acceleration structure (high quality, robust traversal). Call once.
    void commit();

    // Queries, safe to call from many threads at once after commit().
    // Closest hit with 0 < t <= ray.t_max, with the geometry where it is at ray.time; fills every
    // field of *si.
    bool intersect(const Ray &ray, SurfaceInteraction *si) const;
    // The surface record of a hit that intersect() reported (si.hit), rebuilt from the point si.p
    // and the direction si.wo: the same record, t aside (0 here), except that analytic
    // shapes and curves start from the point rather than from the ray, which may move their
    // other fields (normals, derivatives, (u, v)) by a few float ulps. The point is si.p itself.
    SurfaceInteraction interaction(const SurfaceHit &hit, Vec3f p, Vec3f wo, float time) const;
    // Hits in 12 bytes (PackedSurfaceHit), for scenes whose shapes, each instance's counted once
    // per instance, number fewer than 2^32 - 1 (packs_hits()); unpack(pack(hit)) is hit with its
    // (u, v) rounded.
    bool packs_hits() const { return packs_hits_; }
    PackedSurfaceHit pack(const SurfaceHit &hit) const;
    SurfaceHit unpack(const PackedSurfaceHit &packed) const;
    // Any hit with 0 < t < ray.t_max.
    bool occluded(const Ray &ray) const;

    Bounds3f bounds() const;
    size_t shape_count() const { return shape_count_; }        // directives, prototypes' once
    size_t triangle_count() const { return triangle_count_; }  // stored, prototypes' once
    size_t instance_count() const { return instances_.size(); }
    // For benchmarks of raw Embree traversal.
    RTCScene handle() const { return scene_; }

  private:
    struct Primitive {
        std::shared_ptr<const ShapeGroup> group;
        PrimitiveAttributes attributes;
    };
    struct Instance {
        int prototype;
        Transform render_from_instance, instance_from_render;
        RTCGeometry moving = nullptr; // a moving instance's Embree geometry (owned by the scene)
    };
    struct Prototype {
        RTCScene scene;
        std::vector<Primitive> primitives; // by Embree geometry ID
    };
    // Top-level geometry IDs are either a primitive or an instance.
    struct Slot {
        Primitive primitive;
        int instance = -1;
    };

    // The surface record of hit as found by ray at parameter t.
    void fill_interaction(const SurfaceHit &hit, const Ray &ray, float t, SurfaceInteraction *si) const;
    // Attaches the group's Embree geometry to scene with ID geometry_id.
    void attach(RTCScene scene, unsigned geometry_id, const ShapeGroup &group, const AlphaMask *alpha);
    RTCScene new_scene() const;
    void check_device(const char *what) const;
    // The placement of a moving instance at Embree time u in [0, 1].
    Transform transform_at(const Instance &instance, float u) const;

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<Slot> slots_;
    std::vector<Prototype> prototypes_;
    std::vector<Instance> instances_;
    // Per slot, the packed index of its first shape, and the shape count after the last slot.
    std::vector<uint64_t> first_packed_shape_;
    bool packs_hits_ = false;
    // What Embree's callbacks read for each geometry (embree_scene.cpp).
    std::vector<std::unique_ptr<EmbreeCallbackData>> callback_data_;
    size_t shape_count_ = 0, triangle_count_ = 0, moving_instances_ = 0;
    TransformTimes times_;
    bool committed_ = false;
};

} // namespace caustica
