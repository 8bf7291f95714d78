#include "integrators/common/path_tracing.h"

#include "core/sampling.h"
#include "integrators/common/light_sampling.h"
#include "integrators/common/reradiation.h"
#include "integrators/common/subpath_walk.h"
#include "scene/scene.h"

namespace caustica {

SampledSpectrum trace_radiance(const Scene &scene, SubpathWalk &walk, EmissionMIS mis, int depth, int max_depth,
                               Sampler &sampler, uint64_t &rays, bool reradiated_only) {
    SampledSpectrum L(0.f);
    auto counts = [&] { return !reradiated_only || walk.reradiated(); };
    // Emission reached by the walk, weighted against light sampling from the vertex before.
    auto add_emission = [&](const Light &light, const SampledSpectrum &Le, Vec3f wi) {
        if (Le.is_black() || !counts()) return;
        float w = 1;
        if (depth > 0 && !mis.specular_bounce)
            w = power_heuristic(1, mis.bsdf_pdf, 1, light_pdf(scene, light, mis.prev_ctx, wi));
        L += walk.beta * Le * w;
    };
    while (true) {
        const WalkEvent event = walk.advance();
        // Emissive media along the segment, counted as pbrt-v4's volpath counts them: while
        // fewer than maxdepth scattering events lie behind.
        if (depth < max_depth && counts()) L += walk.emitted();
        if (event == WalkEvent::Ended) break;
        if (event == WalkEvent::Escaped) {
            for (const Light *light : scene.infinite_lights)
                add_emission(*light, light->Le(walk.ray(), walk.lambda()), walk.ray().d);
            break;
        }
        const ScatteringPoint &point = walk.vertex();
        if (!point.in_medium()) {
            const SurfaceInteraction &si = walk.hit();
            if (si.area_light)
                add_emission(*si.area_light, si.area_light->L(si.p, si.n, si.uv, si.wo, walk.lambda()), walk.ray().d);
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
                if (counts())
                        L += walk.beta * sample_direct_lighting_in_medium(scene, point.p, point.time, point.wo,
                                                                     *point.medium, walk.lambda(), sampler, rays);
                mis.prev_ctx = LightSampleContext{point.p, {}, {}};
            } else {
                const SurfaceInteraction &si = walk.hit();
                mis.prev_ctx = LightSampleContext{si.p, si.n, si.shading.n};
                if (is_non_specular(point.bsdf.flags()) && counts())
                    L += walk.beta * sample_direct_lighting(scene, si, point.bsdf, mis.prev_ctx, walk.lambda(), sampler,
                                                            rays, TransportMode::Radiance,
                                                            DirectLighting::WeightedAgainstBsdfSampling,
                                                            walk.medium());
                L += reradiated_light_at(scene, walk, sampler, rays);
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

SampledSpectrum reradiated_light_at(const Scene &scene, const SubpathWalk &walk, Sampler &sampler, uint64_t &rays) {
    if (!scene.features.fluorescence) return SampledSpectrum(0.f);
    const ScatteringPoint &point = walk.vertex();
    if (point.in_medium() || walk.after_jump() || !point.bsdf.reradiation()) return SampledSpectrum(0.f);
    const SurfaceInteraction &si = walk.hit();
    return walk.beta * sample_reradiated_lighting(scene, si, point.bsdf, LightSampleContext{si.p, si.n, si.shading.n},
                                                  walk.lambda(), sampler, rays, walk.medium());
}

SampledSpectrum reradiated_beyond(const Scene &scene, SubpathWalk &walk, const LightSampleContext &at, float scattered,
                                  int depth, int max_depth, Sampler &sampler, uint64_t &rays) {
    if (!walk.russian_roulette(depth)) return SampledSpectrum(0.f);
    return trace_radiance(scene, walk, EmissionMIS{false, scattered, at}, depth, max_depth, sampler, rays, true);
}

} // namespace caustica
