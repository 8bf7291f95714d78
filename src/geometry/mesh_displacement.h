// pbrt-v4's displacement of a "plymesh" ("displacement" texture, "edgelength"): the mesh is
// refined until no edge is longer than edgelength in render space, then every vertex moves
// along its normal by the texture's value there, and the normals are recomputed from the moved
// triangles (pbrt-v4's TriQuadMesh::Displace).
//
// As in pbrt-v4:
//   - a triangle with an edge too long is split at the midpoint of its longest edge, into two
//     that are refined in turn; an edge is split once, shared by the triangles on both sides;
//   - the new vertex takes the mean of the edge's uv and its normalised normal sum;
//   - a mesh without normals first gets them: the normalised sum of the unit normals of the
//     triangles around each vertex (so do the moved vertices);
//   - the texture is evaluated at the object-space point and uv, without a footprint, and the
//     vertex moves in object space. pbrt-v4 hands the object-space point to the texture as a
//     point of its render space, which by default is the world moved to put the camera at the
//     origin; Caustica's render space is the world, so textures that read the point (solid
//     noise, 3D checks, the planar, spherical and cylindrical mappings) agree with pbrt-v4's
//     when the camera sits at the world's origin, and uv-mapped ones always;
//   - a mesh without uv cannot be displaced (an error).
// Differs in one respect: a refinement that would make more than MaxDisplacedTriangles
// triangles is an error at "edgelength" rather than a process that runs out of memory.
#pragma once

#include "core/error.h"
#include "core/transform.h"
#include "geometry/mesh_data.h"

namespace caustica {

class FloatTexture;

inline constexpr double MaxDisplacedTriangles = 5e7;

// The displaced mesh. Throws InputError at `loc` (the "displacement" parameter) without uv, and
// at `edge_loc` for an edge length that is not positive and finite or too small for the mesh.
MeshData displace_mesh(MeshData mesh, const FloatTexture &displacement, float edge_length,
                       const Transform &render_from_object, const SourceLocation &loc,
                       const SourceLocation &edge_loc);

// Vertex normals as the normalised sum of the unit normals of the triangles around each vertex
// (zero where no triangle has area).
std::vector<Vec3f> vertex_normals(const MeshData &mesh);

} // namespace caustica
