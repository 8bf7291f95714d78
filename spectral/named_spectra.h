// Spectra that scene files refer to by name (pbrt-v4's named spectra, plus ours):
//  - "glass-*", "gem-*", "water": refractive indices (ior.h);
//  - "metal-{Ag,Al,Au,Cu,CuZn,MgO,TiO2}-{eta,k}": complex refractive indices (metal_data.h);
//  - "stdillum-A", "stdillum-D50", "stdillum-D65", "stdillum-F1".."stdillum-F12",
//    "illum-acesD60": illuminants normalised to luminance 1 (integral of s ybar = CIE_Y_integral);
//  - "<camera sensor>_r", "_g", "_b": camera sensors' responses (camera_sensor_data.h).
#pragma once

#include "spectral/spectrum.h"

#include <string>
#include <vector>

namespace caustica {

// The shared spectrum of that name, or null if there is none.
SpectrumPtr get_named_spectrum(const std::string &name);
// Every name get_named_spectrum knows, sorted.
std::vector<std::string> named_spectrum_names();

} // namespace caustica
