#include "materials/subsurface_material.h"

#include "geometry/interaction.h"
#include "materials/fresnel.h"
#include "materials/normalized_fresnel_bxdf.h"
#include "materials/subsurface_entry_bxdf.h"

namespace caustica {

SubsurfaceMaterial::SubsurfaceMaterial(Coefficients coefficients, float g, float eta, MicrofacetRoughness roughness)
    : coefficients_(std::move(coefficients)), eta_(eta), roughness_(std::move(roughness)),
      table_(compute_beam_diffusion_table(g, eta)) {}

BSDF SubsurfaceMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                  ScratchBuffer &scratch) const {
    (void)lambda;
    const DielectricBxDF boundary(SampledSpectrum(eta_), roughness_.distribution(TextureEvalContext(si)));
    return BSDF(si.shading.n, si.shading.dpdu, scratch.make<SubsurfaceEntryBxDF>(boundary));
}

const SubsurfaceProfile &SubsurfaceMaterial::entry_profile(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                                           ScratchBuffer &scratch) const {
    const TextureEvalContext ctx(si);
    const Coefficients &c = coefficients_;
    SampledSpectrum sigma_a, sigma_s;
    if (c.sigma_a) {
        sigma_a = clamp_zero(c.sigma_a->evaluate(ctx, lambda) * c.scale);
        sigma_s = clamp_zero(c.sigma_s->evaluate(ctx, lambda) * c.scale);
    } else {
        SampledSpectrum r = c.reflectance->evaluate(ctx, lambda);
        for (int i = 0; i < NumWavelengths; ++i) r[i] = clamp(r[i], 0.f, 1.f);
        beam_diffusion_from_diffuse(table_, r, clamp_zero(c.mfp->evaluate(ctx, lambda) * c.scale), &sigma_a, &sigma_s);
    }
    return *scratch.make<BeamDiffusionProfile>(table_, sigma_a, sigma_s);
}

bool SubsurfaceMaterial::reflects_only_specularly(const SurfaceInteraction &si) const {
    return roughness_.distribution(TextureEvalContext(si)).effectively_smooth();
}

BSDF SubsurfaceMaterial::subsurface_exit_bsdf(const SurfaceInteraction &si, ScratchBuffer &scratch) const {
    return BSDF(si.shading.n, si.shading.dpdu, scratch.make<NormalizedFresnelBxDF>(eta_, fresnel_moment1(1 / eta_)));
}

} // namespace caustica
