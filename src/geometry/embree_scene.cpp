#include "geometry/embree_scene.h"

#include "core/error.h"
#include "core/next_float.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

namespace caustica {

// What Embree's callbacks read for one geometry: its shape, and its alpha mask (null if opaque).
struct EmbreeCallbackData {
    const TriangleMesh *mesh;
    const AnalyticShape *analytic;
    const CurveSet *curves;
    const BilinearPatchMesh *patches;
    const AlphaMask *alpha;
};

// A query's Embree context, with the ray's extent as the query began, which the curves' filter
// needs (Embree gives filters only the distance of the hit they judge).
struct QueryContext {
    RTCIntersectContext embree;
    float t_max;
};

namespace {

constexpr unsigned CurveTessellationRate = 16;

// A hit of user geometry: the ray parameter and the (u, v) reported to Embree (a patch's
// parameters; 0 for analytic shapes, which find their surface record from t).
using UserHit = BilinearPatchMesh::Hit;

// Embree reports errors through this callback; build steps then check rtcGetDeviceError.
void report_embree_error(void *, RTCError code, const char *message) {
    if (code != RTC_ERROR_NONE) warning(std::string("Embree: ") + (message ? message : "error"));
}

const EmbreeCallbackData &data_of(void *user) { return *static_cast<const EmbreeCallbackData *>(user); }

void write_bounds(const Bounds3f &b, RTCBounds *out) {
    out->lower_x = b.lo.x;
    out->lower_y = b.lo.y;
    out->lower_z = b.lo.z;
    out->upper_x = b.hi.x;
    out->upper_y = b.hi.y;
    out->upper_z = b.hi.z;
}

// User geometry callbacks for analytic shapes and bilinear patches: our double-precision
// intersection code.
void analytic_bounds(const RTCBoundsFunctionArguments *args) {
    write_bounds(data_of(args->geometryUserPtr).analytic->bounds(), args->bounds_o);
}
void patch_bounds(const RTCBoundsFunctionArguments *args) {
    write_bounds(data_of(args->geometryUserPtr).patches->bounds(int(args->primID)), args->bounds_o);
}

Vec3f ray_origin(RTCRayN *rays, unsigned n, unsigned i) {
    return {RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)};
}
Vec3f ray_direction(RTCRayN *rays, unsigned n, unsigned i) {
    return {RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i)};
}

// Whether the alpha mask lets the ray o + t d pass the surface record si of its hit at t.
bool passes(const AlphaMask &alpha, Vec3f o, Vec3f d, float t, const SurfaceInteraction &si) {
    return !alpha.stops(TextureEvalContext(si), AlphaMask::uniform(o.x, o.y, o.z, d.x, d.y, d.z, t));
}

// The first hit of an analytic shape in [t_near, t_far) that its alpha mask does not let pass.
std::optional<float> analytic_hit(const EmbreeCallbackData &data, Vec3f o, Vec3f d, float t_near,
                                  float t_far) {
    for (int n = 0;; ++n) {
        std::optional<float> t = data.analytic->nth_hit(o, d, t_far, n);
        if (!t) return std::nullopt;
        if (*t < t_near) continue;
        if (data.alpha) {
            Ray ray;
            ray.o = o;
            ray.d = d;
            if (passes(*data.alpha, o, d, *t, data.analytic->interaction(ray, *t))) continue;
        }
        return t;
    }
}

// The first hit of a bilinear patch in [t_near, t_far) that its alpha mask does not let pass.
std::optional<BilinearPatchMesh::Hit> patch_hit(const EmbreeCallbackData &data, int patch, Vec3f o, Vec3f d,
                                                float t_near, float t_far) {
    BilinearPatchMesh::Hit hits[2];
    const int count = data.patches->hits(patch, o, d, t_far, hits);
    for (int n = 0; n < count; ++n) {
        if (hits[n].t < t_near) continue;
        if (data.alpha) {
            SurfaceInteraction si;
            data.patches->interaction(patch, hits[n].uv, &si);
            if (passes(*data.alpha, o, d, hits[n].t, si)) continue;
        }
        return hits[n];
    }
    return std::nullopt;
}

