#include "integrators/common/medium_emission.h"

#include "integrators/common/light_path_start.h"
#include "media/medium.h"
#include "scene/scene.h"

namespace caustica {

float mean_extinction(const Medium &medium, Vec3f p, const SampledWavelengths &lambda) {
    const MediumProperties mp = medium.properties(p, lambda);
    return (mp.sigma_a + mp.sigma_s).average();
}

const Light *medium_emitter_of(const Scene &scene, const Medium *medium) {
    for (const LightPtr &emitter : scene.medium_emitters)
        if (emitter->medium() == medium) return emitter.get();
    return nullptr;
}

float medium_start_density(const Scene &scene, const Light &emitter, Vec3f p) {
    float pdf_pos, pdf_dir;
    emitter.pdf_le(Ray{p, Vec3f{0, 0, 1}, Infinity}, Vec3f{}, &pdf_pos, &pdf_dir);
    return light_path_start_pmf(scene, emitter) * pdf_pos;
}

} // namespace caustica
