// Multiple importance sampling over the carried wavelengths for one subpath's
// wavelength-dependent sampling decisions (Wilkie et al. 2014, "Hero Wavelength Spectral
// Sampling"; pbrt-v4's r_u ratios): the free-flight distances through a chromatic medium, and the
// directions refracted by a rough dispersive interface (BxDF::has_lane_lobes). Either can be
// sampled with any one wavelength's coefficients. The subpath picks one, its lane, uniformly at
// its first such decision and makes all of them with it; for each wavelength i it then carries
// f_i / mean_k p_k, with p_k the density of all its decisions so far under wavelength k: the
// one-sample balance heuristic over the NumWavelengths ways of sampling the whole subpath (Veach
// and Guibas 1995). That weight is at most NumWavelengths f_i / p_i, the weight had wavelength i
// sampled alone: bounded over the whole subpath, however many decisions it makes. Weighing each
// decision on its own, with a fresh choice of wavelength each time, bounds each one's weight but
// lets their product become heavy-tailed over long walks: through strongly chromatic media
// (docs/media.md has the measurement), and through narrow dispersive lobes, whose fresh lane
// keeps a wavelength alive only when it repeats (tests/integrators/rough_dispersion_test.cpp).
//
// The lane is chosen independently for each subpath, so when a camera and a light subpath are
// joined (a connection or a merge) their two weights multiply into the balance heuristic over
// the NumWavelengths^2 ways of sampling the pair: the stored throughput of a vertex is complete.
// The integrators' MIS over strategies only needs densities that are the same function of the
// path for every strategy (a partition of unity); for lane lobes those are the lanes' mean
// (BxDF::pdf), for media the lane-independent phase function.
//
// Terminating the secondary wavelengths later does not change which wavelength samples: the
// hero's weight stays the balance heuristic over the same ways. A subpath whose secondaries are
// already terminated when it first needs a lane (one wavelength per path, or a dispersive
// refraction before) samples with the hero alone and carries no weights: the other lanes carry
// nothing that the mixture would serve.
#pragma once

#include "sampler/sampler.h"
#include "spectral/sampled_wavelengths.h"

#include <algorithm>

namespace caustica {

class SpectralMIS {
  public:
    // The lane that samples this subpath's wavelength-dependent decisions; the first call draws
    // one sampler dimension unless the secondaries are terminated.
    int lane(const SampledWavelengths &lambda, Sampler &sampler) {
        if (lane_ < 0) {
            mixed_ = !lambda.secondary_terminated();
            lane_ = mixed_ ? std::min(int(sampler.get_1d() * NumWavelengths), NumWavelengths - 1) : 0;
        }
        return lane_;
    }
    // Records a decision made with the lane, given every wavelength's density of it (the lane's
    // entry is the one used, and positive): returns the factor w such that f_i w is f_i / mean_k
    // p_k for the subpath so far divided by that before this decision, the factor the
    // throughput takes in place of 1 / p_lane.
    float inverse_density(const SampledSpectrum &lane_densities) {
        const float own = lane_densities[lane_];
        if (!mixed_) return 1 / own;
        const SampledSpectrum density = density_ * (lane_densities / own);
        const float before = density_.average(), after = density.average();
        density_ = density / density.max_value();
        return before / (own * after);
    }

  private:
    int lane_ = -1; // -1 until the subpath makes its first wavelength-dependent decision
    bool mixed_ = true;
    // Per wavelength, the density of the subpath's decisions so far over the lane's, scaled so
    // that the largest is 1 (only their ratios to each other matter).
    SampledSpectrum density_{1.f};
};

} // namespace caustica
