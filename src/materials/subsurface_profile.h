// Radial diffusion profiles for subsurface scattering with a separable BSSRDF (Jensen et al. 2001;
// the factorisation of pbrt-v3, "Physically Based Rendering", 3rd ed., section 11.4).
//
// A profile R(r) is the diffuse reflectance per unit area at distance r from where light entered
// a flat semi-infinite medium: light entering at one point leaves within dA at distance r with
// probability R(r) dA, so the integral over the plane, 2 pi int_0^inf r R(r) dr, is the medium's
// total diffuse reflectance (its multiple-scattering albedo). R includes that albedo; it has units
// of 1 / length^2 and is given for the path's NumWavelengths wavelengths at once.
//
// Each wavelength ("channel") can also be importance sampled on its own: sample_radius() draws r
// with density 2 pi r pdf_area(r) on [0, inf), i.e. a point of the plane with density
// pdf_area(r) per unit AREA at distance r from the entry point once an angle is drawn uniformly.
// Per unit area is the measure the probe-ray sampler (integrators/common/subsurface_probe.h)
// needs, since it projects planar samples onto the surface.
#pragma once

#include "spectral/sampled_spectrum.h"

namespace caustica {

// Fraction of a channel's energy within its max_radius(): probe rays reach this far and no
// further, so the estimate misses the remaining 0.1% (the same cut-off as pbrt-v3's
// Sample_Sr(ch, 0.999)).
inline constexpr double ProfileEnergyWithinMaxRadius = 0.999;

class SubsurfaceProfile {
  public:

    // R(r) for every channel, per unit area (1 / length^2), albedo included.
    virtual SampledSpectrum evaluate(float r) const = 0;
    // Radius drawn for channel from u in [0, 1), monotone in u. A channel without energy
    // (max_radius(channel) == 0) returns 0.
    virtual float sample_radius(int channel, float u) const = 0;
    // Density of sample_radius(c, .) for every channel c, per unit area of the plane at distance r
    // (the radial density divided by 2 pi r).
    virtual SampledSpectrum pdf_area(float r) const = 0;
    // 2 pi int_0^inf r R(r) dr per channel: the total diffuse reflectance.
    virtual SampledSpectrum albedo() const = 0;
    // Radius holding ProfileEnergyWithinMaxRadius of the channel's energy; 0 when the channel has
    // none (it is then never sampled).
    virtual float max_radius(int channel) const = 0;

  protected:
    // Profiles live in a ScratchBuffer or by value, and are never destroyed through a base
    // pointer.
    ~SubsurfaceProfile() = default;
};

} // namespace caustica
