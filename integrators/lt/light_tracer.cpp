#include "integrators/lt/light_tracer.h"

#include "core/error.h"
#include "geometry/interaction.h"
#include "integrators/common/path_vertex.h"
#include "integrators/common/splat_scale.h"
#include "integrators/common/tile_renderer.h"
#include "scene/scene.h"

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
    // Traced from the lens towards the light point: when a two-sided light is seen from the side
    // opposite to the sampled emission direction, p lies on the wrong side and a ray spawned
    // from it would start on the emitter; spawn_ray_to moves the target to the lens's side and
    // stops short of it, whichever side p is on.
    ++ctx.sample.rays;
    if (scene.occluded(spawn_ray_to(cs->p_lens, Vec3f{}, p, les.n))) return;
    splat(ctx, cs->p_raster, L, lambda);
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
    Ray ray = les->ray;
    int depth = 0;
    while (true) {
        SurfaceInteraction si;
        ++rays;
        bool hit = scene.intersect(ray, &si);

        // Beer-Lambert absorption along a segment inside an absorbing dielectric, tracked as the
        // path tracer does (a light inside such a dielectric is not detected: paths start clear).
        if (absorbing_interior) {
            float dist = hit ? si.t * length(ray.d) : Infinity;
            beta *= exp(-absorbing_interior->interior_sigma_a(lambda) * dist);
            if (beta.is_black()) break;
        }
        if (!hit) break;
        if (!si.material) {
            // A medium boundary without a surface: continue straight through.
            ray = si.spawn_ray(ray.d);
            continue;
        }
        // Scattering vertex number depth + 1: connecting it to the camera makes a path of
        // depth + 1 bounces, which max_depth bounds as it does camera paths.
        if (depth++ == ctx.max_depth) break;

        BSDF bsdf = si.material->get_bsdf(si, lambda, ctx.sample.scratch);
        if (!bsdf) {
            ray = si.spawn_ray(ray.d);
            continue;
        }
        const Vec3f wo = si.wo;

        // Connect this vertex to the lens (t = 1). Specular lobes have zero density towards any
        // given direction, so only non-specular BSDFs can contribute.
        if (is_non_specular(bsdf.flags())) {
            auto cs = scene.camera->sample_wi(si.p, sampler.get_2d(), lambda);
            if (cs && cs->pdf > 0) {
                SampledSpectrum f = bsdf.f(wo, cs->wi, TransportMode::Importance) *
                                    importance_cosine(si, wo, cs->wi);
                if (!f.is_black()) {
                    SampledSpectrum L = flux * beta * f * cs->We / cs->pdf;
                    ++rays;
                    if (!L.is_black() && !scene.occluded(si.spawn_ray_to(cs->p_lens)))
                        splat(ctx, cs->p_raster, L, lambda);
                }
            }
        }

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
        if (bs->is_transmission() && si.material->has_interior_absorption())
            absorbing_interior = dot(bs->wi, si.n) < 0 ? si.material : nullptr;
        ray = si.spawn_ray(bs->wi);

        // Russian roulette on the throughput. Importance transport has no 1/eta^2 factor at
        // refraction (Veach 1997 section 5.2), so unlike the path tracer there is no eta scale
        // to undo.
        if (beta.max_value() < 1 && depth > 1) {
            float q = std::max(0.f, 1 - beta.max_value());
            if (sampler.get_1d() < q) break;
            beta /= 1 - q;
        }
        if (beta.is_black()) break;
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
