#include "scene/scene_probe.h"

#include "core/rng.h"
#include "scene/scene.h"

namespace caustica {

namespace {

enum class FirstHit { Nothing, Emitter, Specular, Other };

bool purely_specular(const Material &material) {
    return material.has_specular_lobe() && !material.has_non_specular_lobe();
}

// The first surface along the ray that is not a bare boundary between media.
FirstHit first_hit(const Scene &scene, Ray ray) {
    constexpr int MaxBoundaries = 16;
    for (int crossing = 0; crossing < MaxBoundaries; ++crossing) {
        SurfaceInteraction si;
        if (!scene.intersect(ray, &si)) return scene.infinite_lights.empty() ? FirstHit::Nothing : FirstHit::Emitter;
        if (si.area_light) return FirstHit::Emitter;
        if (si.material) return purely_specular(*si.material) ? FirstHit::Specular : FirstHit::Other;
        ray = si.spawn_ray(ray.d);
    }
    return FirstHit::Other;
}

} // namespace

SceneProbe probe_scene(const Scene &scene, int rays_per_axis) {
    SceneProbe probe;
    const SampledWavelengths lambda = SampledWavelengths::fixed(550);
    const Vec2i resolution = scene.film->resolution();
    const int count = rays_per_axis * rays_per_axis;
    int emitters = 0, specular = 0, camera_rays = 0;
    for (int j = 0; j < rays_per_axis; ++j)
        for (int i = 0; i < rays_per_axis; ++i) {
            CameraSample sample;
            sample.p_film = {(i + 0.5f) * resolution.x / rays_per_axis,
                             (j + 0.5f) * resolution.y / rays_per_axis};
            sample.p_lens = {0.5f, 0.5f};
            std::optional<CameraRay> camera_ray = scene.camera->generate_ray(sample, lambda);
            if (!camera_ray) continue;
            ++camera_rays;
            FirstHit hit = first_hit(scene, camera_ray->ray);
            emitters += hit == FirstHit::Emitter;
            specular += hit == FirstHit::Specular;
        }
    if (camera_rays > 0) {
        probe.view_emitters = float(emitters) / camera_rays;
        probe.view_specular = float(specular) / camera_rays;
    }

    // Light rays in proportion to power, as light paths are started.
    Rng rng(0x5ce9e, 1);
    double behind_specular = 0, total = 0;
    for (int k = 0; k < count && scene.light_sampler; ++k) {
        std::optional<SampledLight> sampled = scene.light_sampler->sample(rng.uniform());
        if (!sampled) break;
        std::optional<LightLeSample> le = sampled->light->sample_le(rng.uniform2(), rng.uniform2(), lambda);
        if (!le || le->L.is_black()) continue;
        total += 1;
        Ray ray = le->ray;
        if (length_squared(le->n) > 0) ray = spawn_ray(ray.o, le->n, le->error_scale, ray.d, ray.time);
        behind_specular += first_hit(scene, ray) == FirstHit::Specular;
    }
    if (total > 0) probe.lights_behind_specular = float(behind_specular / total);
    return probe;
}

} // namespace caustica
