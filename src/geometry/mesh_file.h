// Reading triangle meshes from files (pbrt's "plymesh"), through Assimp.
#pragma once

#include "core/error.h"
#include "geometry/mesh_data.h"

#include <string>

namespace caustica {

// Reads the mesh in `path` with Assimp: PLY as pbrt uses it (positions, optional normals and
// uv), or any other format Assimp recognises. Polygons are split into triangles; several meshes
// in one file are concatenated. Files ending in ".gz" are decompressed first (Assimp reads PLY
// only uncompressed). Throws InputError at loc if the file cannot be read or holds no triangles.
MeshData read_mesh_file(const std::string &path, const SourceLocation &loc);

} // namespace caustica
