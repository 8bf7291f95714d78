// Reflection from a metal: a perfect mirror when smooth, else the Torrance-Sparrow microfacet
// model with the GGX distribution (Walter et al. 2007, "Microfacet Models for Refraction through
// Rough Surfaces", eq. 20), weighted by the exact conductor Fresnel term for the spectral
// complex index of refraction eta + i k.
#pragma once

#include "materials/bxdf.h"
#include "materials/microfacet.h"

namespace caustica {

class ConductorBxDF final : public BxDF {
  public:
    ConductorBxDF(const TrowbridgeReitzDistribution &distribution, const SampledSpectrum &eta,
                  const SampledSpectrum &k)
        : distribution_(distribution), eta_(eta), k_(k) {}

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode mode) const override;
    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override;
    float pdf(Vec3f wo, Vec3f wi, TransportMode mode,
              SampleFlags flags = SampleFlags::All) const override;
    BxDFFlags flags() const override {
        return distribution_.effectively_smooth() ? BxDFSpecularReflection : BxDFGlossyReflection;
    }

  private:
    TrowbridgeReitzDistribution distribution_;
    SampledSpectrum eta_, k_;
};

} // namespace caustica