// A user geometry's first hit along ray i of the packet, found by first_hit(o, d, t_near, t_far)
// as an optional UserHit, reported to Embree as a hit of the primitive.
template <typename FirstHit>
void intersect_user_geometry(const RTCIntersectFunctionNArguments *args, FirstHit first_hit) {
    RTCRayN *rays = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN *hits = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        // The ray arrives in the space the geometry lives in (an instance's, if instanced).
        const std::optional<UserHit> hit =
            first_hit(ray_origin(rays, args->N, i), ray_direction(rays, args->N, i), RTCRayN_tnear(rays, args->N, i),
                      RTCRayN_tfar(rays, args->N, i));
        if (!hit) continue;
        RTCRayN_tfar(rays, args->N, i) = hit->t;
        RTCHitN_Ng_x(hits, args->N, i) = 0;
        RTCHitN_Ng_y(hits, args->N, i) = 0;
        RTCHitN_Ng_z(hits, args->N, i) = 1;
        RTCHitN_u(hits, args->N, i) = hit->uv.x;
        RTCHitN_v(hits, args->N, i) = hit->uv.y;
        RTCHitN_primID(hits, args->N, i) = args->primID;
        RTCHitN_geomID(hits, args->N, i) = args->geomID;
        for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; ++l)
            RTCHitN_instID(hits, args->N, i, l) = args->context->instID[l];
    }
}

// Marks ray i of the packet occluded where any_hit(o, d, t_near, t_far) finds a hit.
template <typename AnyHit>
void occlude_user_geometry(const RTCOccludedFunctionNArguments *args, AnyHit any_hit) {
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        if (any_hit(ray_origin(args->ray, args->N, i), ray_direction(args->ray, args->N, i),
                    RTCRayN_tnear(args->ray, args->N, i), RTCRayN_tfar(args->ray, args->N, i)))
            RTCRayN_tfar(args->ray, args->N, i) = -Infinity; // Embree's "occluded" mark
    }
}

void analytic_intersect(const RTCIntersectFunctionNArguments *args) {
    const EmbreeCallbackData &data = data_of(args->geometryUserPtr);
    intersect_user_geometry(args, [&](Vec3f o, Vec3f d, float t_near, float t_far) -> std::optional<UserHit> {
        const std::optional<float> t = analytic_hit(data, o, d, t_near, t_far);
        if (!t) return std::nullopt;
        return UserHit{*t, {0, 0}};
    });
}

void analytic_occluded(const RTCOccludedFunctionNArguments *args) {
    const EmbreeCallbackData &data = data_of(args->geometryUserPtr);
    occlude_user_geometry(args, [&](Vec3f o, Vec3f d, float t_near, float t_far) {
        return analytic_hit(data, o, d, t_near, t_far).has_value();
    });
}

void patch_intersect(const RTCIntersectFunctionNArguments *args) {
    const EmbreeCallbackData &data = data_of(args->geometryUserPtr);
    intersect_user_geometry(args, [&](Vec3f o, Vec3f d, float t_near, float t_far) {
        return patch_hit(data, int(args->primID), o, d, t_near, t_far);
    });
}

void patch_occluded(const RTCOccludedFunctionNArguments *args) {
    const EmbreeCallbackData &data = data_of(args->geometryUserPtr);
    occlude_user_geometry(args, [&](Vec3f o, Vec3f d, float t_near, float t_far) {
        return patch_hit(data, int(args->primID), o, d, t_near, t_far).has_value();
    });
}

// Embree's intersection and occlusion filter for a cut-out mesh: drops each candidate hit that
// the alpha mask lets the ray pass. Embree gives the candidate's distance as the ray's tfar.
void mesh_alpha_filter(const RTCFilterFunctionNArguments *args) {
    const EmbreeCallbackData &data = data_of(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
        const float b[3] = {std::max(0.f, 1 - u - v), u, v};
        SurfaceInteraction si;
        data.mesh->interaction(int(RTCHitN_primID(args->hit, args->N, i)), b, &si);
        if (passes(*data.alpha, ray_origin(args->ray, args->N, i), ray_direction(args->ray, args->N, i),
                   RTCRayN_tfar(args->ray, args->N, i), si))
            args->valid[i] = 0;
    }
}

