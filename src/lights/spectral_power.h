// How much light the lights emit, in total and per wavelength: the light samplers choose lights
// by the first (light_sampler.h), and the scene fits its wavelength density to the second
// (spectral/wavelength_density.h).
#pragma once

#include "lights/light.h"

#include <utility>
#include <vector>

namespace caustica {

// A light's power integrated over the visible spectrum. A light of one colour (emission_spectrum)
// emits phi(lambda) = G S(lambda), with G the same at every wavelength: one phi at S's peak gives
// G, and the integral of S every nanometre does the rest, so that a light emitting only in a
// narrow line gets its share. Any other light (an environment image, whose texels are smooth
// RGB illuminant spectra) is estimated from phi at four wavelengths spread over the visible range.
float light_power(const Light &light);

// The lights' emitted spectral power at a wavelength, summed over lights: G S(lambda) for each
// light of one colour, exactly; a light of many colours (an environment image) counts as its
// visible power spread evenly over the visible range, which is what its smooth texel spectra
// nearly are.
class EmittedSpectralPower {
  public:
    explicit EmittedSpectralPower(const std::vector<const Light *> &lights);
    float operator()(float lambda) const;

  private:
    // Each distinct spectrum with the sum of its lights' G (meshes share one spectrum over
    // thousands of triangle lights).
    std::vector<std::pair<const Spectrum *, double>> coloured_;
    double flat_ = 0; // per nanometre
};

} // namespace caustica
