// Creating the geometry of a Shape directive from its parameters.
#pragma once

#include "core/transform.h"
#include "geometry/shape_group.h"
#include "params/parameters.h"

#include <memory>
#include <string>
#include <vector>

namespace caustica {

class FloatTexture;

// "trianglemesh", "plymesh" (file relative to the scene's directory; .ply.gz accepted),
// "bilinearmesh", "loopsubdiv", "sphere", "disk", "cylinder" and "curve". One directive gives
// one group, except a PLY file holding both triangles and curved quads, which gives a triangle
// mesh and a group of patches, as pbrt-v4 makes both from such a file. pbrt-v3's quadrics,
// which pbrt-v4 dropped, give a warning naming them and no group; unknown names are an
// InputError. Parameters are read from params, whose unread ones the caller reports.
// `displacement` is a plymesh's "displacement" texture, which the caller finds among the named
// textures (mesh_displacement.h); null for other shapes or none.
std::vector<std::shared_ptr<ShapeGroup>> create_shapes(const std::string &type,
                                                       const Transform &render_from_object,
                                                       bool reverse_orientation,
                                                       const ParameterDictionary &params,
                                                       const SourceLocation &loc,
                                                       const FloatTexture *displacement = nullptr);

} // namespace caustica