// Embree's intersection and occlusion filter for curves. A curve stands for a thin tube, which
// a ray that leaves its surface, or arrives at it, meets nowhere else nearby. The ray-facing
// ribbon that takes its place for each ray does not know this: a ray leaving a point of the
// curve nearly along it, or one arriving so, stays within the width and meets the ribbon again
// (about 1% of the directions from a straight fibre). So a hit is dropped when an end of the ray
// lies within the curve's width of the line that touches its centre line at the hit. (pbrt-v4
// offsets such rays, and their targets, by up to 1.7 widths instead: its curves' error bound.)
// Then the hits outside a ribbon (CurveSet::covers), and those that the alpha mask lets pass,
// are dropped.
void curve_filter(const RTCFilterFunctionNArguments *args) {
    const EmbreeCallbackData &data = data_of(args->geometryUserPtr);
    const float t_max = reinterpret_cast<const QueryContext *>(args->context)->t_max;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const int segment = int(RTCHitN_primID(args->hit, args->N, i));
        const float u = std::clamp(RTCHitN_u(args->hit, args->N, i), 0.f, 1.f);
        const float t = RTCRayN_tfar(args->ray, args->N, i);
        const Vec3f o = ray_origin(args->ray, args->N, i), d = ray_direction(args->ray, args->N, i);
        // In the space the curves live in (an instance's, if instanced), as the width is.
        Vec3f tangent;
        const Vec3f centre = data.curves->render_point(segment, u, &tangent);
        const float width = data.curves->render_width(segment, u);
        const auto near_tangent = [&](Vec3f p) {
            const Vec3f offset = p - centre;
            return length(offset - tangent * dot(offset, tangent)) < width;
        };
        const bool leaves = near_tangent(o), arrives = std::isfinite(t_max) && near_tangent(o + d * t_max);
        if (leaves || arrives || !data.curves->covers(segment, u, o, d, t)) {
            args->valid[i] = 0;
            continue;
        }
        if (!data.alpha) continue;
        Ray ray;
        ray.o = o;
        ray.d = d;
        SurfaceInteraction si;
        data.curves->interaction(segment, u, ray, t, &si);
        if (passes(*data.alpha, o, d, t, si)) args->valid[i] = 0;
    }
}

// Embree's buffer of count elements of element_size bytes for geometry, filled from data.
void set_buffer(RTCGeometry geometry, RTCBufferType type, RTCFormat format, const void *data,
                size_t element_size, size_t count) {
    void *buffer = rtcSetNewGeometryBuffer(geometry, type, 0, format, element_size, count);
    if (buffer) std::memcpy(buffer, data, element_size * count);
}

// Moves a surface record from an instance's space to render space. The point's rounding error
// is carried along: it is bounded in render space by the image of the instance-space box of its
// rounding scale, whose largest coordinate is |translation| + scale * (row sum of |linear part|).
void transform_interaction(const Transform &render_from_instance, SurfaceInteraction *si) {
    const float scale = rounding_scale(si->p, si->error_scale);
    const Matrix4 &m = render_from_instance.matrix();
    si->error_scale = 0;
    for (int i = 0; i < 3; ++i)
        si->error_scale = std::max(si->error_scale, std::abs(m.m[i][3]) + scale * (std::abs(m.m[i][0]) +
                                                                                   std::abs(m.m[i][1]) +
                                                                                   std::abs(m.m[i][2])));
    si->p = render_from_instance.apply_point(si->p);
    si->n = normalize(render_from_instance.apply_normal(si->n));
    si->dpdu = render_from_instance.apply_vector(si->dpdu);
    si->dpdv = render_from_instance.apply_vector(si->dpdv);
    Vec3f ns = normalize(render_from_instance.apply_normal(si->shading.n));
    si->set_shading(ns, render_from_instance.apply_vector(si->shading.dpdu),
                    render_from_instance.apply_vector(si->shading.dpdv));
}

