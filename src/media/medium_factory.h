// Creates media from MakeNamedMedium directives, with pbrt-v4's parameters and defaults.
//
// "homogeneous": "spectrum sigma_a" and "spectrum sigma_s" (spectra or rgb, per unit length;
// default 1), "float scale" (multiplies both, default 1, so coefficients given per millimetre
// render a scene modelled in metres with scale 1000), "float g" (the Henyey-Greenstein asymmetry,
// default 0, in (-1, 1)), and "string preset", the name of one of Jensen et al. 2001's measured
// materials (see materials/subsurface_coefficients.h), whose coefficients are per millimetre and
// replace sigma_a and sigma_s (the reduced scattering coefficient, for isotropic scattering: keep
// g = 0).
// "uniformgrid": "float density" (nx * ny * nz values, x fastest), "integer nx/ny/nz" (default
// 1), "point3 p0/p1" (the box of the medium's space the grid fills, default the unit cube),
// sigma_a, sigma_s, scale and g as above; the coefficients at a point are the interpolated
// density times sigma_a and sigma_s.
// "rgbgrid": "rgb sigma_a" and/or "rgb sigma_s" (one colour per voxel; a missing one is 1), nx,
// ny, nz, p0, p1, scale and g.
// "cloud": pbrt-v4's procedural cloud: "float density" (1), "float wispiness" (1), "float
// frequency" (5), sigma_a, sigma_s, g, p0, p1 (cloud_medium.h).
// "nanovdb": "string filename" (a .nvdb file), "string gridname" (default "density"), sigma_a,
// sigma_s, scale, g; a "temperature" grid (pbrt-v4's emission) is an error unless "Lescale" is 0.
// The grids are placed by the transform in effect at MakeNamedMedium. Emission ("Le",
// "Lescale", "temperature") is not rendered yet: a non-zero one is an error rather than silently
// dark.
#pragma once

#include "core/transform.h"
#include "media/medium.h"
#include "params/parameters.h"

#include <string>

namespace caustica {

MediumPtr create_medium(const std::string &type, const ParameterDictionary &params, const SourceLocation &loc,
                        const Transform &render_from_medium = {});

} // namespace caustica
