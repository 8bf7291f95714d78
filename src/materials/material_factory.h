// Creates materials from `Material "type" ...` / `MakeNamedMaterial` directives with pbrt-v4's
// parameters and defaults:
//  - "diffuse": "reflectance" (spectrum texture, default 0.5);
//  - "conductor": "eta" / "k" (spectrum textures, default "metal-Cu-eta" / "metal-Cu-k"), or
//    "reflectance" instead of both; "roughness" or "uroughness" / "vroughness" (default 0),
//    "remaproughness" (default true);
//  - "dielectric": "eta" (float, or a spectrum such as "glass-BK7"; default 1.5), roughness as
//    for conductors, and Caustica extensions: "float sellmeierB" [B1 B2 B3] with "float
//    sellmeierC" [C1 C2 C3] (C in um^2), or "float cauchyA" / "float cauchyB" (B in um^2),
//    instead of "eta"; interior Beer-Lambert absorption from "sigma_a" (spectrum or rgb, per
//    unit length) or from "rgb transmittance" with "float atDistance" (default 1);
//  - "thindielectric": "eta" as for dielectric;
//  - "coateddiffuse": "reflectance" (default 0.5) under a coat: "eta" (float or spectrum,
//    default 1.5), roughness as for conductors (default 0), "thickness" (float texture, default
//    0.01), "albedo" (spectrum texture, default 0), "g" (float texture, default 0), "maxdepth"
//    (default 10), "nsamples" (default 1);
//  - "coatedconductor": the metal's "conductor.eta" / "conductor.k" (default copper) or
//    "reflectance", and "conductor.roughness" (or .uroughness / .vroughness, default 0), under a
//    coat with "interface.eta" (default 1.5) and "interface.roughness" (etc., default 0), and
//    "thickness", "albedo", "g", "maxdepth", "nsamples" as for coateddiffuse;
//  - "diffusetransmission": "reflectance" and "transmittance" (spectrum textures, default 0.25),
//    both multiplied by "scale" (default 1);
//  - "mix": "string materials" [two named materials, declared before], "amount" (float texture,
//    default 0.5: the probability of the second);
//  - "hair": pbrt-v4's HairBxDF (hair_material.h);
//  - "measured": "string filename", an RGL BSDF file (measured_bxdf.h), required;
//  - "subsurface": pbrt-v4's tabulated photon-beam-diffusion BSSRDF (subsurface_material.h):
//    "name" (a measured medium), or "sigma_a" with "sigma_s", or "reflectance" with "mfp"
//    (default 1); "scale" (default 1), "g" (default 0), "eta" (float, default 1.33), roughness
//    as for conductors (default 0);
//  - "interface": no material (nullptr): the surface only separates media.
//
// Errors (InputError at the offending parameter): an unknown type (at loc), negative or NaN
// roughness, a non-positive or NaN index of refraction, conflicting parameterisations (eta
// together with Sellmeier/Cauchy coefficients or conductor reflectance together with eta/k),
// negative absorption, a non-positive atDistance; for coated materials a negative thickness,
// |g| >= 1, maxdepth or nsamples below 1; a negative diffusetransmission scale; a mix of other
// than two defined named materials, or of materials with an interior (medium, absorption,
// subsurface); a measured material without a filename, or whose file cannot be read or is not an
// RGL BSDF file; a subsurface material with an unknown "name", "sigma_a" without "sigma_s" (or
// the reverse), negative coefficients, scale or mean free path, |g| >= 1 or a non-positive eta.
// Unused parameters produce warnings.
#pragma once

#include "core/error.h"
#include "materials/material.h"
#include "textures/texture.h"

#include <map>
#include <string>

namespace caustica {

class ParameterDictionary;

// named: the named materials created so far, which a "mix" refers to (declared before it).
MaterialPtr create_material(const std::string &type, const ParameterDictionary &params,
                            const NamedTextures &textures, const SourceLocation &loc,
                            const std::map<std::string, MaterialPtr> *named = nullptr);

} // namespace caustica
