#include "materials/dielectric_material.h"

#include "geometry/interaction.h"
#include "materials/dielectric_bxdf.h"
#include "materials/thin_dielectric_bxdf.h"

namespace caustica {

void spectrum_range(const Spectrum &s, float *min_value, float *max_value) {
    *min_value = Infinity;
    *max_value = -Infinity;
    for (int lambda = int(LambdaMin); lambda <= int(LambdaMax); ++lambda) {
        float v = s(float(lambda));
        if (std::isnan(v)) {
            *min_value = *max_value = v;
            return;
        }
        *min_value = std::min(*min_value, v);
        *max_value = std::max(*max_value, v);
    }
}

DielectricMaterial::DielectricMaterial(SpectrumPtr eta, MicrofacetRoughness roughness,
                                       SpectrumPtr sigma_a, FilmLayer film)
    : eta_(std::move(eta)), roughness_(std::move(roughness)), sigma_a_(std::move(sigma_a)),
      film_(std::move(film)) {
    float lo, hi;
    spectrum_range(*eta_, &lo, &hi);
    dispersive_ = !eta_->is_constant() && lo != hi;
    bool index_matched = std::abs(lo - 1) < DielectricBxDF::IndexMatchedTolerance &&
                         std::abs(hi - 1) < DielectricBxDF::IndexMatchedTolerance;
    specular_ = index_matched || roughness_.may_be_smooth();
}

BSDF DielectricMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                  ScratchBuffer &scratch) const {
    TextureEvalContext ctx(si);
    auto *bxdf = scratch.make<DielectricBxDF>(eta_->sample(lambda), roughness_.distribution(ctx),
                                              film_.at(ctx, lambda));
    return BSDF(si.shading.n, si.shading.dpdu, bxdf);
}

BSDF ThinDielectricMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                                      ScratchBuffer &scratch) const {
    const float thickness = film_thickness_ ? std::max(film_thickness_->evaluate(TextureEvalContext(si)), 0.f) : 0.f;
    SampledSpectrum wavelengths;
    for (int i = 0; i < NumWavelengths; ++i) wavelengths[i] = lambda[i];
    auto *bxdf = scratch.make<ThinDielectricBxDF>(eta_->sample(lambda), thickness, wavelengths);
    return BSDF(si.shading.n, si.shading.dpdu, bxdf);
}

bool ThinDielectricMaterial::is_wavelength_independent() const {
    if (!is_flat(*eta_)) return false;
    if (!film_thickness_) return true;
    const float *constant = film_thickness_->constant_value();
    return constant && *constant == 0;
}

} // namespace caustica
