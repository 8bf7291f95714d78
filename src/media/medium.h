// Participating media: what a ray travelling through a medium meets before it reaches the next
// surface. Caustica's media are homogeneous (pbrt-v4's "homogeneous"); the interface is what the
// integrators need from any medium, so that heterogeneous ones can be added beside it.
//
// Chromatic media and hero wavelengths: the distance to a scattering event is sampled from the
// average of the NumWavelengths exponential densities (one wavelength's sigma_t picked at random
// with a fresh random number, then an exponential step with it), and every wavelength is weighted
// by its own f / (that average). This is the one-sample balance heuristic over the wavelengths
// (Veach and Guibas 1995; for spectral rendering Wilkie et al. 2014, "Hero Wavelength Spectral
// Sampling"), applied per event. Because the mixture does not depend on which wavelength is the
// hero, each event is unbiased on its own and no path-level ratio needs to be carried (pbrt-v4's
// r_u), which keeps light vertices and photons small; and since each component is one of the
// mixture's terms, every weight is at most NumWavelengths * sigma_s / sigma_t <= 4. After
// terminate_secondary() only the hero is sampled and weighted. A medium that does not scatter at
// the carried wavelengths samples nothing and weights by the transmittance.
#pragma once

#include "media/phase_function.h"
#include "spectral/sampled_spectrum.h"
#include "spectral/sampled_wavelengths.h"

#include <memory>

namespace caustica {

class Material;

// The outcome of sampling a free-flight distance along a ray segment of length t_max.
struct MediumEvent {
    // True: the path scatters at distance t inside the medium. False: it reaches t_max (the next
    // surface, or infinity) and t == t_max.
    bool scattered = false;
    float t = 0;
    // Throughput factor of the event, f / density per wavelength: T(t) sigma_s(t) over the
    // density of t when scattered, T(t_max) over the probability of passing otherwise.
    SampledSpectrum weight{0.f};
};

class Medium {
  public:
    virtual SampledSpectrum sigma_a(const SampledWavelengths &lambda) const = 0;
    virtual SampledSpectrum sigma_s(const SampledWavelengths &lambda) const = 0;
    virtual const HenyeyGreenstein &phase() const = 0;
    // Transmittance exp(-integral of sigma_t) along a straight segment of the given length.
    virtual SampledSpectrum transmittance(float distance, const SampledWavelengths &lambda) const = 0;
    // Samples where a ray entering the medium first scatters, within distance t_max (may be
    // Infinity). u_channel picks the wavelength whose density is used, u_distance the distance.
    virtual MediumEvent sample_distance(float t_max, const SampledWavelengths &lambda, float u_channel,
                                        float u_distance) const = 0;
    // The material whose interior this medium is when the material made it for one entry point
    // (SampledHomogeneousMedium), else null.
    virtual const Material *interior_of() const { return nullptr; }

  protected:
    // Media are owned through MediumPtr (made by make_shared, which destroys the concrete type)
    // or made in a path's scratch memory, which destroys nothing: no virtual destructor, so that
    // the latter is allowed.
    ~Medium() = default;
};

using MediumPtr = std::shared_ptr<const Medium>;

} // namespace caustica
