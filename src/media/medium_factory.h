// Creates media from MakeNamedMedium directives.
//
// "homogeneous" (pbrt-v4's parameters): "spectrum sigma_a" and "spectrum sigma_s" (spectra or
// rgb, per unit length; default 1), "float scale" (multiplies both, default 1, so coefficients
// given per millimetre render a scene modelled in metres with scale 1000), "float g" (the
// Henyey-Greenstein asymmetry, default 0, in (-1, 1)), and "string preset", the name of one of
// Jensen et al. 2001's measured materials (see materials/subsurface_coefficients.h), whose
// coefficients are per millimetre and replace sigma_a and sigma_s (the reduced scattering
// coefficient, for isotropic scattering: keep g = 0). Emission ("Le") is not
// supported: a non-zero Le is an error rather than silently dark.
#pragma once

#include "media/medium.h"
#include "params/parameters.h"

#include <string>

namespace caustica {

MediumPtr create_medium(const std::string &type, const ParameterDictionary &params, const SourceLocation &loc);

} // namespace caustica
