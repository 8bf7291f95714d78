#include "integrators/pt/path_tracer.h"

#include "core/sampling.h"
#include "geometry/interaction.h"
#include "integrators/common/light_sampling.h"
#include "integrators/common/reradiation.h"
#include "integrators/common/subpath_walk.h"
#include "integrators/common/tile_renderer.h"
#include "scene/scene.h"

namespace caustica {

PathTracer::PathTracer(const ParameterDictionary &params)
    : max_depth_(params.get_one_int("maxdepth", 5)) {
    if (max_depth_ < 0)
        throw InputError(params.location("maxdepth"), "\"maxdepth\" must not be negative");
}

namespace {

// MIS between BSDF sampling and next-event estimation for the emitters the path reaches.
struct EmissionMIS {
    bool specular_bounce = false;
    float bsdf_pdf = 0;          // density of the direction that reached the emitter
    LightSampleContext prev_ctx; // where that direction was sampled
};

// Radiance along a camera ray: next-event estimation at every non-specular vertex (surface or
// medium), weighted against the walk's own hits on emitters by the power heuristic. Emitters and
// lights are evaluated at the wavelengths the walk carries (walk.lambda(): the film's, until a
// fluorescent re-radiation moves them), while L stays on the film's. Emissive
// media are not lights: their emission is what the walk collects (walk.emitted()).
SampledSpectrum trace_path(const Scene &scene, int max_depth, const CameraRay &camera_ray, SampledWavelengths &lambda,
                           Sampler &sampler, ScratchBuffer &scratch, uint64_t &rays) {
    SubpathWalk walk(scene, TransportMode::Radiance, lambda, sampler, scratch, rays, false);
    walk.start(camera_ray.ray, scene.camera_medium, SampledSpectrum(1.f), camera_ray.differential);
    SampledSpectrum L(0.f);
    EmissionMIS mis;
    int depth = 0;
    // Emission reached by the walk, weighted against light sampling from the vertex before.
    auto add_emission = [&](const Light &light, const SampledSpectrum &Le, Vec3f wi) {
        if (Le.is_black()) return;
        float w = 1;
        if (depth > 0 && !mis.specular_bounce)
            w = power_heuristic(1, mis.bsdf_pdf, 1, light_pdf(scene, light, mis.prev_ctx, wi));
        L += walk.beta * Le * w;
    };
    while (true) {
        const WalkEvent event = walk.advance();
        // Emissive media along the segment, counted as pbrt-v4's volpath counts them: while
        // fewer than maxdepth scattering events lie behind.
        if (depth < max_depth) L += walk.emitted();
        if (event == WalkEvent::Ended) break;
        if (event == WalkEvent::Escaped) {
            for (const Light *light : scene.infinite_lights) add_emission(*light, light->Le(walk.ray(), walk.lambda()), walk.ray().d);
            break;
        }
        const ScatteringPoint &point = walk.vertex();
        if (!point.in_medium()) {
            const SurfaceInteraction &si = walk.hit();
            if (si.area_light) add_emission(*si.area_light, si.area_light->L(si.p, si.n, si.uv, si.wo, walk.lambda()), walk.ray().d);
            if (!point.bsdf) {
                walk.pass_through();
                continue;
            }
        }
        if (depth++ == max_depth) break;
        // Next-event estimation at this vertex, and again at the exit of a profile solid that
        // the sampled direction enters (one scattering event, as for maxdepth).
        while (true) {
            if (point.in_medium()) {
                L += walk.beta * sample_direct_lighting_in_medium(scene, point.p, point.time, point.wo, *point.medium, walk.lambda(),
                                                                 sampler, rays);
                mis.prev_ctx = LightSampleContext{point.p, {}, {}};
            } else {
                const SurfaceInteraction &si = walk.hit();
                mis.prev_ctx = LightSampleContext{si.p, si.n, si.shading.n};
                if (is_non_specular(point.bsdf.flags()))
                    L += walk.beta * sample_direct_lighting(scene, si, point.bsdf, mis.prev_ctx, walk.lambda(), sampler,
                                                            rays, TransportMode::Radiance,
                                                            DirectLighting::WeightedAgainstBsdfSampling,
                                                            walk.medium());
                // A fluorescent surface also re-radiates light sampled at another wavelength.
                if (point.bsdf.reradiation())
                    L += walk.beta * sample_reradiated_lighting(scene, si, point.bsdf, mis.prev_ctx, walk.lambda(),
                                                                sampler, rays, walk.medium());
            }
            const std::optional<WalkScatter> s = walk.scatter();
            if (!s) return L;
            mis.bsdf_pdf = s->pdf_fwd;
            mis.specular_bounce = s->specular;
            if (!s->profile) break;
            if (!walk.jump(*s->profile)) return L;
        }
        if (!walk.russian_roulette(depth)) break;
    }
    return L;
}

} // namespace

void PathTracer::render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                        const ProgressCallback &progress) {
    int max_depth = max_depth_;
    render_tiles(scene, budget, stats, progress,
                 [&scene, max_depth](const CameraRay &camera_ray, SampledWavelengths &lambda,
                                     Sampler &sampler, ScratchBuffer &scratch, uint64_t &rays) {
                     return trace_path(scene, max_depth, camera_ray, lambda, sampler, scratch, rays);
                 });
}

} // namespace caustica
