// Reading triangle meshes from files (pbrt's "plymesh"): PLY by our reader, the rest through
// Assimp.
#pragma once

#include "core/error.h"
#include "geometry/mesh_data.h"

#include <string>

namespace caustica {

// Reads the mesh in `path`: PLY as pbrt-v4 does (geometry/ply_file.h), or any other format
// Assimp recognises, with polygons split into triangles and several meshes in one file
// concatenated. Files ending in ".gz" are decompressed first. Throws InputError at loc if the
// file cannot be read or holds no triangles.
MeshData read_mesh_file(const std::string &path, const SourceLocation &loc);

} // namespace caustica