// Embree's quaternion decomposition of a placement: its factors T R S (core/animated_transform.h).
RTCQuaternionDecomposition quaternion_decomposition(const Matrix4 &m) {
    const AffineFactors f = factor_affine(m);
    RTCQuaternionDecomposition qd;
    rtcInitQuaternionDecomposition(&qd);
    rtcQuaternionDecompositionSetScale(&qd, f.s00, f.s11, f.s22);
    rtcQuaternionDecompositionSetSkew(&qd, f.s01, f.s02, f.s12);
    rtcQuaternionDecompositionSetQuaternion(&qd, f.w, f.x, f.y, f.z);
    rtcQuaternionDecompositionSetTranslation(&qd, f.translation.x, f.translation.y, f.translation.z);
    return qd;
}

} // namespace

GeometryScene::GeometryScene() {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw std::runtime_error("cannot create the Embree device");
    rtcSetDeviceErrorFunction(device_, report_embree_error, nullptr);
    scene_ = new_scene();
}

GeometryScene::~GeometryScene() {
    for (Prototype &p : prototypes_) rtcReleaseScene(p.scene);
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
}

RTCScene GeometryScene::new_scene() const {
    RTCScene scene = rtcNewScene(device_);
    // Robust traversal keeps shared edges watertight, so rays do not slip between triangles.
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    return scene;
}

void GeometryScene::check_device(const char *what) const {
    RTCError error = rtcGetDeviceError(device_);
    if (error != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("Embree failed while ") + what + " (error code " +
                                 std::to_string(int(error)) + ")");
}

void GeometryScene::attach(RTCScene scene, unsigned geometry_id, const ShapeGroup &group,
                           const AlphaMask *alpha) {
    // Only analytic shapes, patches, curves and cut-outs have callbacks.
    void *callback_data = nullptr;
    if (group.analytic || group.patches || group.curves || alpha) {
        callback_data_.push_back(std::make_unique<EmbreeCallbackData>(EmbreeCallbackData{
            group.mesh.get(), group.analytic.get(), group.curves.get(), group.patches.get(), alpha}));
        callback_data = callback_data_.back().get();
    }
    RTCGeometry geometry;
    if (group.mesh) {
        const TriangleMesh &mesh = *group.mesh;
        geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                   mesh.positions().data(), 0, sizeof(Vec3f), mesh.vertex_count());
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                   mesh.indices().data(), 0, 3 * sizeof(int),
                                   mesh.triangle_count());
        triangle_count_ += mesh.triangle_count();
        if (alpha) {
            rtcSetGeometryUserData(geometry, callback_data);
            rtcSetGeometryIntersectFilterFunction(geometry, mesh_alpha_filter);
            rtcSetGeometryOccludedFilterFunction(geometry, mesh_alpha_filter);
        }
    } else if (group.curves) {
        const CurveSet &curves = *group.curves;
        geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE);
        const size_t segments = size_t(curves.segment_count());
        set_buffer(geometry, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT4, curves.embree_vertices().data(),
                   4 * sizeof(float), 4 * segments);
        std::vector<unsigned> first_vertex(segments);
        for (size_t i = 0; i < segments; ++i) first_vertex[i] = unsigned(4 * i);
        set_buffer(geometry, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT, first_vertex.data(), sizeof(unsigned), segments);
        // Flat curves are ray-facing quads along the curve, CurveTessellationRate per segment
        // (Embree's default of 4 shows the corners of tight bends in close-ups).
        rtcSetGeometryTessellationRate(geometry, CurveTessellationRate);
        rtcSetGeometryUserData(geometry, callback_data);
        rtcSetGeometryIntersectFilterFunction(geometry, curve_filter);
        rtcSetGeometryOccludedFilterFunction(geometry, curve_filter);
    } else if (group.patches) {
        geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(geometry, unsigned(group.patches->patch_count()));
        rtcSetGeometryUserData(geometry, callback_data);
        rtcSetGeometryBoundsFunction(geometry, patch_bounds, nullptr);
        rtcSetGeometryIntersectFunction(geometry, patch_intersect);
        rtcSetGeometryOccludedFunction(geometry, patch_occluded);
    } else {
        geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(geometry, 1);
        rtcSetGeometryUserData(geometry, callback_data);
        rtcSetGeometryBoundsFunction(geometry, analytic_bounds, nullptr);
        rtcSetGeometryIntersectFunction(geometry, analytic_intersect);
        rtcSetGeometryOccludedFunction(geometry, analytic_occluded);
    }
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, geometry_id);
    rtcReleaseGeometry(geometry);
    ++shape_count_;
    check_device("adding a shape");
}

