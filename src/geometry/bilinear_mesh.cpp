#include "geometry/bilinear_mesh.h"

#include <string>

namespace caustica {

namespace {

// Distance of p11 from the plane through the other three corners, relative to the patch size;
// zero for planar patches (including ones with a collapsed corner).
float non_planarity(Vec3f p00, Vec3f p10, Vec3f p01, Vec3f p11) {
    Vec3f normal = cross(p10 - p00, p01 - p00);
    float size = std::max({length(p10 - p00), length(p01 - p00), length(p11 - p00)});
    if (length_squared(normal) == 0 || size == 0) return 0;
    return std::abs(dot(normalize(normal), p11 - p00)) / size;
}

} // namespace

MeshData triangulate_bilinear_patches(const std::vector<int> &indices, const std::vector<Vec3f> &p,
                                      const std::vector<Vec3f> &n, const std::vector<Vec2f> &uv,
                                      const SourceLocation &loc) {
    if (p.empty()) throw InputError(loc, "bilinearmesh: no vertex positions \"P\" given");
    if (indices.size() % 4 != 0)
        throw InputError(loc, "bilinearmesh: number of vertex indices (" +
                                  std::to_string(indices.size()) + ") is not a multiple of 4");
    for (int index : indices)
        if (index < 0 || size_t(index) >= p.size())
            throw InputError(loc, "bilinearmesh: vertex index " + std::to_string(index) +
                                      " is out of range [0, " + std::to_string(p.size()) + ")");
    if (!n.empty() && n.size() != p.size())
        throw InputError(loc, "bilinearmesh: " + std::to_string(n.size()) + " normals \"N\" for " +
                                  std::to_string(p.size()) + " vertices");
    if (!uv.empty() && uv.size() != p.size())
        throw InputError(loc, "bilinearmesh: " + std::to_string(uv.size()) +
                                  " \"uv\" values for " + std::to_string(p.size()) + " vertices");

    MeshData mesh;
    size_t patches = indices.size() / 4, curved = 0;
    // Relative deviation from planarity beyond float noise of the corner positions.
    constexpr float PlanarityTolerance = 1e-4f;
    if (uv.empty()) {
        mesh.p.reserve(indices.size());
        mesh.uv.reserve(indices.size());
        if (!n.empty()) mesh.n.reserve(indices.size());
    } else {
        mesh.p = p;
        mesh.n = n;
        mesh.uv = uv;
    }
    mesh.indices.reserve(patches * 6);
    static const Vec2f corner_uv[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    for (size_t i = 0; i < patches; ++i) {
        const int *v = &indices[4 * i];
        if (non_planarity(p[v[0]], p[v[1]], p[v[2]], p[v[3]]) > PlanarityTolerance) ++curved;
        int c[4];
        if (uv.empty()) {
            for (int k = 0; k < 4; ++k) {
                c[k] = int(mesh.p.size());
                mesh.p.push_back(p[v[k]]);
                mesh.uv.push_back(corner_uv[k]);
                if (!n.empty()) mesh.n.push_back(n[v[k]]);
            }
        } else {
            for (int k = 0; k < 4; ++k) c[k] = v[k];
        }
        mesh.indices.insert(mesh.indices.end(), {c[0], c[1], c[2], c[1], c[3], c[2]});
    }
    if (curved > 0)
        warning(loc, "bilinearmesh: " + std::to_string(curved) + " of " + std::to_string(patches) +
                         " patches are not planar; curved patches are approximated by two "
                         "triangles each");
    return mesh;
}

} // namespace caustica
