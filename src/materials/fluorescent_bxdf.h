// The two parts of a fluorescent surface (fluorophore.h), each a Lambertian lobe:
//  - FluorescentBxDF, what the BSDF interface shows: the light that keeps its wavelength,
//    reflected by the substrate after the dye let it through, f = rho (1 - a) / pi;
//  - ReradiationBxDF, the light that changes wavelength, which the shared walk samples and
//    evaluates itself (integrators/common/reradiation.h), because its value links two
//    wavelengths: it is made for one sampled wavelength shift at a time.
// A path chooses between them with a probability that depends on the transport mode and only on
// the set of carried wavelengths, never on which of them is the hero, so that the choice treats
// every rotation of the set alike and the hero-wavelength estimator stays unbiased. The elastic
// lobe's pdf and sample_f include its share of that choice: sample_f returns nothing for the
// re-radiation's share of uc, and pdf integrates to the elastic share. A walk that does not
// re-radiate therefore treats the dye as an absorber, consistently with its densities.
#pragma once

#include "core/sampling.h"
#include "materials/bxdf.h"
#include "materials/fluorophore.h"

namespace caustica {

// What a walk needs to re-radiate at a vertex: the dye, and the probability of choosing the
// re-radiation in each transport mode (the elastic lobe has the rest).
struct Reradiation {
    const Fluorophore *fluorophore = nullptr;
    float radiance_probability = 0, importance_probability = 0;
    float probability(TransportMode mode) const {
        return mode == TransportMode::Radiance ? radiance_probability : importance_probability;
    }
};

// A Lambertian lobe chosen with probability `share` of the sample space's uc in [skip, skip + share).
class SharedLambertianBxDF : public BxDF {
  public:
    SharedLambertianBxDF(const SampledSpectrum &albedo, float radiance_share, float importance_share,
                         float radiance_skip, float importance_skip)
        : albedo_(albedo), share_{radiance_share, importance_share}, skip_{radiance_skip, importance_skip} {}

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return {};
        return albedo_ * InvPi;
    }
    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override {
        const float skip = skip_[int(mode)];
        if (!allows(flags, SampleFlags::Reflection) || !(uc >= skip && uc < skip + share_[int(mode)])) return {};
        BSDFSample s;
        s.wi = sample_cosine_hemisphere(u);
        if (wo.z < 0) s.wi.z = -s.wi.z;
        s.pdf = share_[int(mode)] * cosine_hemisphere_pdf(std::abs(s.wi.z));
        if (s.pdf == 0) return {};
        s.f = albedo_ * InvPi;
        s.flags = BxDFDiffuseReflection;
        return s;
    }
    float pdf(Vec3f wo, Vec3f wi, TransportMode mode, SampleFlags flags = SampleFlags::All) const override {
        if (!allows(flags, SampleFlags::Reflection) || !same_hemisphere(wo, wi)) return 0;
        return share_[int(mode)] * cosine_hemisphere_pdf(std::abs(wi.z));
    }
    BxDFFlags flags() const override { return BxDFDiffuseReflection; }

  protected:
    ~SharedLambertianBxDF() = default;

  private:
    SampledSpectrum albedo_;
    float share_[2], skip_[2]; // indexed by TransportMode
};

// The elastic part: chosen when uc >= the re-radiation probability.
class FluorescentBxDF final : public SharedLambertianBxDF {
  public:
    FluorescentBxDF(const SampledSpectrum &elastic_albedo, const Reradiation &reradiation)
        : SharedLambertianBxDF(elastic_albedo, 1 - reradiation.radiance_probability,
                               1 - reradiation.importance_probability, reradiation.radiance_probability,
                               reradiation.importance_probability),
          reradiation_(reradiation) {}
    const Reradiation *reradiation() const override { return &reradiation_; }

  private:
    Reradiation reradiation_;
};

// The re-radiated part for one sampled shift: albedo[j] = pi f(shift) / (density of the sampled
// wavelength) for carried wavelength j; chosen when uc < the re-radiation probability.
class ReradiationBxDF final : public SharedLambertianBxDF {
  public:
    ReradiationBxDF(const SampledSpectrum &albedo, const Reradiation &reradiation)
        : SharedLambertianBxDF(albedo, reradiation.radiance_probability, reradiation.importance_probability, 0, 0) {}
};

} // namespace caustica
