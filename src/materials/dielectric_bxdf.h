// A dielectric interface (glass, water): Fresnel-weighted specular reflection and refraction
// when smooth, or the rough-interface microfacet model of Walter et al. 2007, "Microfacet Models
// for Refraction through Rough Surfaces" (eqs. 20-21, with the generalised half vector of
// eq. 16) over the GGX distribution with visible-normal sampling (Heitz 2018).
//
// eta is the index of the inside (the side -z points into) relative to the outside, one value
// per wavelength so that dispersion can be modelled. Reflection is exact for every wavelength
// (the direction does not depend on it). Smooth refraction through a wavelength-dependent eta
// follows the hero wavelength (lane 0) and sets BSDFSample::dispersive, so the integrator
// terminates the secondary wavelengths, whose lanes in the sample's f are then zero (their delta
// lies in another direction). Rough refraction through it keeps every wavelength: each lane's
// transmission lobe is its own (the lane lobes of BxDF::has_lane_lobes), so the BxDF samples as
// any one lane would (its facets refract by its index, its own Fresnel term chooses the lobe) and
// reports every lane's density, and the subpath's spectral MIS weighs each wavelength by
// f_i / mean_k p_k (integrators/common/spectral_mis.h). That weight is at most NumWavelengths
// f_i / p_i = NumWavelengths G / G1 (over eta'^2 for radiance), bounded however narrow the lobes,
// where weighing the secondaries by the hero's density alone, f_i / p_0, diverges at the edge of
// the hero's lobe.
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
    const DielectricBxDF *regularized(ScratchBuffer &scratch) const override {
        return scratch.make<DielectricBxDF>(eta_, distribution_.regularized(), film_);
    }

    // Rough and dispersive, with no lane in the index-matched band (where a lane's lobe is a
    // delta, and the hero alone is followed as on a smooth interface).
    bool has_lane_lobes() const override { return lane_lobes_; }
    std::optional<BSDFSample> sample_f_as(int lane, Vec3f wo, float uc, Vec2f u, TransportMode mode) const override;
    // Per lane, the density with which sample_f_as(that lane, ...) returns wi.
    SampledSpectrum lane_pdfs(Vec3f wo, Vec3f wi, SampleFlags flags = SampleFlags::All) const;

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
    // The reflectance that chooses the lobe when sampling as `lane`: with lane lobes, the lane's
    // own, so that each lane samples its own BSDF exactly up to G / G1 (and the spectral MIS
    // bounds a whole subpath by NumWavelengths, where the average's ratios F_i / F multiply
    // from vertex to vertex); otherwise selection_reflectance.
    float choice_reflectance(float cos_d, int lane) const;
    // Reflectance of one lane (Fresnel's, or the film's over the interface): zero for a lane in
    // the index-matched band.
    float lane_reflectance(float cos_d, int lane) const;
    std::optional<BSDFSample> sample_specular(Vec3f wo, float uc, TransportMode mode,
                                              SampleFlags flags) const;
    // Samples the rough interface as wavelength `lane` would: its facets refract by its index.
    std::optional<BSDFSample> sample_rough(Vec3f wo, float uc, Vec2f u, TransportMode mode, SampleFlags flags,
                                           int lane) const;
    // The density with which sample_rough(..., lane) returns wi.
    float lane_pdf(Vec3f wo, Vec3f wi, int lane, SampleFlags flags) const;
    // Every lane's density of reflecting off facet wm: the facet's visible-normal density times
    // the lane's probability of choosing reflection there.
    SampledSpectrum reflection_lane_pdfs(Vec3f wo, Vec3f wm, SampleFlags flags) const;
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
    bool lane_lobes_ = false;
};

} // namespace caustica
