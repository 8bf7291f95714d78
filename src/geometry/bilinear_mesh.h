// pbrt's "bilinearmesh": bilinear patches given by four vertices each (p00, p10, p01, p11).
// A mesh whose patches are all parallelograms, with normals and uv that are affine over each, is
// exactly the triangles each patch splits into, and is rendered as triangles (Embree's fastest
// primitive; area lights on them get spherical triangle sampling). Any other mesh is rendered as
// exact bilinear patches (bilinear_patch.h).
#pragma once

#include "core/error.h"
#include "geometry/mesh_data.h"

namespace caustica {

// Throws InputError for an index count that is not a multiple of 4, an index out of range,
// non-finite positions, or per-vertex arrays whose length differs from p's.
void validate_bilinear_patches(const std::vector<int> &indices, const std::vector<Vec3f> &p,
                               const std::vector<Vec3f> &n, const std::vector<Vec2f> &uv,
                               const SourceLocation &loc);

// Whether every patch is a parallelogram (p00 + p11 = p10 + p01, to float precision), and so are
// its normals and uv where given: then P, N and uv are affine in (u, v), and the two triangles
// of triangulate_bilinear_patches reproduce the patch exactly.
bool bilinear_patches_are_affine(const std::vector<int> &indices, const std::vector<Vec3f> &p,
                                 const std::vector<Vec3f> &n, const std::vector<Vec2f> &uv);

// Splits each (validated) patch along its p10-p01 diagonal into triangles (p00, p10, p01) and
// (p10, p11, p01), whose winding gives the patch's normal cross(dp/du, dp/dv). Without "uv" the
// patch's own parameterization is kept, (0,0), (1,0), (0,1), (1,1) at its corners, which needs
// vertices of their own per patch.
MeshData triangulate_bilinear_patches(const std::vector<int> &indices, const std::vector<Vec3f> &p,
                                      const std::vector<Vec3f> &n, const std::vector<Vec2f> &uv);

// A mesh file's quads (MeshData::quads) split into the same two triangles each, appended to its
// triangles, which is exact when bilinear_patches_are_affine(mesh.quads, ...).
void split_quads(MeshData *mesh);

} // namespace caustica
