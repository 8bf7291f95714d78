#include "materials/hair_material.h"

#include "geometry/interaction.h"
#include "materials/hair_bxdf.h"

#include <memory>

namespace caustica {

namespace {

float concentration(const FloatTexturePtr &t, const TextureEvalContext &ctx) {
    return t ? std::max(0.f, t->evaluate(ctx)) : 0.f;
}

bool is_constant(const FloatTexturePtr &t) { return !t || t->constant_value(); }

} // namespace

HairMaterial::HairMaterial(Absorption absorption, FloatTexturePtr eta, FloatTexturePtr beta_m,
                           FloatTexturePtr beta_n, FloatTexturePtr alpha)
    : absorption_(std::move(absorption)), eta_(std::move(eta)), beta_m_(std::move(beta_m)),
      beta_n_(std::move(beta_n)), alpha_(std::move(alpha)) {
    const Absorption &a = absorption_;
    if (!a.sigma_a && !a.color && is_constant(a.eumelanin) && is_constant(a.pheomelanin)) {
        const TextureEvalContext none;
        concentration_sigma_a_ = std::make_shared<RGBUnboundedSpectrum>(HairBxDF::sigma_a_from_concentration(
            concentration(a.eumelanin, none), concentration(a.pheomelanin, none)));
    }
}

SampledSpectrum HairMaterial::sigma_a(const TextureEvalContext &ctx, const SampledWavelengths &lambda,
                                      float beta_n) const {
    const Absorption &a = absorption_;
    if (a.sigma_a) return clamp_zero(a.sigma_a->evaluate(ctx, lambda));
    if (a.color) {
        SampledSpectrum c = a.color->evaluate(ctx, lambda);
        for (int i = 0; i < NumWavelengths; ++i) c[i] = clamp(c[i], 0.f, 1.f);
        return HairBxDF::sigma_a_from_reflectance(c, beta_n);
    }
    if (concentration_sigma_a_) return concentration_sigma_a_->sample(lambda);
    return HairBxDF::sigma_a_from_concentration(concentration(a.eumelanin, ctx), concentration(a.pheomelanin, ctx))
        .sample(lambda);
}

BSDF HairMaterial::get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                            ScratchBuffer &scratch) const {
    const TextureEvalContext ctx(si);
    // pbrt-v4 keeps the roughnesses in [0.01, 1].
    const float beta_m = clamp(beta_m_->evaluate(ctx), 0.01f, 1.f);
    const float beta_n = clamp(beta_n_->evaluate(ctx), 0.01f, 1.f);
    const float eta = std::max(eta_->evaluate(ctx), 1e-4f);
    const float h = -1 + 2 * si.uv.y;
    auto *bxdf = scratch.make<HairBxDF>(h, eta, sigma_a(ctx, lambda, beta_n), beta_m, beta_n, alpha_->evaluate(ctx));
    return BSDF(si.shading.n, si.shading.dpdu, bxdf);
}

bool HairMaterial::is_wavelength_independent() const {
    if (absorption_.sigma_a) return absorption_.sigma_a->is_wavelength_independent();
    if (absorption_.color) return absorption_.color->is_wavelength_independent();
    return false;
}

} // namespace caustica
