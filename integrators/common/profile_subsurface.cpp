#include "integrators/common/profile_subsurface.h"

#include "integrators/common/subsurface_probe.h"
#include "materials/profile_subsurface_material.h"
#include "sampler/sampler.h"

namespace caustica {

const ProfileSubsurfaceMaterial *profile_entry(const SurfaceInteraction &si, const BSDFSample &bs) {
    if (!bs.is_transmission() || !is_diffuse(bs.flags) || bs.is_specular()) return nullptr;
    if (!si.material->has_profile_subsurface() || dot(si.wo, si.shading.n) <= 0) return nullptr;
    return dynamic_cast<const ProfileSubsurfaceMaterial *>(si.material);
}

std::optional<ProfileExit> sample_profile_exit(const Scene &scene, const ProfileSubsurfaceMaterial &material,
                                               const SurfaceInteraction &entry, const SampledWavelengths &lambda,
                                               Sampler &sampler, ScratchBuffer &scratch, uint64_t &rays) {
    thread_local SubsurfaceProbeSampler probe;
    const SubsurfaceProfile &profile = material.entry_profile(entry, lambda, scratch);
    const float u_strategy = sampler.get_1d();
    const Vec2f u_plane = sampler.get_2d();
    ++rays;
    std::optional<SubsurfaceExit> exit = probe.sample(entry, profile, u_strategy, u_plane, scene);
    if (!exit) return {};
    ProfileExit result{exit->si, BSDF(), exit->weight * material.cavity_fade(entry.n, exit->si.n)};
    result.si.wo = -result.si.n;
    result.bsdf = material.subsurface_exit_bsdf(result.si, scratch);
    return result;
}

float profile_exit_density(const ProfileSubsurfaceMaterial &material, const SurfaceInteraction &entry, ScratchBuffer &scratch) {
    return material.subsurface_exit_bsdf(entry, scratch).pdf(-entry.n, entry.wo, TransportMode::Radiance);
}

} // namespace caustica
