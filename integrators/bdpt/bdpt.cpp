#include "integrators/bdpt/bdpt.h"

#include "camera/camera.h"
#include "core/error.h"
#include "integrators/bdpt/mis_weight.h"
#include "integrators/common/camera_importance.h"
#include "integrators/common/light_path_start.h"
#include "integrators/common/medium_emission.h"
#include "integrators/common/path_tracing.h"
#include "integrators/common/path_vertex.h"
#include "integrators/common/profile_subsurface.h"
#include "integrators/common/splat_scale.h"
#include "integrators/common/subpath_walk.h"
#include "integrators/common/tile_renderer.h"
#include "integrators/common/transmittance.h"
#include "materials/profile_subsurface_material.h"
#include "media/medium_interface.h"
#include "scene/scene.h"

#include <new>
#include <type_traits>

namespace caustica {

BDPT::BDPT(const ParameterDictionary &params, const Scene &scene)
    : max_depth_(params.get_one_int("maxdepth", 5)), regularize_(params.get_one_bool("regularize", false)) {
    if (max_depth_ < 0)
        throw InputError(params.location("maxdepth"), "\"maxdepth\" must not be negative");
    require_camera_importance(scene, "bidirectional path tracing (bdpt)");
}

namespace {

// Begins the lifetime of a default vertex in unconstructed storage (see new_vertices).
PathVertex &start_vertex(PathVertex &storage) { return *new (&storage) PathVertex(); }

struct SubpathContext {
    const Scene &scene;
    SampledWavelengths &lambda;
    PixelSampleContext &sample;
    float time; // of the camera ray, which the light subpath shares
    bool regularize; // "regularize": each subpath widens the lobes it meets after a non-specular bounce
};

// The MIS weight of the emission that the camera subpath path[0, count) collected at a collision
// in a medium (s = 0), against the light subpaths that start at that point: the collision is the
// subpath's next vertex, a medium emitter reached with solid-angle density pdf_fwd from
// path[count - 1] (held in path[count] while the weight is computed).
float medium_emission_weight(const SubpathContext &ctx, const SubpathWalk &walk, PathVertex *path, int count,
                             float pdf_fwd) {
    const Light *emitter = medium_emitter_of(ctx.scene, walk.medium());
    if (!emitter) return 1;
    PathVertex &collision = start_vertex(path[count]);
    collision.type = PathVertexType::Light;
    collision.light = emitter;
    collision.medium = walk.medium();
    collision.si.p = walk.emission_point();
    collision.jumps = path[count - 1].jumps;
    collision.collision_sigma = mean_extinction(*walk.medium(), collision.si.p, walk.lambda());
    collision.pdf_fwd = path[count - 1].convert_density(pdf_fwd, collision);
    return bdpt_mis_weight(ctx.scene, nullptr, path, collision, 0, count + 1);
}

// Extends the subpath whose last vertex is path[count - 1] by following ray, whose direction
// was sampled there with solid-angle density pdf_fwd, until max_count vertices exist; returns the
// new count. beta is the throughput carried by the ray, medium the one it starts in. Camera
// subpaths (Radiance) that leave the scene end in a vertex at infinity when there are environment
// lights to receive. Camera subpaths add to *camera_only what they collect along the way: the
// emission of emissive media they meet, MIS-weighted against the light subpaths that start
// there, while fewer than max_count - 2 scattering vertices lie behind (the path tracer's
// maxdepth rule: the emission counts as a scattering event), and the light that fluorescent
// surfaces re-radiate (path_tracing.h), after which the subpath ends.
int random_walk(const SubpathContext &ctx, const Ray &ray, const SampledSpectrum &beta, float pdf_fwd,
                TransportMode mode, const Medium *medium, PathVertex *path, int count, int max_count,
                SampledSpectrum *camera_only = nullptr,
                const std::optional<RayDifferential> &differential = std::nullopt) {
    const Scene &scene = ctx.scene;
    SubpathWalk walk(scene, mode, ctx.lambda, ctx.sample.sampler, ctx.sample.scratch, ctx.sample.rays, true);
    if (camera_only) walk.allow_reradiation();
    if (ctx.regularize) walk.regularize_after_non_specular_bounces();
    walk.start(ray, medium, beta, differential);
    // Vertices that count towards max_count: a jump's exit shares its entry's (see after_jump).
    auto counted = [&] { return count - path[count - 1].jumps; };
    while (counted() < max_count) {
        const WalkEvent event = walk.advance();
        if (camera_only && counted() + 1 < max_count && !walk.emitted().is_black())
            *camera_only += walk.emitted() * medium_emission_weight(ctx, walk, path, count, pdf_fwd);
        if (event == WalkEvent::Ended) break;
        PathVertex &prev = path[count - 1];
        if (event == WalkEvent::Escaped) {
            if (mode == TransportMode::Radiance && !scene.infinite_lights.empty()) {
                PathVertex &v = start_vertex(path[count++]);
                v.type = PathVertexType::Light;
                v.jumps = prev.jumps;
                v.at_infinity = true;
                v.si.p = walk.ray().o + normalize(walk.ray().d);
                v.beta = walk.beta;
                v.pdf_fwd = pdf_fwd; // solid angle, the measure of a vertex at infinity
            }
            break;
        }
        const ScatteringPoint &point = walk.vertex();
        if (!point.in_medium() && !point.bsdf) {
            walk.pass_through();
            continue;
        }
        PathVertex &v = start_vertex(path[count++]);
        v.jumps = prev.jumps;
        v.medium = walk.medium();
        v.beta = walk.beta;
        if (point.in_medium()) {
            v.type = PathVertexType::Medium;
            v.si.p = point.p;
            v.si.wo = point.wo;
        } else {
            v.type = PathVertexType::Surface;
            v.si = walk.hit();
            v.bsdf = point.bsdf;
        }
        v.pdf_fwd = prev.convert_density(pdf_fwd, v);
        // The last counted vertex still enters a profile solid if its sample says so: the exit
        // is part of the same scattering event.
        const bool last = counted() == max_count;
        if (last && (point.in_medium() || !walk.hit().material->has_profile_subsurface())) break;
        if (camera_only && !last) *camera_only += reradiated_light_at(scene, walk, ctx.sample.sampler, ctx.sample.rays);
        const std::optional<WalkScatter> s = walk.scatter();
        if (!s) break;
        if (walk.reradiated()) {
            *camera_only += reradiated_beyond(scene, walk, LightSampleContext{v.si.p, v.si.n, v.si.shading.n}, s->pdf_fwd,
                                              counted() - 1, max_count - 2, ctx.sample.sampler, ctx.sample.rays);
            break;
        }
        if (s->profile) {
            // The predecessor's reverse density becomes the exit lobe's here (a walk from the
            // other end would leave the solid at this point); the reverse jump's is 1.
            const float exit_pdf_here = profile_exit_density(*s->profile, v.si, ctx.sample.scratch);
            path[count - 2].pdf_rev = v.convert_density(exit_pdf_here, path[count - 2]);
            v.pdf_rev = 1;
            const uint16_t jumps = v.jumps + 1;
            if (!walk.jump(*s->profile)) break;
            PathVertex &exit = start_vertex(path[count++]);
            exit.type = PathVertexType::Surface;
            exit.after_jump = true;
            exit.jumps = jumps;
            exit.si = walk.hit();
            exit.bsdf = walk.vertex().bsdf;
            exit.medium = walk.medium();
            exit.beta = walk.beta;
            exit.pdf_fwd = 1; // the jump
            if (last) break;
            // The exit lobe's direction; the entry's reverse density stays the jump's.
            const std::optional<WalkScatter> next = walk.scatter();
            if (!next || walk.beta.is_black()) break;
            pdf_fwd = next->pdf_fwd;
            continue;
        }
        if (last) break;
        pdf_fwd = s->pdf_fwd;
        float pdf_rev = s->pdf_rev;
        if (s->specular) {
            v.delta = true;
            pdf_rev = pdf_fwd = 0;
        }
        path[count - 2].pdf_rev = v.convert_density(pdf_rev, path[count - 2]);
        if (walk.beta.is_black()) break;
    }
    return count;
}

// The camera subpath: the lens vertex, then up to max_count - 1 scattering vertices; the
// emission of media and the re-radiated light met along it are added to *camera_only.
int camera_subpath(const SubpathContext &ctx, const CameraRay &camera_ray, PathVertex *path,
                   int max_count, SampledSpectrum *camera_only) {
    PathVertex &lens = start_vertex(path[0]);
    lens.type = PathVertexType::Camera;
    lens.si.p = camera_ray.ray.o;
    lens.si.time = camera_ray.ray.time;
    lens.medium = ctx.scene.camera_medium;
    lens.beta = camera_ray.weight;
    float pdf_pos, pdf_dir;
    ctx.scene.camera->pdf_we(camera_ray.ray, &pdf_pos, &pdf_dir);
    return random_walk(ctx, camera_ray.ray, camera_ray.weight, pdf_dir, TransportMode::Radiance, lens.medium,
                       path, 1, max_count, camera_only, camera_ray.differential);
}

// The light subpath: a light or an emissive medium chosen by power, an emitted ray, then
// scattering vertices.
int light_subpath(const SubpathContext &ctx, PathVertex *path, int max_count) {
    const Scene &scene = ctx.scene;
    const std::optional<LightPathStart> start = start_light_path(scene, ctx.sample.sampler, ctx.lambda, ctx.time);
    if (!start || max_count == 0) return 0;
    const Light &light = *start->light;
    const LightLeSample *les = &start->les;

    PathVertex &origin = start_vertex(path[0]);
    origin.type = PathVertexType::Light;
    origin.light = &light;
    origin.at_infinity = light.type() == LightType::Infinite || light.type() == LightType::DeltaDirection;
    origin.si.p = les->ray.o;
    origin.si.n = origin.si.shading.n = les->n;
    origin.si.error_scale = les->error_scale;
    origin.si.uv = les->uv;
    // Light paths start in the light's medium (for an area light, that on its shape's outside).
    origin.medium = light.medium();
    origin.beta = les->L / (start->pmf * les->pdf_pos);
    origin.pdf_fwd = start->pmf * les->pdf_pos;
    if (origin.is_medium_emitter()) origin.collision_sigma = mean_extinction(*origin.medium, origin.p(), ctx.lambda);

    const Vec3f d = normalize(les->ray.d);
    int count = random_walk(ctx, les->ray, origin.beta * (start->cos_origin / les->pdf_dir), les->pdf_dir,
                            TransportMode::Importance, origin.medium, path, 1, max_count);
    if (origin.at_infinity) {
        // Rays from infinity start on a disk across the scene: the first vertex's area density
        // is the disk's times the cosine there (no distance falloff), and the origin's density is
        // that of its direction (pbrt-v4 section 16.3.3).
        if (count > 1) {
            path[1].pdf_fwd = les->pdf_pos;
            if (path[1].on_surface()) path[1].pdf_fwd *= abs_dot(d, path[1].ng());
        }
        PathVertex along_ray;
        along_ray.si.p = origin.p() + d;
        origin.pdf_fwd = origin.pdf_light_origin(scene, along_ray);
    }
    if (count > 1) origin.next_event_ratio_ahead = origin.next_event_ratio(scene, path[1]);
    return count;
}

// The fraction of light that travels between two vertices: zero when a surface is in the way,
// else the transmittance of the media along the segment.
SampledSpectrum connection_transmittance(const SubpathContext &ctx, const PathVertex &a, const PathVertex &b) {
    return transmittance(ctx.scene, spawn_ray_to(a.p(), a.ng(), a.si.error_scale, b.p(), b.ng(), b.si.error_scale, ctx.time),
                         a.medium_towards(b.p() - a.p()), ctx.lambda, ctx.sample.rays);
}

struct Connection {
    SampledSpectrum L{0.f};
    bool splat = false;
    Vec2f p_raster;
};

// The contribution of strategy (s, t), MIS-weighted.
Connection connect(const SubpathContext &ctx, PathVertex *light_vertices, PathVertex *camera_vertices,
                   int s, int t) {
    const Scene &scene = ctx.scene;
    Sampler &sampler = ctx.sample.sampler;
    uint64_t &rays = ctx.sample.rays;
    Connection c;
    // A camera subpath that escaped is only ever an emitter (s = 0).
    if (t > 1 && s != 0 && camera_vertices[t - 1].type == PathVertexType::Light) return c;

    PathVertex sampled;
    SampledSpectrum L(0.f);
    if (s == 0) {
        // An exit from a profile solid was not reached along a ray: its emission, if any, is
        // the subpath's hit on the entry's surface, not counted again here (as in the path
        // tracer).
        const PathVertex &pt = camera_vertices[t - 1];
        if (pt.is_light() && !pt.after_jump) L = pt.Le(scene, camera_vertices[t - 2], ctx.lambda) * pt.beta;
    } else if (t == 1) {
        // Join the light subpath's end to a sampled lens point; the result lands on the film
        // where that direction images.
        const PathVertex &qs = light_vertices[s - 1];
        if (!qs.connectible() || qs.at_infinity) return c;
        const Vec2f u_lens = sampler.get_2d();
        sampled = PathVertex{};
        sampled.type = PathVertexType::Camera;
        sampled.si.time = ctx.time;
        sampled.medium = scene.camera_medium;
        if (qs.type == PathVertexType::Light) {
            // The light point itself (s = 1), joined as light tracing joins it.
            const LightPoint origin{qs.light, qs.p(), qs.ng(), qs.si.uv, qs.si.error_scale, ctx.time, qs.pdf_fwd};
            const std::optional<StartSeenByLens> seen = join_start_to_lens(scene, origin, u_lens, ctx.lambda, rays);
            if (!seen) return c;
            sampled.si.p = seen->p_lens;
            c.p_raster = seen->p_raster;
            L = seen->L;
        } else {
            const auto cs = scene.camera->sample_wi(qs.p(), u_lens, ctx.lambda, ctx.time);
            if (!cs || !(cs->pdf > 0)) return c;
            sampled.si.p = cs->p_lens;
            c.p_raster = cs->p_raster;
            L = qs.beta * qs.f(cs->wi, TransportMode::Importance) * qs.cosine(cs->wi, TransportMode::Importance) *
                (cs->We / cs->pdf);
            if (L.is_black()) return c;
            L *= connection_transmittance(ctx, sampled, qs);
        }
        c.splat = true;
    } else if (s == 1) {
        // Sample a point on a light from the camera subpath's end (next-event estimation).
        const PathVertex &pt = camera_vertices[t - 1];
        if (!pt.connectible()) return c;
        const LightSampleContext lctx{pt.p(), pt.ng(), pt.ns()};
        auto chosen = scene.light_sampler->sample(lctx, sampler.get_1d());
        Vec2f u = sampler.get_2d();
        if (!chosen) return c;
        auto ls = chosen->light->sample_li(lctx, u, ctx.lambda);
        if (!ls || ls->L.is_black() || !(ls->pdf > 0)) return c;
        sampled = PathVertex{};
        sampled.type = PathVertexType::Light;
        sampled.light = chosen->light;
        sampled.at_infinity = ls->is_infinite;
        // A point at infinity stands for its direction; any point along it serves.
        sampled.si.p = ls->is_infinite ? pt.p() + ls->wi : ls->p_light;
        sampled.si.n = sampled.si.shading.n = ls->is_infinite ? Vec3f{} : ls->n_light;
        sampled.si.error_scale = ls->error_scale_light;
        sampled.beta = ls->L / (chosen->pmf * ls->pdf);
        sampled.pdf_fwd = sampled.pdf_light_origin(scene, pt);
        // Next-event estimation's choice over the light subpath's, which the weights need
        // (mis_weight.cpp): known here without asking the light sampler again, but for a
        // direction at infinity, which any of the infinite lights may have produced.
        const float light_subpath_pmf = light_path_start_pmf(scene, *chosen->light);
        sampled.next_event_ratio_ahead = ls->is_infinite        ? sampled.next_event_ratio(scene, pt)
                                         : light_subpath_pmf > 0 ? chosen->pmf / light_subpath_pmf
                                                                 : 1.f;
        L = pt.beta * pt.f(ls->wi, TransportMode::Radiance) * pt.cosine(ls->wi, TransportMode::Radiance) *
            sampled.beta;
        if (L.is_black()) return c;
        // A medium vertex has no normal, so its rays start at the point itself.
        Ray shadow = ls->is_infinite ? spawn_ray(pt.p(), pt.ng(), pt.si.error_scale, ls->wi, ctx.time)
                                     : spawn_ray_to(pt.p(), pt.ng(), pt.si.error_scale, ls->p_light, ls->n_light,
                                                    ls->error_scale_light, ctx.time);
        L *= transmittance(scene, shadow, pt.medium_towards(ls->wi), ctx.lambda, rays);
    } else {
        // Join two scattering vertices with a shadow ray: both scattering functions and the
        // geometry term (shading-normal cosines, adjoint-corrected on the light side, none at
        // medium vertices, over distance^2) times the transmittance between them.
        const PathVertex &qs = light_vertices[s - 1], &pt = camera_vertices[t - 1];
        if (!qs.connectible() || !pt.connectible()) return c;
        Vec3f d = pt.p() - qs.p();
        float dist2 = length_squared(d);
        if (dist2 == 0) return c;
        d = d / std::sqrt(dist2);
        L = qs.beta * qs.f(d, TransportMode::Importance) * qs.cosine(d, TransportMode::Importance) *
            pt.f(-d, TransportMode::Radiance) * (pt.cosine(-d, TransportMode::Radiance) / dist2) * pt.beta;
        if (L.is_black()) return c;
        L *= connection_transmittance(ctx, qs, pt);
    }
    if (L.is_black()) return c;
    c.L = L * bdpt_mis_weight(scene, light_vertices, camera_vertices, sampled, s, t);
    return c;
}

// Strategy s = 1 for light that an emissive medium emits: next-event estimation samples lights
// alone, so the camera vertex is joined to the light subpath's start when that lies in a medium:
// the emission sigma_a Le, the same towards every direction, over the start's density.
SampledSpectrum connect_to_medium_start(const SubpathContext &ctx, PathVertex *light_vertices,
                                        PathVertex *camera_vertices, int t) {
    const PathVertex &start = light_vertices[0], &pt = camera_vertices[t - 1];
    if (!pt.connectible()) return SampledSpectrum(0.f);
    Vec3f d = pt.p() - start.p();
    const float dist2 = length_squared(d);
    if (dist2 == 0) return SampledSpectrum(0.f);
    d = d / std::sqrt(dist2);
    SampledSpectrum L = start.beta * pt.f(-d, TransportMode::Radiance) *
                        (pt.cosine(-d, TransportMode::Radiance) / dist2) * pt.beta;
    if (L.is_black()) return L;
    L *= connection_transmittance(ctx, start, pt);
    if (L.is_black()) return L;
    return L * bdpt_mis_weight(ctx.scene, light_vertices, camera_vertices, start, 1, t);
}

// Room for n vertices in the sample's scratch memory (released with it: vertices own nothing).
// They are left unconstructed: a subpath starts each vertex it reaches (start_vertex), and
// zeroing all max_depth + 2 of them up front, most never reached, cost a tenth of BDPT's time.
PathVertex *new_vertices(ScratchBuffer &scratch, int n) {
    static_assert(std::is_trivially_destructible_v<PathVertex>);
    return static_cast<PathVertex *>(scratch.allocate(sizeof(PathVertex) * n, alignof(PathVertex)));
}

// Keeps only the hero wavelength's value once the sample's wavelengths were terminated.
SampledSpectrum hero_only(SampledSpectrum L, const SampledWavelengths &lambda) {
    if (lambda.secondary_terminated())
        for (int i = 1; i < NumWavelengths; ++i) L[i] = 0;
    return L;
}

} // namespace

void BDPT::render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                  const ProgressCallback &progress) {
    const int max_depth = max_depth_;
    Film &film = *scene.film;
    const bool join_light_starts = lens_joins_light_starts(scene);
    for_each_pixel_sample(scene, budget, stats, progress, [&](Vec2i pixel, int, PixelSampleContext &sample) {
        Sampler &sampler = sample.sampler;
        SampledWavelengths lambda = sample_wavelengths(scene, sampler.get_1d());
        CameraSample cs = get_camera_sample(sampler, pixel, film.filter(), scene.motion_shutter());
        SampledSpectrum L(0.f);
        auto camera_ray = scene.generate_camera_ray(cs, lambda, sampler.samples_per_pixel());
        if (camera_ray) {
            SubpathContext ctx{scene, lambda, sample, camera_ray->ray.time, regularize_};
            // A path of depth d (bounces) has d + 2 vertices: the camera subpath may need all of
            // them (s = 0), the light subpath all but the lens point (t = 1); each subsurface
            // jump adds one that is not a bounce (PathVertex::after_jump), at most one per bounce.
            PathVertex *camera_vertices = new_vertices(sample.scratch, 2 * (max_depth + 2));
            PathVertex *light_vertices = new_vertices(sample.scratch, 2 * (max_depth + 1));
            SampledSpectrum camera_only(0.f);
            const int n_camera = camera_subpath(ctx, *camera_ray, camera_vertices, max_depth + 2, &camera_only);
            L += hero_only(camera_only, lambda);
            const int n_light = light_subpath(ctx, light_vertices, max_depth + 1);
            // s = 1 samples a light point of its own (next-event estimation), so it is tried
            // even when the light subpath did not start (a light point under an alpha cut-out):
            // the MIS weights of the other strategies count on it. With t = 1 it joins the
            // light subpath's first vertex to the lens and needs one. (Its MIS weight puts its
            // own light point in the first vertex's place, which must then hold a value.)
            if (n_light == 0) light_vertices[0] = PathVertex{};
            // A light subpath that starts in an emissive medium counts its start as a scattering
            // event, as the path tracer counts the emission it collects there.
            const bool medium_start = n_light > 0 && light_vertices[0].is_medium_emitter();
            auto add = [&](const Connection &c) {
                if (c.L.is_black()) return;
                SampledSpectrum contribution = hero_only(c.L, lambda);
                // A non-finite value is a bug to fix at its source; counted, never filmed.
                if (contribution.has_non_finite()) {
                    ++sample.non_finite;
                    return;
                }
                if (c.splat)
                    film.add_splat(c.p_raster, contribution, lambda);
                else
                    L += contribution;
            };
            for (int t = 1; t <= n_camera; ++t)
                for (int s = 0; s <= std::max(n_light, t > 1 ? 1 : 0); ++s) {
                    if (s == 1 && t == 1 && !join_light_starts) continue;
                    const int depth = s + t - 2 - camera_vertices[t - 1].jumps - (s > 1 ? light_vertices[s - 1].jumps : 0);
                    if (depth < 0) continue;
                    // s = 1 with t > 1 samples a light afresh: the medium start is joined on its own.
                    const bool from_medium = medium_start && s > 0 && !(s == 1 && t > 1);
                    if (depth + from_medium <= max_depth) add(connect(ctx, light_vertices, camera_vertices, s, t));
                    if (medium_start && s == 1 && t > 1 && depth + 1 <= max_depth)
                        add(Connection{connect_to_medium_start(ctx, light_vertices, camera_vertices, t), false, {}});
                }
        }
        film.add_sample(pixel, L, lambda, cs.filter_weight);
    });
}

// One light subpath per pixel sample.
double BDPT::splat_scale(const Scene &scene, const RenderStats &stats) const {
    return light_path_splat_scale(scene, stats.pixel_samples);
}

} // namespace caustica
