#include "integrators/common/reradiation.h"

#include "integrators/common/light_sampling.h"
#include "sampler/sampler.h"

namespace caustica {

std::optional<ReradiationSample> sample_reradiation(const Reradiation &reradiation, TransportMode mode,
                                                    const SampledWavelengths &lambda, float u) {
    const ReradiationShift shift = sample_reradiation_shift(*reradiation.fluorophore, mode, lambda, u);
    if (!shift) return std::nullopt;
    SampledWavelengths shifted = lambda;
    shifted.shift_to(shift.lambda);
    return ReradiationSample{ReradiationBxDF(shift.albedo, reradiation), shifted};
}

SampledSpectrum sample_reradiated_lighting(const Scene &scene, const SurfaceInteraction &si, const BSDF &bsdf,
                                           const LightSampleContext &ctx, const SampledWavelengths &lambda,
                                           Sampler &sampler, uint64_t &rays, const Medium *medium) {
    const std::optional<ReradiationSample> r =
        sample_reradiation(*bsdf.reradiation(), TransportMode::Radiance, lambda, sampler.get_1d());
    if (!r) return SampledSpectrum(0.f);
    return sample_direct_lighting(scene, si, BSDF(bsdf.frame(), &r->lobe), ctx, r->lambda, sampler, rays,
                                  TransportMode::Radiance, DirectLighting::WeightedAgainstBsdfSampling, medium);
}

} // namespace caustica
