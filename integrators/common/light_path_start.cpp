#include "integrators/common/light_path_start.h"

#include "lights/light_sampler.h"
#include "sampler/sampler.h"
#include "scene/scene.h"

namespace caustica {

std::optional<LightPathStart> start_light_path(const Scene &scene, Sampler &sampler, const SampledWavelengths &lambda) {
    auto chosen = scene.light_sampler->sample(sampler.get_1d());
    const Vec2f u_position = sampler.get_2d(), u_direction = sampler.get_2d();
    if (!chosen) return std::nullopt;
    auto les = chosen->light->sample_le(u_position, u_direction, lambda);
    if (!les || les->L.is_black() || !(les->pdf_pos > 0) || !(les->pdf_dir > 0)) return std::nullopt;
    LightPathStart start{chosen->light, chosen->pmf, *les};
    if (les->n != Vec3f{}) start.cos_origin = abs_dot(les->n, normalize(les->ray.d));
    start.flux = les->L * (start.cos_origin / (chosen->pmf * les->pdf_pos * les->pdf_dir));
    return start;
}

} // namespace caustica
