#include "integrators/common/reradiation.h"

#include "integrators/common/light_sampling.h"
#include "sampler/sampler.h"

namespace caustica {

SampledSpectrum sample_reradiated_lighting(const Scene &scene, const SurfaceInteraction &si, const BSDF &bsdf,
                                           const LightSampleContext &ctx, const SampledWavelengths &lambda,
                                           Sampler &sampler, uint64_t &rays, const Medium *medium) {
    const Reradiation &reradiation = *bsdf.reradiation();
    const ReradiationShift shift =
        sample_reradiation_shift(*reradiation.fluorophore, TransportMode::Radiance, lambda, sampler.get_1d());
    if (!shift) return SampledSpectrum(0.f);
    const ReradiationBxDF lobe(shift.albedo, reradiation);
    SampledWavelengths absorbed = lambda;
    absorbed.shift_to(shift.lambda);
    return sample_direct_lighting(scene, si, BSDF(bsdf.frame(), &lobe), ctx, absorbed, sampler, rays,
                                  TransportMode::Radiance, DirectLighting::WeightedAgainstBsdfSampling, medium);
}

} // namespace caustica