void GeometryScene::add(std::shared_ptr<const ShapeGroup> group, PrimitiveAttributes attributes) {
    if (committed_) throw std::logic_error("GeometryScene::add after commit");
    if (!group || group->empty()) return;
    attach(scene_, unsigned(slots_.size()), *group, attributes.alpha.get());
    slots_.push_back({Primitive{std::move(group), std::move(attributes)}, -1});
}

int GeometryScene::add_prototype(
    std::vector<std::pair<std::shared_ptr<const ShapeGroup>, PrimitiveAttributes>> shapes) {
    if (committed_) throw std::logic_error("GeometryScene::add_prototype after commit");
    Prototype prototype{new_scene(), {}};
    for (auto &[group, attributes] : shapes) {
        if (!group || group->empty()) continue;
        attach(prototype.scene, unsigned(prototype.primitives.size()), *group, attributes.alpha.get());
        prototype.primitives.push_back({std::move(group), std::move(attributes)});
    }
    // Instanced scenes must be committed before the scenes that instance them.
    rtcCommitScene(prototype.scene);
    check_device("building an object instance");
    prototypes_.push_back(std::move(prototype));
    return int(prototypes_.size()) - 1;
}

void GeometryScene::add_instance(int prototype, const AnimatedTransform &render_from_instance) {
    if (committed_) throw std::logic_error("GeometryScene::add_instance after commit");
    if (prototype < 0 || size_t(prototype) >= prototypes_.size())
        throw std::out_of_range("GeometryScene::add_instance: no such prototype");
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geometry, prototypes_[prototype].scene);
    const bool moving = render_from_instance.is_animated();
    if (moving) {
        rtcSetGeometryTimeStepCount(geometry, 2);
        const RTCQuaternionDecomposition start = quaternion_decomposition(render_from_instance.start.matrix()),
                                         end = quaternion_decomposition(render_from_instance.end.matrix());
        rtcSetGeometryTransformQuaternion(geometry, 0, &start);
        rtcSetGeometryTransformQuaternion(geometry, 1, &end);
    } else {
        float xfm[12];
        const Matrix4 &m = render_from_instance.start.matrix();
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 3; ++row) xfm[3 * column + row] = m.m[row][column];
        rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene_, geometry, unsigned(slots_.size()));
    rtcReleaseGeometry(geometry);
    check_device("adding an object instance");
    instances_.push_back({prototype, render_from_instance.start, render_from_instance.start.inverse(),
                          moving ? geometry : nullptr});
    moving_instances_ += moving;
    slots_.push_back({Primitive{}, int(instances_.size()) - 1});
}

void GeometryScene::add_moving(std::shared_ptr<const ShapeGroup> group, PrimitiveAttributes attributes,
                               const AnimatedTransform &render_from_object) {
    if (!group || group->empty()) return;
    std::vector<std::pair<std::shared_ptr<const ShapeGroup>, PrimitiveAttributes>> shape;
    shape.emplace_back(std::move(group), std::move(attributes));
    add_instance(add_prototype(std::move(shape)), render_from_object);
}

Transform GeometryScene::transform_at(const Instance &instance, float u) const {
    float xfm[12];
    rtcGetGeometryTransform(instance.moving, u, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
    Matrix4 m;
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 3; ++row) m.m[row][column] = xfm[3 * column + row];
    m.m[3][0] = m.m[3][1] = m.m[3][2] = 0;
    m.m[3][3] = 1;
    // Embree interpolates between invertible placements by invertible factors.
    return Transform(m, *inverse(m));
}

