#include "integrators/pt/path_tracer.h"

#include "core/sampling.h"
#include "geometry/interaction.h"
#include "integrators/common/light_sampling.h"
#include "integrators/common/path_segment.h"
#include "integrators/common/profile_subsurface.h"
#include "integrators/common/tile_renderer.h"
#include "materials/disney_material.h"
#include "media/medium_interface.h"
#include "scene/scene.h"

namespace caustica {

PathTracer::PathTracer(const ParameterDictionary &params)
    : max_depth_(params.get_one_int("maxdepth", 5)) {
    if (max_depth_ < 0)
        throw InputError(params.location("maxdepth"), "\"maxdepth\" must not be negative");
}

namespace {

struct PathState {
    SampledSpectrum L{0.f}, beta{1.f};
    // Product of eta^2 over refractions: Russian roulette looks at beta * eta_scale so that the
    // radiance-mode 1/eta^2 factor does not end paths inside dense glass (pbrt-v4 14.1).
    float eta_scale = 1;
    bool specular_bounce = false;
    float bsdf_pdf = 0;          // pdf of the last BSDF sample, for MIS on emitters hit
    LightSampleContext prev_ctx; // where that sample was taken
    const Material *absorbing_interior = nullptr;
    const Medium *medium = nullptr; // the participating medium the ray travels through
    FreeFlightMIS free_flight;
};

// Russian roulette after the first bounces; false when the path ends.
bool russian_roulette(PathState &st, int depth, Sampler &sampler) {
    SampledSpectrum rr_beta = st.beta * st.eta_scale;
    if (rr_beta.max_value() < 1 && depth > 1) {
        float q = std::max(0.f, 1 - rr_beta.max_value());
        if (sampler.get_1d() < q) return false;
        st.beta /= 1 - q;
    }
    return !st.beta.is_black();
}

// The rest of a profile BSSRDF event after its entry at `entry` (profile_subsurface.h): the
// exit point, whose weight R(r) / pdf carries the albedo, then the exit lobe there, with
// next-event estimation and a sampled direction, as at any diffuse surface. False when the path
// ends.
bool leave_through_profile(const Scene &scene, const DisneyMaterial &material, const SurfaceInteraction &entry,
                           PathState &st, Ray &ray, SampledWavelengths &lambda, Sampler &sampler,
                           ScratchBuffer &scratch, uint64_t &rays) {
    std::optional<ProfileExit> exit = sample_profile_exit(scene, material, entry, lambda, sampler, scratch, rays);
    if (!exit) return false;
    st.beta *= exit->weight;
    if (st.beta.is_black()) return false;

    const SurfaceInteraction &si = exit->si;
    const BSDF &bsdf = exit->bsdf;
    const LightSampleContext ctx{si.p, si.n, si.shading.n};
    st.L += st.beta * sample_direct_lighting(scene, si, bsdf, ctx, lambda, sampler, rays, TransportMode::Radiance,
                                             DirectLighting::WeightedAgainstBsdfSampling, st.medium);
    auto bs = bsdf.sample_f(si.wo, 0, sampler.get_2d(), TransportMode::Radiance);
    if (!bs) return false;
    st.beta *= bs->f * abs_dot(bs->wi, si.shading.n) / bs->pdf;
    st.bsdf_pdf = bs->pdf;
    st.specular_bounce = false;
    st.prev_ctx = ctx;
    st.medium = medium_after(si, bs->wi, st.medium);
    ray = si.spawn_ray(bs->wi);
    return true;
}

SampledSpectrum trace_path(const Scene &scene, int max_depth, Ray ray, SampledWavelengths &lambda,
                           Sampler &sampler, ScratchBuffer &scratch, uint64_t &rays) {
    PathState st;
    st.medium = scene.camera_medium;
    int depth = 0;
    while (true) {
        SurfaceInteraction si;
        ++rays;
        bool hit = scene.intersect(ray, &si);

        PathSegment segment = traverse_segment(st.medium, st.absorbing_interior,
                                               hit ? si.t * length(ray.d) : Infinity, lambda, sampler, st.free_flight);
        st.beta *= segment.weight;
        if (st.beta.is_black()) break;
        if (segment.scattered) {
            // A scattering event in the medium: light sampling and phase-function sampling,
            // combined by MIS as at a surface.
            if (depth++ == max_depth) break;
            const Vec3f wo = -normalize(ray.d), p = ray.o - wo * segment.t;
            st.L += st.beta * sample_direct_lighting_in_medium(scene, p, wo, *st.medium, lambda, sampler, rays);
            PhaseSample ps = st.medium->phase().sample_p(wo, sampler.get_2d());
            st.bsdf_pdf = ps.p;
            st.specular_bounce = false;
            st.prev_ctx = LightSampleContext{p, {}, {}};
            ray = Ray{p, ps.wi, Infinity};
            if (!russian_roulette(st, depth, sampler)) break;
            continue;
        }

        if (!hit) {
            for (const Light *light : scene.infinite_lights) {
                SampledSpectrum Le = light->Le(ray, lambda);
                if (Le.is_black()) continue;
                float w = 1;
                if (depth > 0 && !st.specular_bounce)
                    w = power_heuristic(1, st.bsdf_pdf, 1, light_pdf(scene, *light, st.prev_ctx, ray.d));
                st.L += st.beta * Le * w;
            }
            break;
        }

        if (si.area_light) {
            SampledSpectrum Le = si.area_light->L(si.p, si.n, si.uv, si.wo, lambda);
            if (!Le.is_black()) {
                float w = 1;
                if (depth > 0 && !st.specular_bounce)
                    w = power_heuristic(1, st.bsdf_pdf, 1, light_pdf(scene, *si.area_light, st.prev_ctx, ray.d));
                st.L += st.beta * Le * w;
            }
        }

        if (!si.material) {
            // A medium boundary without a surface: continue straight through.
            st.medium = medium_after(si, ray.d, st.medium);
            ray = si.spawn_ray(ray.d);
            continue;
        }
        if (depth++ == max_depth) break;

        BSDF bsdf = shade(si, lambda, scratch);
        if (!bsdf) {
            st.medium = medium_after(si, ray.d, st.medium);
            ray = si.spawn_ray(ray.d);
            continue;
        }
        const Vec3f wo = si.wo;
        const LightSampleContext ctx{si.p, si.n, si.shading.n};

        if (is_non_specular(bsdf.flags()))
            st.L += st.beta * sample_direct_lighting(scene, si, bsdf, ctx, lambda, sampler, rays,
                                                     TransportMode::Radiance,
                                                     DirectLighting::WeightedAgainstBsdfSampling, st.medium);

        float u = sampler.get_1d();
        auto bs = bsdf.sample_f(wo, u, sampler.get_2d(), TransportMode::Radiance);
        if (!bs) break;
        if (const DisneyMaterial *profile_material = profile_entry(si, *bs)) {
            st.beta *= bs->f * abs_dot(bs->wi, si.shading.n) / bs->pdf;
            if (!leave_through_profile(scene, *profile_material, si, st, ray, lambda, sampler, scratch, rays)) break;
            if (!russian_roulette(st, depth, sampler)) break;
            continue;
        }
        if (bs->dispersive && !lambda.secondary_terminated()) {
            lambda.terminate_secondary();
            for (int i = 1; i < NumWavelengths; ++i) st.beta[i] = 0;
        }
        st.beta *= bs->f * abs_dot(bs->wi, si.shading.n) / bs->pdf;
        st.bsdf_pdf = bs->pdf_is_proportional ? bsdf.pdf(wo, bs->wi) : bs->pdf;
        st.specular_bounce = bs->is_specular();
        st.prev_ctx = ctx;
        if (bs->is_transmission()) {
            st.eta_scale *= sqr(bs->eta);
            if (si.material->has_interior_absorption())
                st.absorbing_interior = dot(bs->wi, si.n) < 0 ? si.material : nullptr;
        }
        st.medium = medium_after(si, bs->wi, st.medium);
        ray = si.spawn_ray(bs->wi);
        if (!russian_roulette(st, depth, sampler)) break;
    }
    return st.L;
}

} // namespace

void PathTracer::render(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                        const ProgressCallback &progress) {
    int max_depth = max_depth_;
    render_tiles(scene, budget, stats, progress,
                 [&scene, max_depth](const CameraRay &camera_ray, SampledWavelengths &lambda,
                                     Sampler &sampler, ScratchBuffer &scratch, uint64_t &rays) {
                     return trace_path(scene, max_depth, camera_ray.ray, lambda, sampler, scratch, rays);
                 });
}

} // namespace caustica
