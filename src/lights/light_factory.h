// Creating lights from scene-file directives (`LightSource` and `AreaLightSource`) with pbrt-v4's
// parameters and radiometric conventions (photometric normalisation, "power", "illuminance";
// see photometric.h). Both functions report unused parameters when done, as pbrt-v4 does.
#pragma once

#include "core/error.h"
#include "core/transform.h"
#include "geometry/alpha_mask.h"
#include "geometry/shape.h"
#include "lights/light.h"
#include "params/parameters.h"

#include <memory>
#include <string>
#include <vector>

namespace caustica {

// "point", "spot", "goniometric", "projection", "distant" and "infinite" (uniform, from an
// image: "filename", or through a "portal"). Throws InputError for unknown types and bad parameters (at the parameter's location).
LightPtr create_light(const std::string &type, const Transform &render_from_light,
                      const ParameterDictionary &params, const SourceLocation &loc);

// One "diffuse" area light per shape, the shapes already in render space. As in pbrt-v4, a
// "power" applies to each shape separately (a triangle mesh's triangles each emit that power).
// alpha is the shapes' cut-out (null if opaque).
std::vector<LightPtr> create_area_lights(const std::string &type, const ParameterDictionary &params,
                                         const std::vector<std::shared_ptr<Shape>> &shapes,
                                         const SourceLocation &loc,
                                         std::shared_ptr<const AlphaMask> alpha = nullptr);

}  // namespace caustica
