#include "integrators/lt/light_tracer.h"

#include "core/error.h"
#include "geometry/interaction.h"
#include "integrators/common/path_segment.h"
#include "integrators/common/path_vertex.h"
#include "integrators/common/profile_subsurface.h"
#include "integrators/common/splat_scale.h"
#include "integrators/common/tile_renderer.h"
#include "integrators/common/transmittance.h"
#include "materials/disney_material.h"
#include "media/medium_interface.h"
#include "scene/scene.h"

#include <optional>
#include <utility>

namespace caustica {

LightTracer::LightTracer(const ParameterDictionary &params, const Scene &scene)
    : max_depth_(params.get_one_int("maxdepth", 5)) {
    if (max_depth_ < 0)
        throw InputError(params.location("maxdepth"), "\"maxdepth\" must not be negative");
    if (!scene.camera->models_importance())
        throw InputError(scene.integrator_location,
                         "the light tracer (lt) needs a camera whose importance is modelled "
                         "(perspective); this scene's camera has none");
    if (!scene.infinite_lights.empty())
        warning(scene.integrator_location,
                "the light tracer (lt) does not render environment lights seen directly by the "
                "camera (their emission at infinity cannot be connected to the lens)");
}

namespace {

struct LightPathContext {
    const Scene &scene;
    int max_depth;
    PixelSampleContext &sample;
};

// Adds a connection's contribution at p_raster; non-finite values are counted and dropped.
void splat(const LightPathContext &ctx, Vec2f p_raster, const SampledSpectrum &L,
           const SampledWavelengths &lambda) {
    if (L.is_black()) return;
    if (L.has_non_finite()) {
        ++ctx.sample.non_finite;
        return;
    }
    ctx.scene.film->add_splat(p_raster, L, lambda);
}

// The light path's first vertex, the point on an area light, connected to the lens (s = 1,
// t = 1): emission seen directly by the camera. Estimate Le(wi) |cos_light| We / (pmf pdf_pos
// pdf_lens), where sample_wi's pdf (solid angle at the light point) carries the lens geometry.
void connect_light_vertex(const LightPathContext &ctx, const Light &light, const LightLeSample &les,
                          float light_pmf, const SampledWavelengths &lambda) {
    const Scene &scene = ctx.scene;
    // LightLeSample gives the sampled point only as the emitted ray's origin, already moved off
    // the surface towards the sampled direction (a few ulps): that offset is far below anything
    // visible. It carries no uv either; Caustica's area lights emit uniformly over their shape,
    // so L does not depend on it.
    const Vec3f p = les.ray.o;
    auto cs = scene.camera->sample_wi(p, ctx.sample.sampler.get_2d(), lambda);
    if (!cs || !(cs->pdf > 0)) return;
    SampledSpectrum Le = light.L(p, les.n, Vec2f{}, cs->wi, lambda);
    if (Le.is_black()) return;
    SampledSpectrum L = Le * cs->We * (abs_dot(les.n, cs->wi) / (light_pmf * les.pdf_pos * cs->pdf));
    if (L.is_black()) return;
    // Traced from the lens (in the camera's medium) towards the light point: when a two-sided
    // light is seen from the side opposite to the sampled emission direction, p lies on the
    // wrong side and a ray spawned from it would start on the emitter; spawn_ray_to moves the
    // target to the lens's side and stops short of it, whichever side p is on.
    L *= transmittance(scene, spawn_ray_to(cs->p_lens, Vec3f{}, p, les.n), scene.camera_medium, lambda,
                       ctx.sample.rays);
    splat(ctx, cs->p_raster, L, lambda);
}

// Connects a scattering vertex at p, reached with the given throughput, to a sampled lens point
// (t = 1) and splats the result. scattering(wi) is the vertex's scattering function towards the
// lens (times the cosine there, at a surface); ray_to_lens(p_lens, wi) the connecting ray from
// the vertex and the medium it starts in.
template <typename Scattering, typename RayToLens>
void connect_to_lens(const LightPathContext &ctx, Vec3f p, const SampledSpectrum &throughput,
                     const SampledWavelengths &lambda, const Scattering &scattering, const RayToLens &ray_to_lens) {
    auto cs = ctx.scene.camera->sample_wi(p, ctx.sample.sampler.get_2d(), lambda);
    if (!cs || !(cs->pdf > 0)) return;
    SampledSpectrum f = scattering(cs->wi);
    if (f.is_black()) return;
    SampledSpectrum L = throughput * f * cs->We / cs->pdf;
    if (L.is_black()) return;
    auto [ray, medium] = ray_to_lens(cs->p_lens, cs->wi);
    L *= transmittance(ctx.scene, ray, medium, lambda, ctx.sample.rays);
    splat(ctx, cs->p_raster, L, lambda);
}

// Russian roulette on the throughput after the first bounces; false when the path ends.
// Importance transport has no 1/eta^2 factor at refraction (Veach 1997 section 5.2), so unlike
// the path tracer there is no eta scale to undo.
bool russian_roulette(SampledSpectrum &beta, int depth, Sampler &sampler) {
    if (beta.max_value() < 1 && depth > 1) {
        float q = std::max(0.f, 1 - beta.max_value());
        if (sampler.get_1d() < q) return false;
        beta /= 1 - q;
    }
    return !beta.is_black();
}

// The rest of a profile BSSRDF event entered at `entry` (profile_subsurface.h): the exit point,
// joined to the lens through its exit lobe like any diffuse vertex, then a direction sampled
// from that lobe. The path keeps to the medium it arrived in (a profile solid has no interior
// medium). False when the path ends.
bool leave_through_profile(const LightPathContext &ctx, const DisneyMaterial &material,
                           const SurfaceInteraction &entry, const SampledSpectrum &flux, SampledSpectrum &beta,
                           Ray &ray, const Medium *&medium, const SampledWavelengths &lambda) {
    Sampler &sampler = ctx.sample.sampler;
    std::optional<ProfileExit> exit =
        sample_profile_exit(ctx.scene, material, entry, lambda, sampler, ctx.sample.scratch, ctx.sample.rays);
    if (!exit) return false;
    beta *= exit->weight;
    if (beta.is_black()) return false;
    const SurfaceInteraction &si = exit->si;
    const BSDF &bsdf = exit->bsdf;
    connect_to_lens(
        ctx, si.p, flux * beta, lambda,
        [&](Vec3f wi) { return bsdf.f(si.wo, wi, TransportMode::Importance) * importance_cosine(si, si.wo, wi); },
        [&](Vec3f p_lens, Vec3f wi) { return std::pair{si.spawn_ray_to(p_lens), medium_after(si, wi, medium)}; });
    auto bs = bsdf.sample_f(si.wo, 0, sampler.get_2d(), TransportMode::Importance);
    if (!bs) return false;
    beta *= bs->f * (importance_cosine(si, si.wo, bs->wi) / bs->pdf);
    medium = medium_after(si, bs->wi, medium);
    ray = si.spawn_ray(bs->wi);
    return true;
}

// One light path for the sampler's current (pixel, iteration).
void trace_light_path(const LightPathContext &ctx) {
    const Scene &scene = ctx.scene;
    Sampler &sampler = ctx.sample.sampler;
    uint64_t &rays = ctx.sample.rays;

    SampledWavelengths lambda = sample_wavelengths(scene, sampler.get_1d());
    auto sampled = scene.light_sampler->sample(sampler.get_1d());
    if (!sampled) return;
    const Light &light = *sampled->light;
    Vec2f u_position = sampler.get_2d(), u_direction = sampler.get_2d();
    auto les = light.sample_le(u_position, u_direction, lambda);
    if (!les || les->L.is_black() || !(les->pdf_pos > 0) || !(les->pdf_dir > 0)) return;

    if (light.type() == LightType::Area) connect_light_vertex(ctx, light, *les, sampled->pmf, lambda);

    // The emitted flux the path carries, kept apart from the scattering throughput beta so that
    // Russian roulette sees beta on the same scale (starting at 1) as in the path tracer. Lights
    // without a surface (point, spot, distant, infinite) have no cosine at the origin.
    const float cos_origin = les->n == Vec3f{} ? 1.f : abs_dot(les->n, les->ray.d);
    SampledSpectrum flux = les->L * (cos_origin / (sampled->pmf * les->pdf_pos * les->pdf_dir));
    SampledSpectrum beta(1.f);
    const Material *absorbing_interior = nullptr;
    FreeFlightMIS free_flight;
    // The path starts in the light's medium (for an area light, that on its shape's outside).
    const Medium *medium = light.medium();
    Ray ray = les->ray;
    int depth = 0;
    while (true) {
        SurfaceInteraction si;
        ++rays;
        bool hit = scene.intersect(ray, &si);

        // Free flight through the medium and absorption inside an absorbing dielectric, as in
        // the path tracer (a light inside such a dielectric is not detected: paths start clear).
        PathSegment segment = traverse_segment(medium, absorbing_interior, hit ? si.t * length(ray.d) : Infinity,
                                               lambda, sampler, free_flight);
        beta *= segment.weight;
        if (beta.is_black()) break;
        if (segment.scattered) {
            // A scattering event in the medium, which counts as a vertex like a surface one:
            // connect it to the lens through the medium, then continue by sampling the phase
            // function, whose value equals its density (beta is unchanged).
            if (depth++ == ctx.max_depth) break;
            const Vec3f wo = -normalize(ray.d), p = ray.o - wo * segment.t;
            const HenyeyGreenstein &phase = medium->phase();
            connect_to_lens(
                ctx, p, flux * beta, lambda, [&](Vec3f wi) { return SampledSpectrum(phase.p(wo, wi)); },
                [&](Vec3f p_lens, Vec3f) { return std::pair{spawn_ray_to(p, Vec3f{}, p_lens), medium}; });
            PhaseSample ps = phase.sample_p(wo, sampler.get_2d());
            if (!(ps.p > 0)) break;
            ray = Ray{p, ps.wi, Infinity};
            if (!russian_roulette(beta, depth, sampler)) break;
            continue;
        }
        if (!hit) break;
        if (!si.material) {
            // A medium boundary without a surface: continue straight through.
            medium = medium_after(si, ray.d, medium);
            ray = si.spawn_ray(ray.d);
            continue;
        }
        // Scattering vertex number depth + 1: connecting it to the camera makes a path of
        // depth + 1 bounces, which max_depth bounds as it does camera paths.
        if (depth++ == ctx.max_depth) break;

        BSDF bsdf = shade(si, lambda, ctx.sample.scratch);
        if (!bsdf) {
            medium = medium_after(si, ray.d, medium);
            ray = si.spawn_ray(ray.d);
            continue;
        }
        const Vec3f wo = si.wo;

        // Connect this vertex to the lens (t = 1). Specular lobes have zero density towards any
        // given direction, so only non-specular BSDFs can contribute.
        if (is_non_specular(bsdf.flags()))
            connect_to_lens(
                ctx, si.p, flux * beta, lambda,
                [&](Vec3f wi) {
                    return bsdf.f(wo, wi, TransportMode::Importance) * importance_cosine(si, wo, wi);
                },
                [&](Vec3f p_lens, Vec3f wi) {
                    return std::pair{si.spawn_ray_to(p_lens), medium_after(si, wi, medium)};
                });

        float u = sampler.get_1d();
        auto bs = bsdf.sample_f(wo, u, sampler.get_2d(), TransportMode::Importance);
        if (!bs) break;
        // Hero-wavelength sampling (Wilkie et al. 2014): a direction that depends on wavelength
        // is valid for the hero only; the other lanes' contributions end here.
        if (bs->dispersive && !lambda.secondary_terminated()) {
            lambda.terminate_secondary();
            for (int i = 1; i < NumWavelengths; ++i) beta[i] = 0;
        }
        beta *= bs->f * (importance_cosine(si, wo, bs->wi) / bs->pdf);
        if (const DisneyMaterial *material = profile_entry(si, *bs)) {
            if (!leave_through_profile(ctx, *material, si, flux, beta, ray, medium, lambda)) break;
            if (!russian_roulette(beta, depth, sampler)) break;
            continue;
        }
        if (bs->is_transmission() && si.material->has_interior_absorption())
            absorbing_interior = dot(bs->wi, si.n) < 0 ? si.material : nullptr;
        medium = medium_after(si, bs->wi, medium);
        ray = si.spawn_ray(bs->wi);
        if (!russian_roulette(beta, depth, sampler)) break;
    }
}

} // namespace

void LightTracer::render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                         const ProgressCallback &progress) {
    const int max_depth = max_depth_;
    for_each_pixel_sample(scene, budget, stats, progress, [&](Vec2i, int, PixelSampleContext &sample) {
        trace_light_path(LightPathContext{scene, max_depth, sample});
    });
}

// One light path per pixel sample.
double LightTracer::splat_scale(const Scene &scene, const RenderStats &stats) const {
    return light_path_splat_scale(scene, stats.pixel_samples);
}

} // namespace caustica
