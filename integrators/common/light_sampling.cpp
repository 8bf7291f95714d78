#include "integrators/common/light_sampling.h"

#include "core/sampling.h"
#include "geometry/interaction.h"
#include "integrators/common/transmittance.h"
#include "media/medium_interface.h"
#include "scene/scene.h"

namespace caustica {

float light_pdf(const Scene &scene, const Light &light, const LightSampleContext &ctx, Vec3f wi) {
    return scene.light_sampler->pmf(ctx, &light) * light.pdf_li(ctx, wi);
}

namespace {

// The estimator shared by surface and medium points. scattering(wi) returns the BSDF times
// cosine (or the phase function) and its sampling density; shadow_ray(light sample) returns the
// ray to the light and the medium it starts in.
template <typename Scattering, typename ShadowRay>
SampledSpectrum estimate_direct(const Scene &scene, const LightSampleContext &ctx, const SampledWavelengths &lambda,
                                Sampler &sampler, uint64_t &rays, DirectLighting strategy,
                                const Scattering &scattering, const ShadowRay &shadow_ray) {
    float u_light = sampler.get_1d();
    Vec2f u = sampler.get_2d();
    auto sampled = scene.light_sampler->sample(ctx, u_light);
    if (!sampled) return {};
    const Light &light = *sampled->light;
    auto ls = light.sample_li(ctx, u, lambda);
    if (!ls || ls->L.is_black() || ls->pdf == 0) return {};

    auto [f, scattering_pdf] = scattering(ls->wi);
    if (f.is_black()) return {};
    auto [ray, medium] = shadow_ray(*ls);
    SampledSpectrum T = transmittance(scene, ray, medium, lambda, rays);
    if (T.is_black()) return {};

    float p_light = sampled->pmf * ls->pdf;
    if (is_delta_light(light.type()) || strategy == DirectLighting::LightSamplingOnly)
        return f * T * ls->L / p_light;
    return f * T * ls->L * (power_heuristic(1, p_light, 1, scattering_pdf) / p_light);
}

} // namespace

SampledSpectrum sample_direct_lighting(const Scene &scene, const SurfaceInteraction &si,
                                       const BSDF &bsdf, const LightSampleContext &ctx,
                                       const SampledWavelengths &lambda, Sampler &sampler,
                                       uint64_t &rays, TransportMode mode, DirectLighting strategy,
                                       const Medium *medium) {
    auto scattering = [&](Vec3f wi) {
        SampledSpectrum f = bsdf.f(si.wo, wi, mode) * abs_dot(wi, si.shading.n);
        return std::pair{f, f.is_black() || strategy == DirectLighting::LightSamplingOnly ? 0.f
                                                                                          : bsdf.pdf(si.wo, wi, mode)};
    };
    auto shadow_ray = [&](const LightLiSample &ls) {
        Ray ray = ls.is_infinite ? si.spawn_ray(ls.wi) : si.spawn_ray_to(ls.p_light, ls.n_light, ls.error_scale_light);
        return std::pair{ray, medium_after(si, ls.wi, medium)};
    };
    return estimate_direct(scene, ctx, lambda, sampler, rays, strategy, scattering, shadow_ray);
}

SampledSpectrum sample_direct_lighting_in_medium(const Scene &scene, Vec3f p, float time, Vec3f wo, const Medium &medium,
                                                 const SampledWavelengths &lambda, Sampler &sampler,
                                                 uint64_t &rays, DirectLighting strategy) {
    const HenyeyGreenstein &phase = medium.phase();
    auto scattering = [&](Vec3f wi) {
        float value = phase.p(wo, wi);
        return std::pair{SampledSpectrum(value), value};
    };
    auto shadow_ray = [&](const LightLiSample &ls) {
        Ray ray = ls.is_infinite ? Ray{p, ls.wi, Infinity, time} : spawn_ray_to(p, Vec3f{}, 0, ls.p_light, ls.n_light, ls.error_scale_light, time);
        return std::pair{ray, &medium};
    };
    return estimate_direct(scene, LightSampleContext{p, {}, {}}, lambda, sampler, rays, strategy, scattering,
                           shadow_ray);
}

} // namespace caustica
