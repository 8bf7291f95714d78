#include "integrators/common/light_sampling.h"

#include "core/sampling.h"
#include "geometry/interaction.h"
#include "scene/scene.h"

namespace caustica {

float light_pdf(const Scene &scene, const Light &light, const LightSampleContext &ctx, Vec3f wi) {
    return scene.light_sampler->pmf(&light) * light.pdf_li(ctx, wi);
}

SampledSpectrum sample_direct_lighting(const Scene &scene, const SurfaceInteraction &si,
                                       const BSDF &bsdf, const LightSampleContext &ctx,
                                       const SampledWavelengths &lambda, Sampler &sampler,
                                       uint64_t &rays, TransportMode mode, DirectLighting strategy) {
    float u_light = sampler.get_1d();
    Vec2f u = sampler.get_2d();
    auto sampled = scene.light_sampler->sample(u_light);
    if (!sampled) return {};
    const Light &light = *sampled->light;
    auto ls = light.sample_li(ctx, u, lambda);
    if (!ls || ls->L.is_black() || ls->pdf == 0) return {};

    SampledSpectrum f = bsdf.f(si.wo, ls->wi, mode) * abs_dot(ls->wi, si.shading.n);
    if (f.is_black()) return {};
    ++rays;
    Ray shadow = ls->is_infinite ? si.spawn_ray(ls->wi) : si.spawn_ray_to(ls->p_light, ls->n_light);
    if (scene.occluded(shadow)) return {};

    float p_light = sampled->pmf * ls->pdf;
    if (is_delta_light(light.type()) || strategy == DirectLighting::LightSamplingOnly) return f * ls->L / p_light;
    float p_bsdf = bsdf.pdf(si.wo, ls->wi, mode);
    return f * ls->L * (power_heuristic(1, p_light, 1, p_bsdf) / p_light);
}

} // namespace caustica
