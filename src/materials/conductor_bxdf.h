// Reflection from a metal: a perfect mirror when smooth, else the Torrance-Sparrow microfacet
// model with the GGX distribution (Walter et al. 2007, "Microfacet Models for Refraction through
// Rough Surfaces", eq. 20), weighted by the exact conductor Fresnel term for the spectral
// complex index of refraction eta + i k, or by the reflectance of a thin film over the metal
// (thin_film.h) where the surface has one, on the mirror and on every microfacet alike.
#pragma once

#include "materials/bxdf.h"
#include "materials/microfacet.h"
#include "materials/thin_film.h"

namespace caustica {

class ConductorBxDF final : public BxDF {
  public:
    ConductorBxDF(const TrowbridgeReitzDistribution &distribution, const SampledSpectrum &eta,
                  const SampledSpectrum &k, const ThinFilm &film = {})
        : distribution_(distribution), eta_(eta), k_(k), film_(film) {}

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode mode) const override;
    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override;
    float pdf(Vec3f wo, Vec3f wi, TransportMode mode,
              SampleFlags flags = SampleFlags::All) const override;
    BxDFFlags flags() const override {
        return distribution_.effectively_smooth() ? BxDFSpecularReflection : BxDFGlossyReflection;
    }

    const BxDF *regularized(ScratchBuffer &scratch) const override {
        return scratch.make<ConductorBxDF>(distribution_.regularized(), eta_, k_, film_);
    }

  private:
    // Reflectance for light meeting the metal (or one microfacet) with cosine cos_i.
    SampledSpectrum fresnel(float cos_i) const;

    TrowbridgeReitzDistribution distribution_;
    SampledSpectrum eta_, k_;
    ThinFilm film_;
};

} // namespace caustica
