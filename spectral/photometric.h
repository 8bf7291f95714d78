// Photometric conventions of pbrt-v4's emitters, its lights and emissive media (the PhysLight model
// of Langlands and Fascione):
// a light's spectrum only gives its colour. The spectrum is divided by its luminance integral
// (spectrum_to_photometric), so "L" or "I" of any spectrum means 1 nit (or 1 candela) times
// "scale", and the optional "power" / "illuminance" parameters then fix the absolute level.
#pragma once

#include "spectral/color.h"
#include "spectral/spectrum.h"

namespace caustica {

class RGBColorSpace;

// Integral of the spectrum against CIE ybar over integer nm (pbrt-v4's SpectrumToPhotometric).
// For an RGBIlluminantSpectrum only the colour space's illuminant counts, so that an RGB light's
// colour does not change its brightness: "rgb L [1 1 1]" has luminance exactly 1 after
// normalisation, and other colours have the luminance of their RGB in that space.
float spectrum_to_photometric(const Spectrum &s);

// Weights giving the luminance Y of a linear RGB value in the colour space (the Y row of its
// RGB-to-XYZ matrix; the white (1, 1, 1) has luminance 1).
RGB luminance_weights(const RGBColorSpace &cs);

}  // namespace caustica
