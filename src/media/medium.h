// Participating media: what a ray travelling through a medium meets before it reaches the next
// surface. Caustica's media are homogeneous (pbrt-v4's "homogeneous"); the interface is what the
// integrators need from any medium, so that heterogeneous ones can be added beside it.
//
// Chromatic media: a path carries NumWavelengths wavelengths, and the medium has a different
// extinction for each. A medium samples a distance with the coefficients of one of them (the
// subpath's "lane") and reports the event's density under every wavelength's coefficients; the
// path combines the densities of all its events by multiple importance sampling over the
// wavelengths (integrators/common/path_segment.h, FreeFlightMIS). A medium that does not scatter
// at the carried wavelengths samples nothing: the event is the transmittance itself, with density
// 1 for every wavelength.
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
    // Per wavelength: the event's contribution f, T(t) sigma_s when scattered and T(t_max) when
    // passing (zero at terminated wavelengths), and its density had that wavelength's
    // coefficients sampled it, sigma_t T(t) and T(t_max) (all 1 when nothing was sampled).
    SampledSpectrum f{0.f}, density{1.f};
};

class Medium {
  public:
    virtual SampledSpectrum sigma_a(const SampledWavelengths &lambda) const = 0;
    virtual SampledSpectrum sigma_s(const SampledWavelengths &lambda) const = 0;
    virtual const HenyeyGreenstein &phase() const = 0;
    // Transmittance exp(-integral of sigma_t) along a straight segment of the given length.
    virtual SampledSpectrum transmittance(float distance, const SampledWavelengths &lambda) const = 0;
    // Samples where a ray entering the medium first scatters, within distance t_max (may be
    // Infinity), with the extinction of wavelength lambda[lane]; u_distance picks the distance.
    virtual MediumEvent sample_distance(float t_max, const SampledWavelengths &lambda, int lane,
                                        float u_distance) const = 0;
    // The material whose interior this medium is when the material made it for one entry point
    // (SampledHomogeneousMedium), else null.
    virtual const Material *interior_of() const { return nullptr; }
    // Scene analysis: true when its coefficients do not depend on wavelength (see
    // SceneFeatures::achromatic); false unless a medium shows it.
    virtual bool is_wavelength_independent() const { return false; }

  protected:
    // Media are owned through MediumPtr (made by make_shared, which destroys the concrete type)
    // or made in a path's scratch memory, which destroys nothing: no virtual destructor, so that
    // the latter is allowed.
    ~Medium() = default;
};

using MediumPtr = std::shared_ptr<const Medium>;

} // namespace caustica
