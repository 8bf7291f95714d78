// pbrt's "bilinearmesh": bilinear patches given by four vertices each (p00, p10, p01, p11).
// We render them as two triangles per patch, exact for planar patches and an approximation of
// curved ones.
#pragma once

#include "core/error.h"
#include "geometry/mesh_data.h"

namespace caustica {

// Splits each patch along its p10-p01 diagonal into triangles (p00, p10, p01) and
// (p10, p11, p01), whose winding gives the patch's normal cross(dp/du, dp/dv). Without "uv" the
// patch's own parameterization is kept, (0,0), (1,0), (0,1), (1,1) at its corners, which needs
// vertices of their own per patch. Throws InputError for a bad index count or index; warns when
// patches are not planar.
MeshData triangulate_bilinear_patches(const std::vector<int> &indices, const std::vector<Vec3f> &p,
                                      const std::vector<Vec3f> &n, const std::vector<Vec2f> &uv,
                                      const SourceLocation &loc);

} // namespace caustica
