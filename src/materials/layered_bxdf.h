// A coated surface: a dielectric interface (the coat) over an opaque base (a diffuse or a
// conductor BxDF), with a homogeneous slab of unit extinction between them, of the given
// thickness, single-scattering albedo and Henyey-Greenstein asymmetry g. This is pbrt-v4's
// LayeredBxDF (Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., section 14.3),
// an implementation of the position-free Monte Carlo estimators of Guo, Hasan, Yan and Zhao 2018,
// "Position-Free Monte Carlo Simulation for Arbitrary Layered BSDFs".
//
// Nothing here is tabulated: f, pdf and sample_f each run random walks between the two
// interfaces, using the interfaces' own sampling routines.
//  - f(wo, wi) is an unbiased estimate, averaged over nsamples walks that enter through the coat
//    towards wo, with next-event estimation towards a direction sampled from wi through the coat
//    (Guo et al. 2018 section 5: the walk is connected at each vertex to the "virtual light"
//    below wi, MIS-weighted against continuing it). Its random numbers come from a generator
//    seeded by hashing wo and wi, so the same query always returns the same value: f stays a
//    function, and an integrator that evaluates it twice sees one value.
//  - sample_f follows one walk to its exit: the sample's f / pdf is the walk's throughput, an
//    unbiased weight, but neither f nor pdf is f(wo, wi) or the marginal density of wi. The sample
//    is then marked pdf_is_proportional, and MIS asks pdf() instead.
//  - pdf(wo, wi) estimates the density of sample_f from the single- and double-transmission
//    paths only, mixed with a uniform density over the sphere (weight 0.1, as pbrt-v4 does) so
//    that no direction sample_f can reach has an estimate of zero. It is used for MIS weights
//    only, where any density is unbiased.
//
// The surface is two-sided: a direction below the base is mirrored to the coat's side, as if
// the coating were on both faces. The base is opaque, so there is no transmission.
//
// A dispersive coat (an eta that varies with wavelength) is refracted with the hero
// wavelength's index for every lane (the caller passes that index), and every sample that
// crossed the coat is marked dispersive, so the integrator keeps the hero alone from there on:
// pbrt-v4 terminates the secondary wavelengths as soon as it builds the BSDF. Values from f() at
// the vertex itself (next-event estimation there) still carry the secondaries, computed with
// the hero's index.
#pragma once

#include "materials/bxdf.h"
#include "materials/dielectric_bxdf.h"
#include "media/phase_function.h"

namespace caustica {

struct LayerMedium {
    float thickness = 0.01f;  // in units of the mean free path (unit extinction)
    SampledSpectrum albedo;   // zero: a clear slab, no scattering or absorption inside
    float g = 0;
};

class LayeredBxDF final : public BxDF {
  public:
    // top and bottom live at least as long as this BxDF (in the same ScratchBuffer). bottom must
    // be a reflection-only BxDF. max_depth bounds each walk's scattering events; n_samples is
    // the number of walks averaged by f() and pdf().
    LayeredBxDF(const DielectricBxDF *top, const BxDF *bottom, const LayerMedium &medium, int max_depth,
                int n_samples, bool dispersive_coat);

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode mode) const override;
    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override;
    float pdf(Vec3f wo, Vec3f wi, TransportMode mode,
              SampleFlags flags = SampleFlags::All) const override;
    // A smooth coat adds a specular lobe; the base (or a scattering slab) adds a diffuse or
    // glossy one, so a smooth coat over a diffuse base is both specular and diffuse: integrators
    // treat it as non-specular (visible points, merging, connections) while its samples through
    // the coat's delta are flagged specular.
    BxDFFlags flags() const override;
    // The coat's and the base's lobes widened (pbrt-v4 regularises both).
    const BxDF *regularized(ScratchBuffer &scratch) const override {
        return scratch.make<LayeredBxDF>(top_->regularized(scratch), bottom_->regularized(scratch), medium_, max_depth_,
                                         n_samples_, dispersive_coat_);
    }

  private:
    // Density with which the connection strategy of f() reaches the internal direction w (going
    // up to the coat): that of sampling -w through the coat from wi, in the adjoint mode. The
    // MIS weights of the two strategies that find a path leaving by w need both densities over
    // the same variable, w; pbrt-v4 weighs the sampled exit with the coat's density of wi given
    // -w instead, a density over the outside direction, so its two weights do not sum to one
    // and its f is biased for rough coats (by several percent at alpha 0.3; see
    // layered_bxdf_test.cpp).
    float virtual_light_pdf(Vec3f wi, Vec3f w, TransportMode mode) const;
    // Beer-Lambert transmittance of the unit-extinction slab over a height difference dz along w.
    static float transmittance(float dz, Vec3f w);

    const DielectricBxDF *top_;
    const BxDF *bottom_;
    LayerMedium medium_;
    HenyeyGreenstein phase_;
    int max_depth_, n_samples_;
    bool dispersive_coat_;
};

} // namespace caustica
