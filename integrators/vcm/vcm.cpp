#include "integrators/vcm/vcm.h"

#include "camera/camera.h"
#include "core/error.h"
#include "integrators/common/camera_importance.h"
#include "integrators/common/iteration_renderer.h"
#include "integrators/common/merge_radius.h"
#include "integrators/common/light_path_start.h"
#include "integrators/common/medium_emission.h"
#include "integrators/common/medium_photon.h"
#include "integrators/common/path_vertex.h"
#include "integrators/common/photon_search_parameter.h"
#include "integrators/common/profile_subsurface.h"
#include "integrators/common/splat_scale.h"
#include "integrators/common/path_tracing.h"
#include "integrators/common/subpath_walk.h"
#include "integrators/common/transmittance.h"
#include "integrators/vcm/light_vertex.h"
#include "integrators/vcm/vcm_mis.h"
#include "integrators/common/wavelength_groups.h"
#include "materials/profile_subsurface_material.h"
#include "media/medium_interface.h"
#include "scene/scene.h"
#include "spatial/photon_map.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <deque>
#include <span>
#include <stdexcept>

namespace caustica {

VCM::VCM(Mode mode, const ParameterDictionary &params, const Scene &scene)
    : mode_(mode), max_depth_(params.get_one_int("maxdepth", 5)),
      base_radius_(params.get_one_float("radius", 0)), alpha_(params.get_one_float("alpha", 0.75f)),
      wavelength_groups_(params.get_one_int("wavelengthgroups", 16)),
      photon_search_(read_photon_search(params)) {
    const std::string light_vertices = params.get_one_string("lightvertices", "store");
    const char *name = mode == Mode::VertexConnectionMerging ? "vcm" : "bpm";
    static_assert(StoredLightVertex::MaxPathLength <= Photon::MaxPathLength);
    if (max_depth_ < 0 || max_depth_ > StoredLightVertex::MaxPathLength)
        throw InputError(params.location("maxdepth"),
                         "\"maxdepth\" must lie in [0, " + std::to_string(StoredLightVertex::MaxPathLength) + "]");
    if (base_radius_ < 0 || !std::isfinite(base_radius_))
        throw InputError(params.location("radius"), "\"radius\" must be a positive distance (or 0 for the default)");
    if (!(alpha_ > 0 && alpha_ <= 1))
        throw InputError(params.location("alpha"), "\"alpha\" must lie in (0, 1]");
    if (wavelength_groups_ < 1 || wavelength_groups_ > 64)
        throw InputError(params.location("wavelengthgroups"), "\"wavelengthgroups\" must lie in [1, 64]");
    if (light_vertices != "store" && light_vertices != "retrace")
        throw InputError(params.location("lightvertices"), "\"lightvertices\" must be \"store\" or \"retrace\"");
    retrace_light_paths_ = light_vertices == "retrace";
    require_camera_importance(scene, name);
    // A radius given in the scene is used on surfaces and in media alike.
    base_medium_radius_ = base_radius_;
    if (base_radius_ == 0) {
        base_radius_ = default_merge_radius(scene);
        base_medium_radius_ = default_medium_merge_radius(scene, base_radius_);
    }
    // Advice only: vcm always merges, so that it renders the same image as every other
    // integrator whatever the analysis concludes.
    if (mode == Mode::VertexConnectionMerging && !scene.features.caustic_paths)
        note("vcm: the scene analysis finds no surface that focuses light, so merging adds little "
             "that connections do not already render; bdpt may converge faster here");
}

namespace {

// Light subpaths draw their random numbers from sampler dimensions far above those any camera
// subpath of the same pixel and iteration reaches, so the two are independent.
constexpr int kLightPathDimension = 1 << 12;

// What every pass of one iteration shares.
struct Iteration {
    const Scene &scene;
    int max_depth;
    bool use_vc;
    // Light tracing of the light subpaths' starts on area lights (lens_joins_light_starts).
    bool join_light_starts;
    float radius, medium_radius; // of the disks that merge on surfaces, and the spheres in media
    const WavelengthGroups &groups;
    std::vector<VcmWeights> weights;       // per wavelength group
    std::vector<float> vm_normalization;   // per group: 1 / (pi r^2 N_group), merges on surfaces
    std::vector<float> volume_normalization; // per group: 1 / (4/3 pi r^3 N_group), in media
    // Light tracing: N light paths against one camera sample per pixel of the full frame.
    float light_paths, full_frame_pixels;
    float time; // of every path of the iteration (IterationRenderer::time)
};

// The vertices of a light subpath that its pixel's camera subpath is joined to, with their BSDFs.
using ShadedLightPath = std::span<const LightVertex>;

// The vertices trace_light_path keeps of one light subpath, as traced (their BSDFs in the
// context's memory), each with its compact form for the iteration's store.
struct TracedLightPath {
    std::vector<LightVertex> vertices;
    std::vector<StoredScatteringPoint> points;

