#include "integrators/common/light_path_start.h"

#include "camera/camera.h"
#include "integrators/common/transmittance.h"
#include "lights/light_sampler.h"
#include "media/medium_interface.h"
#include "sampler/sampler.h"
#include "scene/scene.h"

namespace caustica {

namespace {

// The medium at point p: the one on p's side of the first surface along a fixed direction that
// separates two media, or, when no such surface lies that way, the camera's (a medium that
// surrounds the camera without bounds). Surfaces that are no transition are passed through.
const Medium *medium_at(const Scene &scene, Vec3f p, float time) {
    const Vec3f d = normalize(Vec3f{0.267f, 0.535f, 0.802f});
    Ray ray{p, d, Infinity, time};
    for (int crossed = 0; crossed < 64; ++crossed) {
        SurfaceInteraction si;
        if (!scene.intersect(ray, &si)) return scene.camera_medium;
        if (si.medium_interface && si.medium_interface->is_transition())
            return dot(d, si.n) > 0 ? si.medium_interface->inside : si.medium_interface->outside;
        ray = si.spawn_ray(d);
    }
    return nullptr;
}

// Light subpaths choose among the lights and the emissive media by power.
const LightSampler &light_path_sampler(const Scene &scene) {
    return scene.light_and_medium_sampler ? *scene.light_and_medium_sampler : *scene.light_sampler;
}

} // namespace

std::optional<LightPathStart> start_light_path(const Scene &scene, Sampler &sampler, const SampledWavelengths &lambda,
                                               float time) {
    auto chosen = light_path_sampler(scene).sample(sampler.get_1d());
    const Vec2f u_position = sampler.get_2d(), u_direction = sampler.get_2d();
    if (!chosen) return std::nullopt;
    auto les = chosen->light->sample_le(u_position, u_direction, lambda);
    if (!les || les->L.is_black() || !(les->pdf_pos > 0) || !(les->pdf_dir > 0)) return std::nullopt;
    les->ray.time = time;
    if (chosen->light->type() == LightType::Volume && medium_at(scene, les->ray.o, time) != chosen->light->medium())
        return std::nullopt;
    LightPathStart start{chosen->light, chosen->pmf, *les};
    if (les->n != Vec3f{}) start.cos_origin = abs_dot(les->n, normalize(les->ray.d));
    start.flux = les->L * (start.cos_origin / (chosen->pmf * les->pdf_pos * les->pdf_dir));
    return start;
}

float light_path_start_pmf(const Scene &scene, const Light &light) { return light_path_sampler(scene).pmf(&light); }

LightPoint LightPathStart::origin() const {
    // LightLeSample gives the sampled point only as the emitted ray's origin, already moved off
    // the surface towards the sampled direction (a few ulps): that offset is far below anything
    // visible.
    return {light, les.ray.o, les.n, les.uv, les.error_scale, les.ray.time, pmf * les.pdf_pos};
}

bool lens_joins_light_starts(const Scene &scene) { return !scene.film->clamps_samples(); }

std::optional<StartSeenByLens> join_start_to_lens(const Scene &scene, const LightPoint &start, Vec2f u_lens,
                                                  const SampledWavelengths &lambda, uint64_t &rays) {
    if (is_delta_light(start.light->type())) return std::nullopt;
    auto cs = scene.camera->sample_wi(start.p, u_lens, lambda, start.time);
    if (!cs || !(cs->pdf > 0)) return std::nullopt;
    SampledSpectrum Le = start.light->L(start.p, start.n, start.uv, cs->wi, lambda);
    if (Le.is_black()) return std::nullopt;
    // A point in a medium has no cosine: its Le is sigma_a Le per unit length, and its density
    // is per unit volume.
    const float cos_light = start.n == Vec3f{} ? 1.f : abs_dot(start.n, cs->wi);
    SampledSpectrum L = Le * cs->We * (cos_light / (start.pdf * cs->pdf));
    if (L.is_black()) return std::nullopt;
    // Traced from the lens (in the camera's medium) towards the light point: when a two-sided
    // light is seen from the side opposite to the sampled emission direction, p lies on the
    // wrong side and a ray spawned from it would start on the emitter; spawn_ray_to moves the
    // target to the lens's side and stops short of it, whichever side p is on.
    L *= transmittance(scene, spawn_ray_to(cs->p_lens, Vec3f{}, 0, start.p, start.n, start.error_scale, start.time),
                       scene.camera_medium, lambda, rays);
    if (L.is_black()) return std::nullopt;
    return StartSeenByLens{cs->p_raster, cs->p_lens, cs->wi, cos_light, L};
}

} // namespace caustica
