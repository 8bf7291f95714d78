#include "geometry/bilinear_mesh.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace caustica {

namespace {

// Relative size of f00 + f11 - f10 - f01 below which corner values count as affine: float noise
// of the values themselves.
constexpr float AffineTolerance = 1e-5f;

float magnitude(Vec3f v) { return length(v); }
float magnitude(Vec2f v) { return std::hypot(v.x, v.y); }

template <typename T>
bool corners_affine(const std::vector<T> &values, const int *v) {
    const T a = values[v[0]], b = values[v[1]], c = values[v[2]], d = values[v[3]];
    const float size = std::max({magnitude(b - a), magnitude(c - a), magnitude(d - a), magnitude(d - b)});
    return magnitude(a + d - b - c) <= AffineTolerance * size;
}

} // namespace

void validate_bilinear_patches(const std::vector<int> &indices, const std::vector<Vec3f> &p,
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
    for (Vec3f q : p)
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
            throw InputError(loc, "bilinearmesh: vertex positions \"P\" must be finite");
    if (!n.empty() && n.size() != p.size())
        throw InputError(loc, "bilinearmesh: " + std::to_string(n.size()) + " normals \"N\" for " +
                                  std::to_string(p.size()) + " vertices");
    if (!uv.empty() && uv.size() != p.size())
        throw InputError(loc, "bilinearmesh: " + std::to_string(uv.size()) +
                                  " \"uv\" values for " + std::to_string(p.size()) + " vertices");
}

bool bilinear_patches_are_affine(const std::vector<int> &indices, const std::vector<Vec3f> &p,
                                 const std::vector<Vec3f> &n, const std::vector<Vec2f> &uv) {
    for (size_t i = 0; i < indices.size(); i += 4) {
        const int *v = &indices[i];
        if (!corners_affine(p, v)) return false;
        if (!n.empty() && !corners_affine(n, v)) return false;
        if (!uv.empty() && !corners_affine(uv, v)) return false;
    }
    return true;
}

MeshData triangulate_bilinear_patches(const std::vector<int> &indices, const std::vector<Vec3f> &p,
                                      const std::vector<Vec3f> &n, const std::vector<Vec2f> &uv) {
    MeshData mesh;
    const size_t patches = indices.size() / 4;
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
    return mesh;
}

void split_quads(MeshData *mesh) {
    for (size_t i = 0; i < mesh->quads.size(); i += 4) {
        const int *q = &mesh->quads[i];
        mesh->indices.insert(mesh->indices.end(), {q[0], q[1], q[2], q[1], q[3], q[2]});
    }
    mesh->quads.clear();
}

} // namespace caustica
