#include "materials/fluorescent_material.h"

#include "geometry/interaction.h"
#include "materials/fluorescent_bxdf.h"

namespace caustica {

namespace {

// The share of a choice between two parts of albedos a (re-radiated) and b (elastic), with
// every existing part kept at least a tenth, so that neither estimate's weight grows without
// bound where one part is faint.
float choice_probability(float a, float b) {
    if (!(a > 0)) return 0;
    if (!(b > 0)) return 1;
    return clamp(a / (a + b), 0.1f, 0.9f);
}

} // namespace

BSDF FluorescentMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                   ScratchBuffer &scratch) const {
    const SampledSpectrum rho = reflectance_->evaluate(TextureEvalContext(si), lambda);
    SampledSpectrum elastic;
    float radiance_albedo = 0, importance_albedo = 0;
    for (int i = 0; i < NumWavelengths; ++i) {
        elastic[i] = clamp(rho[i], 0.f, 1.f) * (1 - dye_->absorption(lambda[i]));
        radiance_albedo += dye_->radiance_albedo(lambda[i]);
        importance_albedo += dye_->importance_albedo(lambda[i]);
    }
    // Means over the carried set (the sums' common factor cancels), the same for all its rotations.
    const float elastic_albedo = elastic.average() * NumWavelengths;
    Reradiation reradiation{dye_.get(), choice_probability(radiance_albedo, elastic_albedo),
                            choice_probability(importance_albedo, elastic_albedo)};
    return BSDF(si.shading.n, si.shading.dpdu, scratch.make<FluorescentBxDF>(elastic, reradiation));
}

} // namespace caustica
