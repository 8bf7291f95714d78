// Creates textures from `Texture "name" "float"|"spectrum" "type" ...` directives, with
// pbrt-v4's parameters and defaults. Supported: "constant" ("value"), "scale" ("tex" x
// "scale"), "mix" ((1 - "amount") "tex1" + "amount" "tex2"), "checkerboard" ("tex1"/"tex2",
// "dimension" 2 or 3), "bilerp" ("v00" "v10" "v01" "v11"), "imagemap" (image_texture.h); 2D
// ones take pbrt's "mapping" ("uv" with "uscale" "vscale" "udelta" "vdelta", "spherical",
// "cylindrical", "planar" with "v1" "v2" "udelta" "vdelta"), "directionmix" ("tex1" "tex2"
// "dir"), and the noise textures of noise_textures.h: "fbm", "wrinkled", "windy" (float),
// "marble" (spectrum) and "dots" ("inside" "outside"), with "roughness" and "octaves".
// An unknown type is an InputError; "ptex" is refused by the scene builder, which names the
// texture (Debian 12 has no Ptex library).
#pragma once

#include "core/error.h"
#include "core/transform.h"
#include "textures/texture.h"

#include <string>

namespace caustica {

class ParameterDictionary;

FloatTexturePtr create_float_texture(const std::string &type, const Transform &render_from_texture,
                                     const ParameterDictionary &params, const NamedTextures &textures,
                                     const SourceLocation &loc);

SpectrumTexturePtr create_spectrum_texture(const std::string &type,
                                           const Transform &render_from_texture,
                                           const ParameterDictionary &params,
                                           SpectrumType spectrum_type,
                                           const NamedTextures &textures, const SourceLocation &loc);

} // namespace caustica