void GeometryScene::commit() {
    if (committed_) throw std::logic_error("GeometryScene::commit called twice");
    rtcCommitScene(scene_);
    check_device("building the acceleration structure");
    first_packed_shape_.reserve(slots_.size() + 1);
    uint64_t shapes = 0;
    for (const Slot &slot : slots_) {
        first_packed_shape_.push_back(shapes);
        shapes += slot.instance < 0 ? 1 : prototypes_[instances_[slot.instance].prototype].primitives.size();
    }
    first_packed_shape_.push_back(shapes);
    packs_hits_ = shapes < SurfaceHit::None;
    committed_ = true;
}

bool GeometryScene::intersect(const Ray &ray, SurfaceInteraction *si) const {
    QueryContext context;
    rtcInitIntersectContext(&context.embree);
    context.t_max = ray.t_max;
    RTCRayHit rayhit;
    rayhit.ray.org_x = ray.o.x;
    rayhit.ray.org_y = ray.o.y;
    rayhit.ray.org_z = ray.o.z;
    rayhit.ray.dir_x = ray.d.x;
    rayhit.ray.dir_y = ray.d.y;
    rayhit.ray.dir_z = ray.d.z;
    rayhit.ray.tnear = 0;
    rayhit.ray.tfar = ray.t_max;
    rayhit.ray.time = moving_instances_ > 0 ? times_.fraction(ray.time) : 0.f;
    rayhit.ray.mask = ~0u;
    rayhit.ray.id = 0;
    rayhit.ray.flags = 0;
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; ++l)
        rayhit.hit.instID[l] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context.embree, &rayhit);
    if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

    SurfaceHit found;
    if (rayhit.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
        found.slot = rayhit.hit.instID[0];
        found.geometry = rayhit.hit.geomID;
    } else {
        found.slot = rayhit.hit.geomID;
    }
    found.primitive = rayhit.hit.primID;
    found.uv = {rayhit.hit.u, rayhit.hit.v};
    fill_interaction(found, ray, rayhit.ray.tfar, si);
    return true;
}

SurfaceInteraction GeometryScene::interaction(const SurfaceHit &hit, Vec3f p, Vec3f wo, float time) const {
    // The point stands for the ray's origin at t = 0: analytic shapes project it onto their
    // surface and curves face their width towards -wo, as they did for the ray. The point itself
    // is kept as intersect() reported it: projected again it may move by an ulp, and whatever is
    // seeded from its bits (the ratio tracking of a shadow ray to it through a heterogeneous
    // medium, HeterogeneousMedium::transmittance) would then draw other random numbers.
    SurfaceInteraction si;
    fill_interaction(hit, Ray{p, -wo, Infinity, time}, 0, &si);
    si.p = p;
    si.wo = wo;
    return si;
}

PackedSurfaceHit GeometryScene::pack(const SurfaceHit &hit) const {
    if (!packs_hits_) throw std::logic_error("GeometryScene::pack: the scene has too many shapes to pack its hits");
    const uint64_t first = first_packed_shape_[hit.slot];
    const uint32_t shape = uint32_t(hit.geometry == SurfaceHit::None ? first : first + hit.geometry);
    return {shape, hit.primitive, PackedSurfaceHit::quantise(hit.uv.x), PackedSurfaceHit::quantise(hit.uv.y)};
}

SurfaceHit GeometryScene::unpack(const PackedSurfaceHit &packed) const {
    // The slot whose shapes include the packed one: the last that starts at or before it.
    const auto after = std::upper_bound(first_packed_shape_.begin(), first_packed_shape_.end(), uint64_t(packed.shape));
    const uint32_t slot = uint32_t(after - first_packed_shape_.begin() - 1);
    SurfaceHit hit;
    hit.slot = slot;
    if (slots_[slot].instance >= 0) hit.geometry = uint32_t(packed.shape - first_packed_shape_[slot]);
    hit.primitive = packed.primitive;
    hit.uv = {PackedSurfaceHit::dequantise(packed.u), PackedSurfaceHit::dequantise(packed.v)};
    return hit;
}

