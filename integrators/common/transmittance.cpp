#include "integrators/common/transmittance.h"

#include "media/medium_interface.h"
#include "scene/scene.h"

namespace caustica {

SampledSpectrum transmittance(const Scene &scene, Ray ray, const Medium *medium,
                              const SampledWavelengths &lambda, uint64_t &rays) {
    ++rays;
    if (!scene.features.media && !scene.features.medium_boundaries)
        return SampledSpectrum(scene.occluded(ray) ? 0.f : 1.f);

    const bool bounded = ray.t_max < Infinity;
    const Vec3f target = bounded ? ray.at(ray.t_max) : Vec3f{};
    SampledSpectrum T(1.f);
    while (true) {
        SurfaceInteraction si;
        bool hit = scene.intersect(ray, &si);
        if (hit && si.material) return SampledSpectrum(0.f);
        if (medium) {
            const float speed = length(ray.d);
            T *= medium->transmittance(Ray{ray.o, ray.d / speed}, (hit ? si.t : ray.t_max) * speed, lambda);
            if (T.is_black()) return T;
        }
        if (!hit) return T;
        // A boundary between media: continue on the other side, towards the same target.
        medium = medium_after(si, ray.d, medium);
        ray = bounded ? Ray{offset_ray_origin(si.p, si.n, si.error_scale, ray.d), {}, 1, ray.time}
                      : si.spawn_ray(ray.d);
        if (bounded) ray.d = target - ray.o;
        ++rays;
    }
}

} // namespace caustica
