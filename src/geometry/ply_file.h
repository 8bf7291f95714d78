// Reading PLY meshes (Turk's Polygon File Format) the way pbrt-v4's "plymesh" reads them.
//
// Assimp's PLY importer, the one in Debian 12, drops the first byte of a binary body when that
// byte is a line end (assimp issue #5341, open upstream), shifts every value after it and then
// aborts inside its triangulation step. Debian packages no other PLY library, so the format's
// small grammar is read here, with every count and index checked before it is used.
#pragma once

#include "core/error.h"
#include "geometry/mesh_data.h"

#include <string>
#include <string_view>

namespace caustica {

// True when `bytes` starts with the PLY magic line.
bool is_ply(std::string_view bytes);

// Reads the whole PLY file held in `bytes` (ascii, binary_little_endian or binary_big_endian).
// From the "vertex" element it takes x, y, z; nx, ny, nz when all three are there; and u, v
// (or s, t, texture_u, texture_v, texture_s, texture_t) when both are there. From the "face"
// element it takes the "vertex_indices" (or "vertex_index") lists: triangles into `indices`, and
// quads into `quads` as pbrt-v4's bilinear patches (v0, v1, v3, v2). Other
// elements and properties (colours, face_indices, edges) are read past. Faces of other sizes
// are skipped with one warning, as pbrt-v4 does. Throws InputError at loc, naming `path`, for a
// malformed header, a body shorter than the header declares, or an index outside the vertices.
MeshData read_ply(std::string_view bytes, const std::string &path, const SourceLocation &loc);

} // namespace caustica