void GeometryScene::fill_interaction(const SurfaceHit &hit, const Ray &ray, float t, SurfaceInteraction *si) const {
    const Primitive *primitive;
    const Instance *instance = nullptr;
    if (hit.geometry != SurfaceHit::None) {
        instance = &instances_[slots_[hit.slot].instance];
        primitive = &prototypes_[instance->prototype].primitives[hit.geometry];
    } else {
        primitive = &slots_[hit.slot].primitive;
    }

    // Shading data are computed where the shape lives and then moved to render space. The ray
    // parameter is the same in both spaces (the maps are affine).
    Ray local = ray;
    std::optional<Transform> moved, moved_back;
    const Transform *render_from_instance = nullptr;
    if (instance) {
        render_from_instance = &instance->render_from_instance;
        const Transform *instance_from_render = &instance->instance_from_render;
        if (instance->moving) {
            render_from_instance = &moved.emplace(transform_at(*instance, times_.fraction(ray.time)));
            instance_from_render = &moved_back.emplace(moved->inverse());
        }
        local.o = instance_from_render->apply_point(ray.o);
        local.d = instance_from_render->apply_vector(ray.d);
    }
    const unsigned index = hit.primitive;
    const ShapeGroup &group = *primitive->group;
    if (group.mesh) {
        // Embree's barycentrics weight vertices 1 and 2; the point is interpolated from the
        // vertices, so it lies on the triangle up to rounding.
        float b[3] = {std::max(0.f, 1 - hit.uv.x - hit.uv.y), hit.uv.x, hit.uv.y};
        group.mesh->interaction(int(index), b, si);
    } else if (group.curves) {
        group.curves->interaction(int(index), hit.uv.x, local, t, si);
    } else if (group.patches) {
        group.patches->interaction(int(index), hit.uv, si);
    } else {
        *si = group.analytic->interaction(local, t);
    }
    // The mask is evaluated where the filter evaluated it, before the move to render space.
    const AlphaMask *alpha = primitive->attributes.alpha.get();
    si->coverage = alpha ? alpha->coverage(TextureEvalContext(*si)) : 1.f;
    if (render_from_instance) transform_interaction(*render_from_instance, si);

    si->wo = -normalize(ray.d);
    si->t = t;
    si->time = ray.time;
    si->face_index = int(index);
    si->material = primitive->attributes.material;
    si->medium_interface = primitive->attributes.medium_interface;
    const auto &lights = primitive->attributes.area_lights;
    si->area_light = index < lights.size() ? lights[index] : nullptr;
    si->hit = hit;
}

bool GeometryScene::occluded(const Ray &ray) const {
    QueryContext context;
    rtcInitIntersectContext(&context.embree);
    RTCRay r;
    r.org_x = ray.o.x;
    r.org_y = ray.o.y;
    r.org_z = ray.o.z;
    r.dir_x = ray.d.x;
    r.dir_y = ray.d.y;
    r.dir_z = ray.d.z;
    r.tnear = 0;
    // Embree's interval is closed; stop one float short of t_max to make it open.
    r.tfar = ray.t_max > 0 ? next_float_down(ray.t_max) : ray.t_max < 0 ? next_float_up(ray.t_max) : ray.t_max;
    context.t_max = r.tfar;
    r.time = moving_instances_ > 0 ? times_.fraction(ray.time) : 0.f;
    r.mask = ~0u;
    r.id = 0;
    r.flags = 0;
    rtcOccluded1(scene_, &context.embree, &r);
    return r.tfar < 0;
}

Bounds3f GeometryScene::bounds() const {
    if (slots_.empty()) return {};
    RTCBounds b;
    rtcGetSceneBounds(scene_, &b);
    Bounds3f result;
    result.lo = {b.lower_x, b.lower_y, b.lower_z};
    result.hi = {b.upper_x, b.upper_y, b.upper_z};
    return result;
}

} // namespace caustica
