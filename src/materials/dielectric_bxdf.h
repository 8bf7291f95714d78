// A dielectric interface (glass, water): Fresnel-weighted specular reflection and refraction
// when smooth, or the rough-interface microfacet model of Walter et al. 2007, "Microfacet Models
// for Refraction through Rough Surfaces" (eqs. 20-21, with the generalised half vector of
// eq. 16) over the GGX distribution with visible-normal sampling (Heitz 2018).
//
// eta is the index of the inside (the side -z points into) relative to the outside, one value
// per wavelength so that dispersion can be modelled. Reflection is exact for every wavelength
// (the direction does not depend on it). Refraction follows the hero wavelength (lane 0): when
// the sampled direction is a refraction through a wavelength-dependent eta, BSDFSample::
// dispersive is set so the integrator terminates the secondary wavelengths, whose lanes in the
// sample's f are then zero (their delta lies in another direction).
//
// Transmission in Radiance mode carries the 1/eta'^2 factor of radiance compression across the
// interface, where eta' is the index on wi's side over the index on wo's side; Importance mode
// (paths from lights) does not (Veach 1997, "Robust Monte Carlo Methods for Light Transport
// Simulation", section 5.2; Burley 2015, "Extending the Disney BRDF to a BSDF with Integrated
// Subsurface Scattering", section 2.2). Consequently f_importance(wo, wi) = f_radiance(wi, wo).
#pragma once

#include "materials/bxdf.h"
#include "materials/microfacet.h"
#include "materials/thin_film.h"

namespace caustica {

class DielectricBxDF final : public BxDF {
  public:
    // |eta - 1| below this for every wavelength: the interface is index-matched and invisible,
    // so light passes straight through (exactly what pbrt-v4 does for eta == 1, smooth or
    // rough). Outside this band the generalised half vector eta' wi + wo has length at least
    // |eta' - 1| >= 1e-4 (triangle inequality), so its direction keeps about three significant
    // digits in float even where wi is nearly -wo: the band is also the guard that keeps the
    // rough model's half vector robust near eta = 1.
    // A dispersive index can cross 1 (an index-matching liquid does, by design), leaving only
    // some lanes in the band. Those lanes see no interface either: they reflect nothing and
    // pass straight through, while the other lanes scatter as usual. A hero in the band samples
    // that straight-through delta; the other lanes' lobes lie elsewhere, so the sample
    // terminates them. Rough refraction samples of a hero outside the band terminate the
    // secondaries too: a matched lane's light does not go where they go. (Inside the band the
    // rough model itself degenerates: at eta' = 1 its transmission f grows as 1 / |wi + wo|^2,
    // which is not integrable around wi = -wo.)
    static constexpr float IndexMatchedTolerance = 1e-4f;
    // Rough transmission through a dispersive eta keeps the secondary wavelengths (each lane
    // evaluates f exactly with its own half vector) unless the lobe is narrower than this alpha
    // along either axis (the smaller of alpha_x and alpha_y: an anisotropic lobe that is narrow
    // along one axis does not overlap its neighbours there, whatever its width along the other).
    // The reason is variance, not bias: the secondaries are estimated with the hero's sampling
    // density, and their refracted lobes are offset from the hero's by the angular dispersion,
    // roughly delta_n * tan(theta) -- up to about 0.05 rad for dense flint glass over the
    // visible range. Lobes narrower than that offset barely overlap, so f_secondary / pdf_hero
    // becomes rare, huge spikes; wider lobes overlap enough to keep the ratio bounded.
    static constexpr float DispersiveAlphaThreshold = 0.05f;

    // With a film (thin_film.h), every lane reflects the film's reflectance over the interface
    // and transmits the rest; the film does not change directions, so it keeps all lanes. A
    // lane in the index-matched band still sees no interface, film or not: a free-standing film
    // (a soap bubble, air on both sides) is not modelled by this BxDF.
    DielectricBxDF(const SampledSpectrum &eta, const TrowbridgeReitzDistribution &distribution,
                   const ThinFilm &film = {});

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode mode) const override;
    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override;
    float pdf(Vec3f wo, Vec3f wi, TransportMode mode,
              SampleFlags flags = SampleFlags::All) const override;
    BxDFFlags flags() const override;

    // True when the lanes' etas differ, so refraction directions depend on wavelength.
    bool is_dispersive() const { return dispersive_; }
    bool is_index_matched() const { return index_matched_; }
    // Whether lane i's index is within IndexMatchedTolerance of 1, so that it sees no interface.
    bool is_matched_lane(int lane) const {
        return std::abs(eta_[lane] - 1) < IndexMatchedTolerance;
    }
    const SampledSpectrum &eta() const { return eta_; }

  private:
    bool specular() const { return index_matched_ || distribution_.effectively_smooth(); }
    // The reflectance that chooses between reflection and refraction when sampling, for light
    // meeting the interface (or a facet) with cosine cos_d: the Fresnel term of the single
    // index, or, where lanes reflect differently (a dispersive index, a film), the average over
    // the lanes. The average makes every lane's
    // reflection weight F_i / F at most NumWavelengths; the hero's F alone would give F_i / F_0,
    // unbounded where F_0 nearly vanishes (a hero index at or near 1 while other lanes reflect).
    float selection_reflectance(float cos_d) const;
    // Reflectance of one lane (Fresnel's, or the film's over the interface): zero for a lane in
    // the index-matched band.
    float lane_reflectance(float cos_d, int lane) const;
    std::optional<BSDFSample> sample_specular(Vec3f wo, float uc, TransportMode mode,
                                              SampleFlags flags) const;
    std::optional<BSDFSample> sample_rough(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                           SampleFlags flags) const;
    // Rough transmission value of wavelength `lane`.
    float rough_transmission(Vec3f wo, Vec3f wi, int lane, TransportMode mode) const;
    // Rough transmission of every lane when they share one index (no dispersion).
    SampledSpectrum rough_transmission_shared_index(Vec3f wo, Vec3f wi, TransportMode mode) const;

    SampledSpectrum eta_;
    ThinFilm film_;
    TrowbridgeReitzDistribution distribution_;
    bool dispersive_ = false, index_matched_ = false;
    // Some lanes, not all, are in the index-matched band.
    bool partly_matched_ = false;
};

} // namespace caustica
