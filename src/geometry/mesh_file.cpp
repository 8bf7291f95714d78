#include "geometry/mesh_file.h"

#include "core/file_contents.h"
#include "geometry/ply_file.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <filesystem>
#include <memory>

namespace caustica {

namespace {

struct SceneDeleter {
    void operator()(const aiScene *scene) const { aiReleaseImport(scene); }
};
using ScenePtr = std::unique_ptr<const aiScene, SceneDeleter>;

bool ends_with(const std::string &s, const std::string &suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

MeshData read_mesh_file(const std::string &path, const SourceLocation &loc) {
    if (!std::filesystem::exists(path)) throw InputError(loc, "mesh file \"" + path + "\" not found");
    std::string error;
    std::optional<std::string> data = read_file_contents(path, &error);
    if (!data) throw InputError(loc, "mesh file \"" + path + "\": " + error);
    if (is_ply(*data)) return read_ply(*data, path, loc);
    // Other formats go to Assimp, with no post-processing but triangulation: pbrt uses the
    // vertices, normals and winding as stored.
    std::string inner = ends_with(path, ".gz") ? path.substr(0, path.size() - 3) : path;
    std::string hint = std::filesystem::path(inner).extension().string();
    if (!hint.empty()) hint = hint.substr(1);
    ScenePtr scene(aiImportFileFromMemory(data->data(), unsigned(data->size()), aiProcess_Triangulate,
                                          hint.c_str()));
    if (!scene) throw InputError(loc, "cannot read mesh file \"" + path + "\": " + aiGetErrorString());

    MeshData mesh;
    bool all_normals = true, all_uv = true;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        all_normals = all_normals && scene->mMeshes[m]->HasNormals();
        all_uv = all_uv && scene->mMeshes[m]->HasTextureCoords(0);
    }
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh *am = scene->mMeshes[m];
        int base = int(mesh.p.size());
        for (unsigned v = 0; v < am->mNumVertices; ++v) {
            const aiVector3D &p = am->mVertices[v];
            mesh.p.push_back({p.x, p.y, p.z});
            if (all_normals) {
                const aiVector3D &n = am->mNormals[v];
                mesh.n.push_back({n.x, n.y, n.z});
            }
            if (all_uv) {
                const aiVector3D &t = am->mTextureCoords[0][v];
                mesh.uv.push_back({t.x, t.y});
            }
        }
        for (unsigned f = 0; f < am->mNumFaces; ++f) {
            const aiFace &face = am->mFaces[f];
            if (face.mNumIndices != 3) continue; // points and lines
            for (int i = 0; i < 3; ++i) mesh.indices.push_back(base + int(face.mIndices[i]));
        }
    }
    if (mesh.indices.empty()) throw InputError(loc, "mesh file \"" + path + "\" holds no triangles");
    return mesh;
}

} // namespace caustica