    void clear() {
        vertices.clear();
        points.clear();
    }
    void add(const LightVertex &v, const StoredScatteringPoint &point) {
        vertices.push_back(v);
        points.push_back(point);
    }
};

// The photons of one wavelength group, either those on surfaces or those in media: the two are
// never merged with each other (a surface camera vertex gathers over a disk, a medium one over a
// sphere), so each kind has its own map. With "store", the maps keep every light vertex whole
// (StoredLightVertex), and a pixel's camera path finds those of its light path by identity.
using VcmPhotonMap = PhotonMap<Photon>;
using StoredVertexMap = PhotonMap<StoredLightVertex, true>;

// A photon's throughput: over sigma_s at its own point in a medium (merge_in_medium says why).
SampledSpectrum photon_beta(const LightVertex &v, const SampledWavelengths &lambda) {
    if (!v.point.in_medium() || v.medium_start) return v.beta;
    return over_sigma_s(v.beta, *v.point.medium, v.point.p, lambda);
}

// Adds the photons of one light path's vertices to its group's maps (none at the exit of a
// jump, vcm_mis.h, nor at a start in a medium).
void add_photons(std::span<const LightVertex> path, const SampledWavelengths &lambda, VcmPhotonMap &surface_photons,
                 VcmPhotonMap &medium_photons) {
    for (const LightVertex &v : path) {
        if (v.after_jump || v.medium_start) continue;
        const ScatteringPoint &point = v.point;
        const SampledSpectrum beta = photon_beta(v, lambda);
        const Photon photon{{beta[0], beta[1], beta[2], beta[3]},
                            v.d_vcm,
                            v.d_vc,
                            encode_octahedral(point.wo),
                            point.in_medium() ? uint16_t(0) : encode_octahedral_coarse(point.ng),
                            v.path_length,
                            v.secondary_terminated};
        (point.in_medium() ? medium_photons : surface_photons).add(point.p, photon);
    }
}

// Where the vertices of one kept light path are: the identities of its vertices on surfaces and
// of those in media, each consecutive in path order.
struct KeptLightPath {
    uint32_t first_on_surface = 0, on_surface = 0, first_in_medium = 0, in_medium = 0;
};

// Keeps every vertex of one light path in its group's maps ("store").
KeptLightPath keep_light_path(std::span<const LightVertex> path, std::span<const StoredScatteringPoint> points,
                              const SampledWavelengths &lambda, const GeometryScene &geometry,
                              StoredVertexMap &on_surface, StoredVertexMap &in_medium) {
    KeptLightPath kept;
    for (const LightVertex &v : path) ++(v.point.in_medium() ? kept.in_medium : kept.on_surface);
    if (kept.on_surface) kept.first_on_surface = on_surface.take_ids(kept.on_surface);
    if (kept.in_medium) kept.first_in_medium = in_medium.take_ids(kept.in_medium);
    uint32_t next_on_surface = kept.first_on_surface, next_in_medium = kept.first_in_medium;
    for (size_t i = 0; i < path.size(); ++i) {
        const LightVertex &v = path[i];
        const StoredLightVertex stored(v, photon_beta(v, lambda), points[i], geometry);
        if (v.point.in_medium())
            in_medium.add(v.point.p, next_in_medium++, stored);
        else
            on_surface.add(v.point.p, next_on_surface++, stored);
    }
    return kept;
}

// The light path that keep_light_path kept, with each vertex that a camera vertex can be joined
// to within maxdepth (complete_at) shaded again in `memory`, in path order (path lengths grow
// along it; the exit of a jump, which shares its entry's, follows it in the same map), for the
// wavelengths it had.
void rebuild_light_path(const Scene &scene, const KeptLightPath &kept, const StoredVertexMap &on_surface,
                        const StoredVertexMap &in_medium, const SampledWavelengths &lambda, float time, int max_depth,
                        ScratchBuffer &memory, int samples_per_pixel, std::vector<LightVertex> &path) {
    SampledWavelengths terminated = lambda;
    terminated.terminate_secondary();
    uint32_t s = 0, m = 0;
    while (s < kept.on_surface || m < kept.in_medium) {
        const StoredVertexMap::Photon *surface = s < kept.on_surface ? &on_surface.by_id(kept.first_on_surface + s) : nullptr;
        const StoredVertexMap::Photon *medium = m < kept.in_medium ? &in_medium.by_id(kept.first_in_medium + m) : nullptr;
        const bool take_surface = !medium || (surface && surface->record.path_length <= medium->record.path_length);
        const StoredVertexMap::Photon &photon = take_surface ? *surface : *medium;
        ++(take_surface ? s : m);
        const StoredLightVertex &v = photon.record;
        if (v.path_length >= max_depth) continue;
        const SampledWavelengths &vertex_lambda = v.secondary_terminated ? terminated : lambda;
        const ScatteringPoint point =
            SubpathWalk::rebuild(scene, v.point(photon.p, scene.geometry), vertex_lambda, time, memory, samples_per_pixel);
        SampledSpectrum beta = v.beta();
        if (point.in_medium() && !v.medium_start()) beta *= point.medium->properties(point.p, lambda).sigma_s;
        path.push_back(v.with(point, beta));
    }
}

// A ray leaving point towards p_to (with normal n_to, zero if none, and rounding scale
// error_scale_to), as spawn_ray_to makes it.
Ray spawn_ray_between(const ScatteringPoint &point, Vec3f p_to, Vec3f n_to, float error_scale_to) {
    return spawn_ray_to(point.p, point.ng, point.error_scale, p_to, n_to, error_scale_to, point.time);
}

// Contributions made with a terminated wavelength set (a dispersive refraction on either
// subpath) are valid for the hero alone. The camera sample adds everything in the measure of
// its group's full set, so such a contribution keeps its hero value, rescaled by the ratio of the
// two sets' hero densities, and loses the other lanes.
SampledSpectrum in_group_measure(SampledSpectrum L, bool terminated, float hero_scale) {
    if (!terminated) return L;
    SampledSpectrum hero(0.f);
    hero[0] = L[0] * hero_scale;
    return hero;
}

// Emission densities of a light towards a direction, with the delta parts of delta lights set to
// one (pdf_le gives them as zero: a given ray cannot hit them, but a connection can).
struct EmissionDensities {
    float pdf_pos = 0, pdf_dir = 0;
};

EmissionDensities emission_densities(const Light &light, Vec3f p, Vec3f n, Vec3f w) {
    EmissionDensities e;
    light.pdf_le(Ray{p, w, Infinity}, n, &e.pdf_pos, &e.pdf_dir);
    if (light.type() == LightType::DeltaPosition) e.pdf_pos = 1;
    if (light.type() == LightType::DeltaDirection) e.pdf_dir = 1;
    return e;
}

// The density with which next-event estimation picks a light point, given the light's choice
// (pmf) from the receiving vertex: times the position density (pdf_pos) for an area light or a
// point light (whose delta position counts 1), times the directional density at the receiver
// (pdf_li) for an environment light; a distant light's one direction counts 1. The light
// subpath's start (light_start_mis), next-event estimation itself (sample_light) and the camera
// subpath's hits on lights all weigh this strategy with it.
float next_event_density(const Light &light, float pmf, float pdf_pos, float pdf_li) {
    if (light.type() == LightType::Infinite) return pmf * pdf_li;
    if (light.type() == LightType::DeltaDirection) return pmf;
    return pmf * pdf_pos;
}

// ---------------------------------------------------------------------------------------------
// Light subpaths

struct LightPathContext {
    const Iteration &it;
    IterationPixelContext &pixel;
    const VcmWeights &w;
    // Where the light vertices' BSDFs live, while the path's photons and splats are made.
    ScratchBuffer &bsdf_memory;
    // Where the media the path makes at surfaces live, when its vertices are kept through the
    // iteration (their records point to them); null: with the BSDFs.
    ScratchBuffer *kept_media;
    // Light tracing (the t = 1 strategy) is done once per light path: not when it is traced again
    // for its connections.
    bool connect_to_lens;
};

// The density with which the camera generates a point p that light tracing joined to the lens
// point p_lens: its directional density towards p (the same lens point is sampled by both
// strategies, so the lens density cancels), per pixel of the full frame, converted to the area
// measure at p. wi: the unit direction from p to the lens; cos_at_p: |cos| there (1 in a medium).
float camera_area_density(const Iteration &it, Vec3f p, Vec3f p_lens, Vec3f wi, float cos_at_p, float time) {
    float pdf_lens, pdf_dir;
    it.scene.camera->pdf_we(Ray{p_lens, -wi, Infinity, time}, &pdf_lens, &pdf_dir);
    return pdf_dir * it.full_frame_pixels * cos_at_p / length_squared(p_lens - p);
}

// Connects a light vertex to a sampled lens point (light tracing, the t = 1 strategy) and
// splats the weighted contribution where it lands on the film.
void connect_to_camera(const LightPathContext &ctx, const LightVertex &v, const SubpathMis &m,
                       const SampledWavelengths &lambda, Vec2f u_lens) {
    const Scene &scene = ctx.it.scene;
    const ScatteringPoint &point = v.point;
    auto cs = scene.camera->sample_wi(point.p, u_lens, lambda, point.time);
    if (!cs || !(cs->pdf > 0)) return;
    SampledSpectrum f = point.f(cs->wi, TransportMode::Importance);
    if (f.is_black()) return;

    const float camera_pdf_a = camera_area_density(ctx.it, point.p, cs->p_lens, cs->wi, point.cosine(cs->wi), point.time);
    const float bsdf_rev_pdf = v.after_jump ? 1.f : point.pdf(cs->wi, point.wo, TransportMode::Radiance);
    const MergeWeights &merge = v.after_jump ? NoMerge : ctx.w.at(point.in_medium());
    const float w_light = m.connected(camera_pdf_a / ctx.it.light_paths, bsdf_rev_pdf, merge);
    SampledSpectrum L = v.beta * f * cs->We * (1 / (cs->pdf * (1 + w_light)));
    if (L.is_black()) return;
    if (L.has_non_finite()) {
        ++ctx.pixel.non_finite;
        return;
    }
    SampledSpectrum T = transmittance(scene, spawn_ray_between(point, cs->p_lens, Vec3f{}, 0),
                                      point.medium_towards(cs->wi), lambda, ctx.pixel.rays);
    if (T.is_black()) return;
    scene.film->add_splat(cs->p_raster, L * T, lambda);
}

// Joins the light subpath's start on an area light to a sampled lens point and splats it: the
// emission that the camera sees directly, weighed against the camera subpath hitting the light
// (the one other strategy for a path of two vertices, trace_camera_path's first vertex).
void connect_start_to_camera(const LightPathContext &ctx, const LightPathStart &start,
                             const SampledWavelengths &lambda, Vec2f u_lens) {
    const Scene &scene = ctx.it.scene;
    const std::optional<StartSeenByLens> seen = join_start_to_lens(scene, start.origin(), u_lens, lambda, ctx.pixel.rays);
    if (!seen) return;
    const float camera_pdf_a =
        camera_area_density(ctx.it, start.les.ray.o, seen->p_lens, seen->wi, seen->cos_light, start.les.ray.time);
    const float w_light = SubpathMis::light_point(start.pmf * start.les.pdf_pos)
                              .connected(camera_pdf_a / ctx.it.light_paths, 0, NoMerge);
    const SampledSpectrum L = seen->L / (1 + w_light);
    if (L.has_non_finite()) {
        ++ctx.pixel.non_finite;
        return;
    }
    scene.film->add_splat(seen->p_raster, L, lambda);
}

// The light subpath's weights at its start (tech. report eqs. 31-33), set once its first vertex
// is reached. Each strategy's density of the start has its own choice of the light: the light
// subpath's is by power over the lights and emissive media (start.pmf), next-event estimation's
// by importance at the vertex it receives light at (BVHLightSampler), here the first vertex,
// which also sets an environment light's directional density through a portal. A start in an
// emissive medium, which next-event estimation does not sample, has the light subpath's choice
// for both (connect_to_medium_start joins camera vertices to it).
SubpathMis light_start_mis(const Scene &scene, const LightPathStart &start, const ScatteringPoint &first) {
    const Light &light = *start.light;
    const LightLeSample &les = start.les;
    const LightSampleContext receiver{first.p, first.ng, first.ns()};
    float direct_pdf = start.pmf * les.pdf_pos;
    if (light.type() != LightType::Volume) {
        const float pdf_li = light.type() == LightType::Infinite ? light.pdf_li(receiver, -les.ray.d) : 0.f;
        direct_pdf = next_event_density(light, scene.light_sampler->pmf(receiver, &light), les.pdf_pos, pdf_li);
    }
    return SubpathMis::light_start(start.pmf * les.pdf_pos * les.pdf_dir, direct_pdf,
                                   start.at_infinity() ? 1.f : start.cos_origin, !is_delta_light(light.type()));
}

// Traces the light subpath of one pixel with its group's wavelengths, keeping its non-specular
// vertices in `path` and splatting their connections to the lens.
void trace_light_path(const LightPathContext &ctx, SampledWavelengths lambda, TracedLightPath &path) {
    const Iteration &it = ctx.it;
    const Scene &scene = it.scene;
    Sampler &sampler = ctx.pixel.sampler;
    path.clear();
    const std::optional<LightPathStart> start = start_light_path(scene, sampler, lambda, it.time);
    if (!start) return;
    const Light &light = *start->light;
    const LightLeSample &les = start->les;

    // A start in an emissive medium is kept for the camera vertices to join (with connections
    // on), and counts as a scattering event. The camera side's density there is per unit volume,
    // its free flight's included: a factor known once the first vertex is (below), where a
    // surface light has its cosine.
    const bool medium_start = light.type() == LightType::Volume;
    if (it.use_vc && light.type() == LightType::Area) {
        // Drawn whether or not the lens is joined, as for the vertices below.
        const Vec2f u_lens = sampler.get_2d();
        if (ctx.connect_to_lens && it.join_light_starts) connect_start_to_camera(ctx, *start, lambda, u_lens);
    }
    SubpathMis m; // set at the first vertex (light_start_mis)
    int path_length = 0;
    float start_sigma = 0;
    if (medium_start) {
        path_length = 1;
        start_sigma = mean_extinction(*light.medium(), les.ray.o, lambda);
        LightVertex v{les.L / (start->pmf * les.pdf_pos),
                      ScatteringPoint::in_medium_along(Ray{les.ray.o, les.ray.d, Infinity, it.time}, 0, light.medium()),
                      0, 0, 1, lambda.secondary_terminated()};
        v.medium_start = true;
        path.add(v, StoredScatteringPoint{v.point.p, v.point.wo, SurfaceHit{}, false, false, light.medium()});
    }

    // The emitted flux is kept apart from the walk's throughput so that Russian roulette sees
    // the throughput on the path tracer's scale. The path leaves the light into the medium
    // around it (for an area light, the medium outside its shape, the side it emits to).
    SubpathWalk walk(scene, TransportMode::Importance, lambda, sampler, ctx.bsdf_memory, ctx.pixel.rays, true);
    if (ctx.kept_media) walk.keep_media_in(*ctx.kept_media);
    walk.start(les.ray, light.medium(), SampledSpectrum(1.f));
    const int first_length = path_length + 1;
    while (walk.advance() == WalkEvent::Vertex) {
        const ScatteringPoint &point = walk.vertex();
        if (!point.in_medium() && !point.bsdf) {
            walk.pass_through();
            continue;
        }
        ++path_length;
        const bool first = path_length == first_length;
        if (first) m = light_start_mis(scene, *start, point);
        m.arrive(first && start->at_infinity() ? 1.f : walk.distance_squared(), point.cosine(point.wo));
        if (medium_start && first) {
            m.d_vc *= mis(collision_density(start_sigma, std::sqrt(walk.distance_squared())));
        }
        // The vertex, then the exit of a profile solid that its sampled direction enters.
        while (true) {
            if (point.in_medium() || is_non_specular(point.bsdf.flags())) {
                const LightVertex v{start->flux * walk.beta, point, m.d_vcm, m.d_vc, uint16_t(path_length),
                                    lambda.secondary_terminated(), walk.after_jump()};
                path.add(v, walk.stored_vertex());
                if (it.use_vc) {
                    // Drawn whether or not the lens is joined, so that a light path traced
                    // again follows the same random numbers.
                    const Vec2f u_lens = sampler.get_2d();
                    if (ctx.connect_to_lens) connect_to_camera(ctx, v, m, lambda, u_lens);
                }
            }
            // A vertex further along could not be part of a path within max_depth; the exit
            // of a jump through a profile solid still can be, as it shares the entry's length.
            const bool last = path_length >= it.max_depth;
            const bool may_jump = !walk.after_jump() && !point.in_medium() &&
                                  walk.hit().material->has_profile_subsurface();
            if (last && !may_jump) return;
            const std::optional<WalkScatter> s = walk.scatter();
            if (!s) return;
            if (walk.after_jump()) {
                // The exit lobe's direction; the reverse density at the exit is the jump's, 1.
                m.scatter(ctx.w, NoMerge, s->cos_out, s->pdf_fwd, 1.f, false);
                break;
            }
            if (s->profile) {
                m.jump(ctx.w, ctx.w.surface, profile_exit_density(*s->profile, walk.hit(), ctx.pixel.sample_scratch));
                if (!walk.jump(*s->profile)) return;
                continue;
            }
            if (last) return;
            m.scatter(ctx.w, ctx.w.at(point.in_medium()), s->cos_out, s->pdf_fwd, s->pdf_rev, s->specular);
            break;
        }
        // Russian roulette changes the throughput, not the densities: the MIS weights are
        // unaffected and remain a partition of unity.
        if (!walk.russian_roulette(path_length)) break;
    }
}

// ---------------------------------------------------------------------------------------------
// Camera subpaths

struct CameraVertex {
    const ScatteringPoint &point;
    const SubpathMis &m;
    int path_length;
    // The exit of a jump through a profile solid (vcm_mis.h): it can be merged at, and the
    // density of reaching its predecessor from it is the jump's, 1.
    bool after_jump = false;
};

struct CameraPathContext {
    const Iteration &it;
    IterationPixelContext &pixel;
    int group;
    const VcmWeights &w;
    const SampledWavelengths &lambda;    // the camera subpath's (possibly terminated) set
    float hero_scale;                    // see in_group_measure
    // What the camera subpath is completed with: the pixel's light subpath, and the photons of
    // its wavelength group (in the maps of kept light vertices with "store", null otherwise).
    const ShadedLightPath &light_path;
    const VcmPhotonMap &surface_photons, &medium_photons;
    const StoredVertexMap *surface_vertices, *medium_vertices;
};

// Next-event estimation at a camera vertex: a light sampled and connected (the s = 1
// strategy), weighted against the camera path hitting it and against the light subpaths that
// could have produced the vertex (tech. report eq. 44).
SampledSpectrum sample_light(const CameraPathContext &ctx, const CameraVertex &z) {
    const Scene &scene = ctx.it.scene;
    const ScatteringPoint &point = z.point;
    Sampler &sampler = ctx.pixel.sampler;
    const LightSampleContext receiver{point.p, point.ng, point.ns()};
    auto chosen = scene.light_sampler->sample(receiver, sampler.get_1d());
    Vec2f u = sampler.get_2d();
    if (!chosen) return {};
    const Light &light = *chosen->light;
    auto ls = light.sample_li(receiver, u, ctx.lambda);
    if (!ls || ls->L.is_black() || !(ls->pdf > 0)) return {};
    const ScatteringPoint::Connection scattering = point.connect_towards(ls->wi, TransportMode::Radiance);
    if (scattering.f.is_black()) return {};

    const bool at_infinity = ls->is_infinite || light.type() == LightType::DeltaDirection;
    const float dist2 = at_infinity ? 1.f : length_squared(ls->p_light - point.p);
    const float cos_at_light = ls->n_light == Vec3f{} ? 1.f : abs_dot(ls->n_light, ls->wi);
    if (cos_at_light == 0) return {};
    EmissionDensities e = emission_densities(light, ls->p_light, ls->n_light, -ls->wi);
    // The next-event density that the other strategies' weights assume (see light_start_mis),
    // as a solid angle at z.
    float assumed_direct_pdf = next_event_density(light, chosen->pmf, e.pdf_pos, ls->pdf);
    if (!at_infinity) assumed_direct_pdf = assumed_direct_pdf * dist2 / cos_at_light;
    const float emission_pdf = light_path_start_pmf(scene, light) * e.pdf_pos * e.pdf_dir;
    const float w_light = is_delta_light(light.type()) ? 0.f : mis(scattering.pdf_forward / assumed_direct_pdf);
    const float pdf_reverse = z.after_jump ? 1.f : scattering.pdf_reverse;
    const float w_camera = z.m.connected(emission_pdf * point.cosine(ls->wi) / (assumed_direct_pdf * cos_at_light),
                                         pdf_reverse, ctx.w.at(point.in_medium()));
    SampledSpectrum L = scattering.f * ls->L * (1 / (chosen->pmf * ls->pdf * (w_light + 1 + w_camera)));
    if (L.is_black()) return {};
    Ray shadow = ls->is_infinite ? spawn_ray(point.p, point.ng, point.error_scale, ls->wi, point.time)
                                 : spawn_ray_between(point, ls->p_light, ls->n_light, ls->error_scale_light);
    SampledSpectrum T = transmittance(scene, shadow, point.medium_towards(ls->wi), ctx.lambda, ctx.pixel.rays);
    if (T.is_black()) return {};
    return in_group_measure(L * T, ctx.lambda.secondary_terminated(), ctx.hero_scale);
}

// Joins a camera vertex to one light vertex with a shadow ray (tech. report eqs. 40-41).
SampledSpectrum connect(const CameraPathContext &ctx, const CameraVertex &z, const LightVertex &v) {
    const ScatteringPoint &camera = z.point, &light = v.point;
    Vec3f d = light.p - camera.p;
    const float dist2 = length_squared(d);
    if (dist2 == 0) return {};
    d = d / std::sqrt(dist2);
    const ScatteringPoint::Connection at_camera = camera.connect_towards(d, TransportMode::Radiance);
    if (at_camera.f.is_black()) return {};
    const ScatteringPoint::Connection at_light = light.connect_towards(-d, TransportMode::Importance);
    if (at_light.f.is_black()) return {};

    const float camera_dir_pdf_a = at_camera.pdf_forward * light.cosine(d) / dist2;
    const float light_dir_pdf_a = at_light.pdf_forward * camera.cosine(d) / dist2;
    const MergeWeights &light_merge = v.after_jump ? NoMerge : ctx.w.at(light.in_medium());
    const float light_pdf_reverse = v.after_jump ? 1.f : at_light.pdf_reverse;
    const float camera_pdf_reverse = z.after_jump ? 1.f : at_camera.pdf_reverse;
    const SubpathMis light_m{v.d_vcm, v.d_vc};
    const float w_light = light_m.connected(camera_dir_pdf_a, light_pdf_reverse, light_merge);
    const float w_camera = z.m.connected(light_dir_pdf_a, camera_pdf_reverse, ctx.w.at(camera.in_medium()));
    SampledSpectrum L = at_camera.f * at_light.f * v.beta * (1 / (dist2 * (w_light + 1 + w_camera)));
    if (L.is_black()) return {};
    SampledSpectrum T = transmittance(ctx.it.scene, spawn_ray_between(camera, light.p, light.ng, light.error_scale),
                                      camera.medium_towards(d), ctx.lambda, ctx.pixel.rays);
    if (T.is_black()) return {};
    return in_group_measure(L * T, ctx.lambda.secondary_terminated() || v.secondary_terminated, ctx.hero_scale);
}

// Joins a camera vertex to its light path's start in an emissive medium: the s = 1 strategy for
// light that media emit, which next-event estimation does not sample. Weighed as sample_light
// weighs a light point, against the camera subpath reaching the start by a free flight and
// against the light subpaths that could have produced z; the start emits sigma_a Le towards
// every direction, with no cosine.
SampledSpectrum connect_to_medium_start(const CameraPathContext &ctx, const CameraVertex &z, const LightVertex &v) {
    const Scene &scene = ctx.it.scene;
    const ScatteringPoint &camera = z.point, &start = v.point;
    Vec3f d = start.p - camera.p;
    const float dist2 = length_squared(d);
    if (dist2 == 0) return {};
    d = d / std::sqrt(dist2);
    const ScatteringPoint::Connection at_camera = camera.connect_towards(d, TransportMode::Radiance);
    if (at_camera.f.is_black()) return {};
    const Light &emitter = *medium_emitter_of(scene, start.medium);
    const float start_pdf = medium_start_density(scene, emitter, start.p);
    if (!(start_pdf > 0)) return {};
    // Densities of the start per unit volume: the camera's free flight towards it, and the light
    // path's emission of the segment to z (area measure at z) over the start's own density.
    const float camera_pdf = at_camera.pdf_forward *
                             collision_density(mean_extinction(*start.medium, start.p, ctx.lambda), std::sqrt(dist2)) /
                             dist2;
    const float w_light = mis(camera_pdf / start_pdf);
    const float pdf_reverse = z.after_jump ? 1.f : at_camera.pdf_reverse;
    const float w_camera =
        z.m.connected(uniform_sphere_pdf() * camera.cosine(d) / dist2, pdf_reverse, ctx.w.at(camera.in_medium()));
    SampledSpectrum L = at_camera.f * v.beta * (1 / (dist2 * (w_light + 1 + w_camera)));
    if (L.is_black()) return {};
    SampledSpectrum T = transmittance(scene, spawn_ray_between(camera, start.p, Vec3f{}, 0), camera.medium_towards(d),
                                      ctx.lambda, ctx.pixel.rays);
    if (T.is_black()) return {};
    return in_group_measure(L * T, ctx.lambda.secondary_terminated() || v.secondary_terminated, ctx.hero_scale);
}

// Gathers the photons of the camera vertex's wavelength group within the merge radius on its
// surface (tech. report eqs. 42-43), normalised by pi r^2 times the group's light-path count,
// and by the surface's coverage: light paths land on a partly transparent cut-out only that
// often (SurfaceInteraction::coverage).
template <class Map>
SampledSpectrum merge_on_surface(const CameraPathContext &ctx, const CameraVertex &z, const Map &photons) {
    const ScatteringPoint &point = z.point;
    const MergeWeights &here = ctx.w.surface;
    SampledSpectrum sum(0.f);
    photons.for_each_within(point.p, ctx.it.radius, [&](const auto &photon) {
        // The merged vertex belongs to both subpaths.
        if (!photon.merges() || photon.path_length + z.path_length - 1 > ctx.it.max_depth) return;
        if (!same_surface(decode_octahedral_coarse(photon.normal), point.ng)) return;
        const Vec3f wi = photon.towards_previous();
        const float cos_ng = abs_dot(wi, point.ng);
        if (cos_ng == 0) return;
        const BxDFEvaluation e = point.bsdf.evaluate(point.wo, wi, TransportMode::Radiance);
        if (e.f.is_black()) return;
        const float camera_rev_pdf = z.after_jump ? 1.f : e.pdf_reverse;
        const float w_light = SubpathMis{photon.d_vcm, photon.d_vc}.merged(e.pdf_forward, here);
        const float w_camera = z.m.merged(camera_rev_pdf, here);
        // Photon density is flux per unit of geometric area; the shading-normal BSDF turns it
        // into radiance with |wi.ns| / |wi.ng| (the adjoint correction, Veach 1997, 5.3).
        const float shading = abs_dot(wi, point.ns()) / cos_ng;
        sum += in_group_measure(e.f * photon.beta() * (shading / (w_light + 1 + w_camera)),
                                ctx.lambda.secondary_terminated() || photon.secondary_terminated != 0,
                                ctx.hero_scale);
    });
    return sum * (ctx.it.vm_normalization[ctx.group] / point.coverage);
}

// Gathers the photons that the camera vertex's group deposited in media within a sphere of the
// merge radius around a camera vertex in a medium: the volumetric photon map's estimate (Jensen
// and Christensen 1998) as a VCM strategy.
//
// The estimator. Let the full path have its scattering vertex x in the medium, with the light
// subpath's vertex y and the camera subpath's vertex z standing in for it. Its contribution is
// f(path) = F_light(..., x) sigma_s(x) p(w_camera, w_light) F_camera(x, ...), where F_light and
// F_camera are the products of emission, importance, scattering functions and geometry terms
// (with transmittance) on either side, and sigma_s(x) p is the scattering function of a medium
// vertex in the volume measure. Each subpath's throughput reaches its vertex through a
// free-flight sample whose weight is sigma_s T / (distance density) (path_segment.h), so
//   beta_light = F_light sigma_s(y) / p_light(y_0 .. y),   beta_camera = F_camera sigma_s(z) / p_camera(z_0 .. z),
// each over its subpath's density of generating its vertices, the last one per unit volume. A
// light path's y falls within distance r of z with probability p_light(y) V, V = 4/3 pi r^3,
// for each of the N_group light paths: summing over the photons found and dividing by V N_group
// turns p_light(y_0 .. y) into p_light(y_0 .. y_prev) and leaves an unbiased estimate of the
// connection-free integral as r -> 0. The product beta_light beta_camera p holds sigma_s twice
// while f has it once, so one is divided out: the photon's own, sigma_s(y), when it is stored
// (add_photons). The estimate is then sigma_s(z) F_camera times a kernel average of the light
// side's F / p, which is smooth across the sphere. Dividing by sigma_s(z) instead (the same as
// r -> 0) weighs each photon by sigma_s(y) / sigma_s(z): in a heterogeneous medium, photons from
// denser fog around a thin spot then come back as fireflies. No cosine appears: the kernel is
// a sphere, not a disk, and the vertex has no surface. MIS: the merge at a medium vertex has
// eta = V N_group times the density of the connection ending there (vcm_mis.h).
template <class Map>
SampledSpectrum merge_in_medium(const CameraPathContext &ctx, const CameraVertex &z, const Map &photons) {
    const ScatteringPoint &point = z.point;
    const MergeWeights &here = ctx.w.medium;
    const HenyeyGreenstein &phase = point.medium->phase();
    SampledSpectrum sum(0.f);
    photons.for_each_within(point.p, ctx.it.medium_radius, [&](const auto &photon) {
        if (!photon.merges() || photon.path_length + z.path_length - 1 > ctx.it.max_depth) return;
        const Vec3f wi = photon.towards_previous();
        // The phase function is its own sampling density, and symmetric: it is also the density
        // with which the camera (from wo) and the light subpath (from wi) sample each other.
        const float p = phase.p(point.wo, wi);
        const float w_light = SubpathMis{photon.d_vcm, photon.d_vc}.merged(p, here);
        const float w_camera = z.m.merged(p, here);
        sum += in_group_measure(photon.beta() * (p / (w_light + 1 + w_camera)),
                                ctx.lambda.secondary_terminated() || photon.secondary_terminated != 0,
                                ctx.hero_scale);
    });
    return sum * ctx.it.volume_normalization[ctx.group];
}

// Every strategy that completes the camera subpath at its non-specular vertex z, weighted:
// next-event estimation, connections to the pixel's light subpath, merges with the photons
// around z. Before the camera subpath's throughput.
SampledSpectrum complete_at(const CameraPathContext &ctx, const CameraVertex &z) {
    SampledSpectrum L(0.f);
    if (ctx.it.use_vc) {
        L += sample_light(ctx, z);
        for (const LightVertex &v : ctx.light_path) {
            if (v.path_length + z.path_length > ctx.it.max_depth) break;
            L += v.medium_start ? connect_to_medium_start(ctx, z, v) : connect(ctx, z, v);
        }
    }
    if (z.point.in_medium())
        L += ctx.medium_vertices ? merge_in_medium(ctx, z, *ctx.medium_vertices) : merge_in_medium(ctx, z, ctx.medium_photons);
    else
        L += ctx.surface_vertices ? merge_on_surface(ctx, z, *ctx.surface_vertices)
                                  : merge_on_surface(ctx, z, ctx.surface_photons);
    return L;
}

// The MIS weight of the emission that a camera subpath, in state m after its last vertex,
// collected at a collision in an emissive medium: the collision is reached as a vertex whose
// density per unit volume includes the free flight's (medium_emission.h), and a light subpath
// starts there with the emitter's start density, emitting uniformly over the sphere (eq. 44).
float medium_emission_weight(const Scene &scene, const VcmWeights &w, SubpathMis m, const SubpathWalk &walk) {
    const Light *emitter = medium_emitter_of(scene, walk.medium());
    if (!emitter) return 1;
    const Vec3f p = walk.emission_point();
    const float dist2 = length_squared(p - walk.origin());
    m.arrive(dist2, collision_density(mean_extinction(*walk.medium(), p, walk.lambda()), std::sqrt(dist2)));
    const float start_pdf = medium_start_density(scene, *emitter, p);
    return 1 / (1 + m.hit_emitter(w, start_pdf, start_pdf * uniform_sphere_pdf()));
}

// Radiance of the camera subpath of one pixel (tech. report section 5), in the measure of its
// group's full wavelength set.
SampledSpectrum trace_camera_path(const Iteration &it, IterationPixelContext &pixel, int group,
                                  const CameraRay &camera_ray, SampledWavelengths &lambda,
                                  const ShadedLightPath &light_path, const VcmPhotonMap &surface_photons,
                                  const VcmPhotonMap &medium_photons, const StoredVertexMap *surface_vertices,
                                  const StoredVertexMap *medium_vertices) {
    const Scene &scene = it.scene;
    Sampler &sampler = pixel.sampler;
    const VcmWeights &w = it.weights[group];
    SampledWavelengths terminated = lambda;
    terminated.terminate_secondary();
    const float hero_scale = lambda.pdf()[0] / terminated.pdf()[0];
    const CameraPathContext ctx{it,         pixel,           group,          w,
                                lambda,     hero_scale,      light_path,     surface_photons,
                                medium_photons, surface_vertices, medium_vertices};

    float pdf_lens, pdf_dir;
    scene.camera->pdf_we(camera_ray.ray, &pdf_lens, &pdf_dir);
    SubpathMis m = SubpathMis::camera_start(it.light_paths, pdf_dir * it.full_frame_pixels);

    SubpathWalk walk(scene, TransportMode::Radiance, lambda, sampler, pixel.sample_scratch, pixel.rays, true);
    walk.allow_reradiation();
    walk.start(camera_ray.ray, scene.camera_medium, camera_ray.weight, camera_ray.differential);
    SampledSpectrum L(0.f);
    LightSampleContext previous{camera_ray.ray.o, Vec3f{}, Vec3f{}};
    int path_length = 0;
    auto add = [&](const SampledSpectrum &contribution) {
        L += walk.beta * in_group_measure(contribution, lambda.secondary_terminated(), ctx.hero_scale);
    };
    while (true) {
        const WalkEvent event = walk.advance();
        // Emissive media along the segment: the camera subpath's collision estimate, weighed
        // against the light subpaths that start at the collision (with the lens point as the
        // previous vertex, as for a light that the camera sees directly, it is the only strategy).
        if (path_length < it.max_depth && !walk.emitted().is_black())
            L += in_group_measure(walk.emitted(), lambda.secondary_terminated(), ctx.hero_scale) *
                 (path_length == 0 ? 1.f : medium_emission_weight(scene, w, m, walk));
        if (event == WalkEvent::Ended) break;
        if (event == WalkEvent::Escaped) {
            // Environment light: the camera path's own strategy, against next-event estimation
            // of the same direction and the light subpaths that start from it.
            for (const Light *light : scene.infinite_lights) {
                SampledSpectrum Le = light->Le(walk.ray(), lambda);
                if (Le.is_black()) continue;
                if (path_length == 0) {
                    add(Le);
                    continue;
                }
                const Vec3f wi = normalize(walk.ray().d);
                EmissionDensities e = emission_densities(*light, walk.origin(), Vec3f{}, -wi);
                const float direct_pdf =
                    next_event_density(*light, scene.light_sampler->pmf(previous, light), 0, light->pdf_li(previous, wi));
                const float emission_pdf = light_path_start_pmf(scene, *light) * e.pdf_pos * e.pdf_dir;
                const float w_camera = m.hit_emitter(w, direct_pdf, emission_pdf);
                add(Le / (1 + w_camera));
            }
            break;
        }
        const ScatteringPoint &point = walk.vertex();
        ++path_length;
        m.arrive(walk.distance_squared(), point.cosine(point.wo));

        if (!point.in_medium() && walk.hit().area_light) {
            const SurfaceInteraction &si = walk.hit();
            SampledSpectrum Le = si.area_light->L(si.p, si.n, si.uv, si.wo, lambda);
            if (path_length == 1 && !it.join_light_starts) {
                // Seen directly from the lens, with no light tracing of the starts to weigh
                // against: the one strategy for a path of two vertices.
                add(Le);
            } else if (!Le.is_black()) {
                // Seen directly from the lens, the point is weighed against light tracing of the
                // light subpaths' starts (connect_start_to_camera), which chose it by their own
                // choice of a light; further along, against next-event estimation from the
                // previous vertex.
                EmissionDensities e = emission_densities(*si.area_light, si.p, si.n, si.wo);
                const float start_pmf = light_path_start_pmf(scene, *si.area_light);
                const float choice = path_length == 1 ? start_pmf : scene.light_sampler->pmf(previous, si.area_light);
                const float direct_pdf = next_event_density(*si.area_light, choice, e.pdf_pos, 0);
                const float w_camera = m.hit_emitter(w, direct_pdf, start_pmf * e.pdf_pos * e.pdf_dir);
                add(Le / (1 + w_camera));
            }
        }
        // Scattering on from vertex max_depth can still reach an emitter (a path of max_depth
        // scattering events, as the path tracer counts them); the next vertex ends the path.
        if ((!point.in_medium() && !point.bsdf) || path_length > it.max_depth) break;

        // The vertex, then the exit of a profile solid that its sampled direction enters.
        while (true) {
            if (point.in_medium() || is_non_specular(point.bsdf.flags()))
                L += walk.beta * complete_at(ctx, CameraVertex{point, m, path_length, walk.after_jump()});
            // Light that a fluorescent surface re-radiates: no light subpath carries it, so the
            // path tracer's strategies alone gather it (path_tracing.h).
            L += in_group_measure(reradiated_light_at(scene, walk, sampler, pixel.rays), lambda.secondary_terminated(),
                                  ctx.hero_scale);
            const std::optional<WalkScatter> s = walk.scatter();
            if (!s) return L;
            if (walk.reradiated())
                return L + in_group_measure(reradiated_beyond(scene, walk, LightSampleContext{point.p, point.ng, point.ns()},
                                                              s->pdf_fwd, path_length, it.max_depth, sampler, pixel.rays),
                                            lambda.secondary_terminated(), ctx.hero_scale);
            if (walk.after_jump()) {
                // The exit lobe's direction; the reverse density at the exit is the jump's, 1.
                m.scatter(w, w.surface, s->cos_out, s->pdf_fwd, 1.f, false);
            } else if (s->profile) {
                m.jump(w, NoMerge, profile_exit_density(*s->profile, walk.hit(), pixel.sample_scratch));
                if (!walk.jump(*s->profile)) return L;
                continue;
            } else {
                m.scatter(w, w.at(point.in_medium()), s->cos_out, s->pdf_fwd, s->pdf_rev, s->specular);
            }
            previous = point.in_medium() ? LightSampleContext{point.p, Vec3f{}, Vec3f{}}
                                         : LightSampleContext{point.p, point.ng, point.ns()};
            break;
        }
        // Russian roulette on beta * eta^2, as in the path tracer (pbrt-v4 14.1).
        if (!walk.russian_roulette(path_length)) break;
    }
    return L;
}

} // namespace

void VCM::render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                 const ProgressCallback &progress) {
    IterationRenderer renderer(scene, budget, stats, progress);
    const size_t pixel_count = renderer.pixel_count();
    const Vec2i full = scene.film->resolution();
    const bool use_vc = mode_ == Mode::VertexConnectionMerging;
    WavelengthGroups groups(wavelength_groups_, scene.overrides.seed);

    // Light vertices are kept through the iteration only for vcm's connections, and not when
    // they are traced again instead ("lightvertices" "retrace"): whole, in maps of their own
    // (which merging reads as it reads photons), without their BSDFs. Otherwise only their
    // photons are.
    // Kept vertices name their surfaces by packed hits: a scene with too many shapes for them
    // (GeometryScene::packs_hits) has its light paths traced again.
    const bool keep_light_vertices = use_vc && !retrace_light_paths_ && scene.geometry.packs_hits();
    if (use_vc && !retrace_light_paths_ && !keep_light_vertices)
        note("vcm: the scene places 2^32 - 1 shapes or more, more than kept light vertices can name; "
             "its light paths are traced again instead (\"lightvertices\" \"retrace\")");
    // Per wavelength group, the one kind or the other.
    std::deque<VcmPhotonMap> surface_photons, medium_photons;
    std::deque<StoredVertexMap> surface_vertices, medium_vertices;
    auto photon_blocks = std::make_shared<VcmPhotonMap::Pool>();
    auto vertex_blocks = std::make_shared<StoredVertexMap::Pool>();
    for (int g = 0; g < wavelength_groups_; ++g) {
        surface_photons.emplace_back(photon_search_, photon_blocks);
        medium_photons.emplace_back(photon_search_, photon_blocks);
        surface_vertices.emplace_back(photon_search_, vertex_blocks);
        medium_vertices.emplace_back(photon_search_, vertex_blocks);
    }
    std::vector<KeptLightPath> kept_paths(keep_light_vertices ? pixel_count : 0);
    // A path as traced or rebuilt, per thread.
    tbb::enumerable_thread_specific<TracedLightPath> light_path_in_use;
    // The media that kept light vertices lie in, when a surface made them (a random walk's
    // interior under a textured colour): the vertices' records point to them.
    tbb::enumerable_thread_specific<ScratchBuffer> kept_media;
    // One light path per pixel per completed iteration: a resumed render counts those of the
    // iterations it continues from.
    light_paths_traced_ = stats.pixel_samples;
    std::atomic<uint64_t> traced{light_paths_traced_};

    renderer.run([&](int iteration) {
        groups.start_iteration(scene, iteration, pixel_count, pixel_count);
        const float shrink = std::pow(float(iteration + 1), (alpha_ - 1) / 2);
        const float radius = base_radius_ * shrink, medium_radius = base_medium_radius_ * shrink;
        Iteration it{scene, max_depth_, use_vc, use_vc && lens_joins_light_starts(scene), radius, medium_radius, groups, {}, {}, {},
                     float(pixel_count), float(full.x) * float(full.y), renderer.time(iteration)};
        for (int g = 0; g < groups.count(); ++g) {
            const float light_path_count = float(std::max<size_t>(groups.light_path_count(g), 1));
            // The kernels' acceptance regions times the light paths gathered (vcm_mis.h).
            const float eta_vcm = Pi * radius * radius * light_path_count;
            const float eta_volume = 4.f / 3.f * Pi * medium_radius * medium_radius * medium_radius * light_path_count;
            it.weights.push_back(VcmWeights::make(use_vc, eta_vcm, eta_volume));
            it.vm_normalization.push_back(1 / eta_vcm);
            it.volume_normalization.push_back(1 / eta_volume);
        }

        // Pass 1: one light subpath per pixel, connected to the lens, its vertices kept (with
        // "store") or made photons.
        for (ScratchBuffer &media : kept_media) media.reset();
        for (int g = 0; g < groups.count(); ++g) {
            surface_photons[g].clear();
            medium_photons[g].clear();
            surface_vertices[g].clear();
            medium_vertices[g].clear();
        }
        // A group's pixels together, as the camera pass visits them (see there), so that each
        // thread stores the light vertices in the order they are read again.
        bool completed = renderer.for_each_pixel_in_order(iteration, kLightPathDimension, groups.pixels_by_group(),
                                                          [&](Vec2i, size_t index, IterationPixelContext &pixel) {
            const int g = groups.group_of_pixel(index);
            TracedLightPath &path = light_path_in_use.local();
            trace_light_path(LightPathContext{it, pixel, it.weights[g], pixel.sample_scratch,
                                              keep_light_vertices ? &kept_media.local() : nullptr, true},
                             groups.wavelengths(g), path);
            if (keep_light_vertices)
                kept_paths[index] = keep_light_path(path.vertices, path.points, groups.wavelengths(g),
                                                    scene.geometry, surface_vertices[g], medium_vertices[g]);
            else
                add_photons(path.vertices, groups.wavelengths(g), surface_photons[g], medium_photons[g]);
            ++traced;
        });
        light_paths_traced_ = traced;
        if (!completed) return false;

        // The groups' maps are independent, so they are indexed in parallel (one after another,
        // they kept the second thread idle for a tenth of the render).
        tbb::parallel_for(0, groups.count(), [&](int g) {
            surface_photons[g].build(radius);
            medium_photons[g].build(medium_radius);
            surface_vertices[g].build(radius);
            medium_vertices[g].build(medium_radius);
        });
        uint64_t stored = 0;
        for (int g = 0; g < groups.count(); ++g)
            stored += surface_photons[g].size() + medium_photons[g].size() + surface_vertices[g].size() +
                      medium_vertices[g].size();
        stats.stored_light_vertices = std::max<uint64_t>(stats.stored_light_vertices, stored);

        // Pass 2: one camera subpath per pixel, a wavelength group's pixels together, so that the
        // merges of consecutive pixels search the same photon map while it is in cache.
        Film &film = *scene.film;
        return renderer.for_each_pixel_in_order(iteration, 0, groups.pixels_by_group(),
                                                [&](Vec2i pixel, size_t index, IterationPixelContext &ctx) {
            const int g = groups.group_of_pixel(index);
            TracedLightPath &path = light_path_in_use.local();
            path.clear();
            if (keep_light_vertices) {
                // The pixel's light path of pass 1, shaded again in this sample's memory.
                rebuild_light_path(scene, kept_paths[index], surface_vertices[g], medium_vertices[g],
                                   groups.wavelengths(g), it.time, it.max_depth, ctx.sample_scratch,
                                   ctx.sampler.samples_per_pixel(), path.vertices);
            } else if (use_vc) {
                // The pixel's light path of pass 1 again, from its own random numbers (its BSDFs
                // in this sample's memory), then back to the camera path's.
                ctx.sampler.start_pixel_sample(pixel, iteration, kLightPathDimension);
                trace_light_path(LightPathContext{it, ctx, it.weights[g], ctx.sample_scratch, nullptr, false},
                                 groups.wavelengths(g), path);
                ctx.sampler.start_pixel_sample(pixel, iteration, 0);
            }
            const ShadedLightPath light_path = path.vertices;
            SampledWavelengths lambda = groups.wavelengths(g);
            const SampledWavelengths group_lambda = lambda;
            ctx.sampler.get_1d(); // dimension 0 is the hero wavelength, fixed by the group here
            CameraSample cs = get_camera_sample(ctx.sampler, pixel, film.filter());
            cs.time = it.time;
            SampledSpectrum L(0.f);
            if (auto camera_ray = scene.generate_camera_ray(cs, lambda, ctx.sampler.samples_per_pixel())) {
                L = trace_camera_path(it, ctx, g, *camera_ray, lambda, light_path, surface_photons[g],
                                      medium_photons[g], keep_light_vertices ? &surface_vertices[g] : nullptr,
                                      keep_light_vertices ? &medium_vertices[g] : nullptr);
                if (L.has_non_finite()) {
                    ++ctx.non_finite;
                    L = SampledSpectrum(0.f);
                }
            }
            film.add_sample(pixel, L, group_lambda, cs.filter_weight);
        });
    });
    // The splats of a distributed render are reduced into one film: normalise by every rank's
    // light paths.
    light_paths_traced_ = uint64_t(budget.sharing().sum(int64_t(light_paths_traced_)));
}

// One light path per pixel per iteration, counted as traced (an interrupted iteration included).
double VCM::splat_scale(const Scene &scene, const RenderStats &stats) const {
    (void)stats;
    return light_path_splat_scale(scene, light_paths_traced_);
}

} // namespace caustica
