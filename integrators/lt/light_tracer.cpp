#include "integrators/lt/light_tracer.h"

#include "core/error.h"
#include "geometry/interaction.h"
#include "integrators/common/camera_importance.h"
#include "integrators/common/light_path_start.h"
#include "integrators/common/reradiation.h"
#include "integrators/common/splat_scale.h"
#include "integrators/common/subpath_walk.h"
#include "integrators/common/tile_renderer.h"
#include "integrators/common/transmittance.h"
#include "scene/scene.h"

#include <optional>

namespace caustica {

LightTracer::LightTracer(const ParameterDictionary &params, const Scene &scene)
    : max_depth_(params.get_one_int("maxdepth", 5)) {
    if (max_depth_ < 0)
        throw InputError(params.location("maxdepth"), "\"maxdepth\" must not be negative");
    require_camera_importance(scene, "the light tracer (lt)");
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

// Connects a scattering vertex, reached with the given throughput, to a sampled lens point
// (t = 1) and splats the result.
void connect_to_lens(const LightPathContext &ctx, const ScatteringPoint &point, const SampledSpectrum &throughput,
                     const SampledWavelengths &lambda) {
    auto cs = ctx.scene.camera->sample_wi(point.p, ctx.sample.sampler.get_2d(), lambda, point.time);
    if (!cs || !(cs->pdf > 0)) return;
    SampledSpectrum f = point.f(cs->wi, TransportMode::Importance);
    if (f.is_black()) return;
    SampledSpectrum L = throughput * f * cs->We / cs->pdf;
    if (L.is_black()) return;
    L *= transmittance(ctx.scene, spawn_ray_to(point.p, point.ng, point.error_scale, cs->p_lens, Vec3f{}, 0, point.time),
                       point.medium_towards(cs->wi), lambda,
                       ctx.sample.rays);
    splat(ctx, cs->p_raster, L, lambda);
}

// The light a fluorescent light vertex re-radiates towards a sampled lens point: a new
// wavelength drawn from the dye's emission (reradiation.h), splatted there.
void connect_reradiated_to_lens(const LightPathContext &ctx, const ScatteringPoint &point,
                                const SampledSpectrum &throughput, const SampledWavelengths &lambda) {
    const std::optional<ReradiationSample> r = sample_reradiation(*point.bsdf.reradiation(), TransportMode::Importance,
                                                                  lambda, ctx.sample.sampler.get_1d());
    if (!r) return;
    ScatteringPoint emitter = point;
    emitter.bsdf = BSDF(point.bsdf.frame(), &r->lobe);
    connect_to_lens(ctx, emitter, throughput, r->lambda);
}

// One light path for the sampler's current (pixel, iteration).
void trace_light_path(const LightPathContext &ctx) {
    const Scene &scene = ctx.scene;
    Sampler &sampler = ctx.sample.sampler;

    SampledWavelengths lambda = sample_wavelengths(scene, sampler.get_1d(), WavelengthsFor::LightPath);
    // The path's time within the shutter, drawn only when geometry moves (as camera paths do).
    const Shutter *shutter = scene.motion_shutter();
    const float time = shutter ? shutter->time(sampler.get_1d()) : 0.f;
    const std::optional<LightPathStart> start = start_light_path(scene, sampler, lambda, time);
    if (!start) return;
    // A path from an emissive medium starts at an event of the medium (where the path tracer's
    // collision estimator counts the emission), which counts towards max_depth as a scattering
    // vertex does.
    const bool from_medium = start->light->type() == LightType::Volume;
    int depth = from_medium ? 1 : 0;
    if ((start->light->type() == LightType::Area || from_medium) && depth <= ctx.max_depth)
        if (auto seen = join_start_to_lens(scene, start->origin(), sampler.get_2d(), lambda, ctx.sample.rays))
            splat(ctx, seen->p_raster, seen->L, lambda);

    // The emitted flux is kept apart from the walk's throughput, so that Russian roulette sees
    // the throughput on the same scale (starting at 1) as in the path tracer. The path starts in
    // the light's medium (for an area light, that on its shape's outside).
    SubpathWalk walk(scene, TransportMode::Importance, lambda, sampler, ctx.sample.scratch, ctx.sample.rays, false);
    walk.allow_reradiation();
    walk.start(start->les.ray, start->light->medium(), SampledSpectrum(1.f));
    while (walk.advance() == WalkEvent::Vertex) {
        const ScatteringPoint &point = walk.vertex();
        if (!point.in_medium() && !point.bsdf) {
            walk.pass_through();
            continue;
        }
        // Scattering vertex number depth + 1: connecting it to the camera makes a path of
        // depth + 1 bounces, which max_depth bounds as it does camera paths.
        if (depth++ == ctx.max_depth) break;
        // Connect this vertex to the lens (t = 1), and again the exit of a profile solid that the
        // sampled direction enters. Specular lobes have zero density towards any given
        // direction, so only non-specular vertices can contribute.
        while (true) {
            if (point.in_medium() || is_non_specular(point.bsdf.flags())) {
                connect_to_lens(ctx, point, start->flux * walk.beta, lambda);
                if (scene.features.fluorescence && !point.in_medium() && point.bsdf.reradiation())
                    connect_reradiated_to_lens(ctx, point, start->flux * walk.beta, lambda);
            }
            const std::optional<WalkScatter> s = walk.scatter();
            if (!s) return;
            if (!s->profile) break;
            if (!walk.jump(*s->profile)) return;
        }
        if (!walk.russian_roulette(depth)) break;
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
