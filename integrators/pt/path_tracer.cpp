#include "integrators/pt/path_tracer.h"

#include "geometry/interaction.h"
#include "integrators/common/path_tracing.h"
#include "integrators/common/subpath_walk.h"
#include "integrators/common/tile_renderer.h"
#include "scene/scene.h"

namespace caustica {

PathTracer::PathTracer(const ParameterDictionary &params)
    : max_depth_(params.get_one_int("maxdepth", 5)), regularize_(params.get_one_bool("regularize", false)) {
    if (max_depth_ < 0)
        throw InputError(params.location("maxdepth"), "\"maxdepth\" must not be negative");
}

namespace {

// Radiance along a camera ray: the path tracer's estimator (path_tracing.h) from the lens on.
SampledSpectrum trace_path(const Scene &scene, int max_depth, bool regularize, const CameraRay &camera_ray,
                           SampledWavelengths &lambda, Sampler &sampler, ScratchBuffer &scratch, uint64_t &rays) {
    SubpathWalk walk(scene, TransportMode::Radiance, lambda, sampler, scratch, rays, false);
    walk.allow_reradiation();
    if (regularize) walk.regularize_after_non_specular_bounces();
    walk.start(camera_ray.ray, scene.camera_medium, SampledSpectrum(1.f), camera_ray.differential);
    return trace_radiance(scene, walk, EmissionMIS{}, 0, max_depth, sampler, rays);
}

} // namespace

void PathTracer::render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                        const ProgressCallback &progress) {
    int max_depth = max_depth_;
    bool regularize = regularize_;
    render_tiles(scene, budget, stats, progress,
                 [&scene, max_depth, regularize](const CameraRay &camera_ray, SampledWavelengths &lambda,
                                                 Sampler &sampler, ScratchBuffer &scratch, uint64_t &rays) {
                     return trace_path(scene, max_depth, regularize, camera_ray, lambda, sampler, scratch, rays);
                 });
}

} // namespace caustica
