#include "materials/coating.h"

#include "core/scratch_buffer.h"
#include "params/constant_textures.h"
#include "spectral/sampled_wavelengths.h"

namespace caustica {

float Coating::hero_eta(const SampledWavelengths &lambda) const {
    const float e = (*eta)(lambda[0]);
    return e == 0 ? 1.f : e;
}

const LayeredBxDF *Coating::over(const BxDF *base, const TextureEvalContext &ctx,
                                 const SampledWavelengths &lambda, ScratchBuffer &scratch) const {
    auto *top = scratch.make<DielectricBxDF>(SampledSpectrum(hero_eta(lambda)), roughness.distribution(ctx));
    LayerMedium medium;
    medium.thickness = thickness->evaluate(ctx);
    medium.albedo = albedo->evaluate(ctx, lambda);
    for (int i = 0; i < NumWavelengths; ++i) medium.albedo[i] = clamp(medium.albedo[i], 0.f, 1.f);
    // |g| = 1 would be a delta lobe; the parser rejects such constants, textures are kept off it.
    medium.g = clamp(g->evaluate(ctx), -MaxAsymmetry, MaxAsymmetry);
    return scratch.make<LayeredBxDF>(top, base, medium, max_depth, n_samples, is_dispersive());
}

bool Coating::may_scatter() const {
    auto *c = dynamic_cast<const ConstantSpectrumTexture *>(albedo.get());
    if (!c) return true;
    for (int lambda = int(LambdaMin); lambda <= int(LambdaMax); ++lambda)
        if ((*c->spectrum())(float(lambda)) > 0) return true;
    return false;
}

} // namespace caustica
