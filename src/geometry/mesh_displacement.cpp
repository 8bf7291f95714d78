#include "geometry/mesh_displacement.h"

#include "textures/texture.h"

#include <cmath>
#include <map>
#include <utility>

namespace caustica {

namespace {

class Refinement {
  public:
    Refinement(MeshData &mesh, const Transform &render_from_object, float max_length)
        : mesh_(mesh), render_from_object_(render_from_object), max_length_(max_length) {}

    // Appends triangle (v0, v1, v2), split until its edges are short enough, to `out`.
    void refine(int v0, int v1, int v2, std::vector<int> &out) {
        const float d01 = length_of(v0, v1), d12 = length_of(v1, v2), d20 = length_of(v2, v0);
        if (d01 < max_length_ && d12 < max_length_ && d20 < max_length_) {
            out.insert(out.end(), {v0, v1, v2});
            return;
        }
        // The longest edge first, keeping the winding.
        int a = v2, b = v0, c = v1;
        if (d01 > d12) {
            if (d01 > d20) a = v0, b = v1, c = v2;
        } else if (d12 > d20) {
            a = v1, b = v2, c = v0;
        }
        const int mid = midpoint(a, b);
        refine(a, mid, c, out);
        refine(mid, b, c, out);
    }

  private:
    float length_of(int a, int b) const {
        return distance(render_from_object_.apply_point(mesh_.p[a]), render_from_object_.apply_point(mesh_.p[b]));
    }

    int midpoint(int a, int b) {
        const std::pair<int, int> edge = std::minmax(a, b);
        if (auto it = split_.find(edge); it != split_.end()) return it->second;
        const int mid = int(mesh_.p.size());
        split_.emplace(edge, mid);
        mesh_.p.push_back((mesh_.p[a] + mesh_.p[b]) * 0.5f);
        Vec3f n = mesh_.n[a] + mesh_.n[b];
        if (length_squared(n) > 0) n = normalize(n);
        mesh_.n.push_back(n);
        mesh_.uv.push_back((mesh_.uv[a] + mesh_.uv[b]) * 0.5f);
        return mid;
    }

    MeshData &mesh_;
    Transform render_from_object_;
    float max_length_;
    std::map<std::pair<int, int>, int> split_;
};

// An upper bound on the triangles refinement makes: each triangle's longest edge is halved until
// it is short enough, at most (longest / max_length rounded up to a power of two)^2 pieces.
double refined_triangle_bound(const MeshData &mesh, const Transform &render_from_object, float max_length) {
    double total = 0;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        float longest = 0;
        for (int e = 0; e < 3; ++e) {
            const Vec3f a = render_from_object.apply_point(mesh.p[mesh.indices[i + e]]);
            const Vec3f b = render_from_object.apply_point(mesh.p[mesh.indices[i + (e + 1) % 3]]);
            longest = std::max(longest, distance(a, b));
        }
        const double pieces = std::exp2(std::ceil(std::log2(std::max(1.0, double(longest) / max_length) + 1e-9)));
        total += pieces * pieces * 2;
    }
    return total;
}

} // namespace

std::vector<Vec3f> vertex_normals(const MeshData &mesh) {
    std::vector<Vec3f> n(mesh.p.size());
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const int v0 = mesh.indices[i], v1 = mesh.indices[i + 1], v2 = mesh.indices[i + 2];
        const Vec3f face = cross(mesh.p[v1] - mesh.p[v0], mesh.p[v2] - mesh.p[v1]);
        if (!(length_squared(face) > 0)) continue;
        const Vec3f unit = normalize(face);
        for (int v : {v0, v1, v2}) n[v] += unit;
    }
    for (Vec3f &v : n)
        if (length_squared(v) > 0) v = normalize(v);
    return n;
}

MeshData displace_mesh(MeshData mesh, const FloatTexture &displacement, float edge_length,
                       const Transform &render_from_object, const SourceLocation &loc,
                       const SourceLocation &edge_loc) {
    if (mesh.uv.empty())
        throw InputError(loc, "plymesh: displacement needs per-vertex texture coordinates (\"u\" and \"v\" "
                              "in the PLY file), as in pbrt-v4");
    if (!(edge_length > 0) || !std::isfinite(edge_length))
        throw InputError(edge_loc, "plymesh: \"edgelength\" must be a positive number");
    if (refined_triangle_bound(mesh, render_from_object, edge_length) > MaxDisplacedTriangles)
        throw InputError(edge_loc, "plymesh: \"edgelength\" " + std::to_string(edge_length) +
                                       " would split the mesh into more than " +
                                       std::to_string(int64_t(MaxDisplacedTriangles)) + " triangles");
    if (mesh.n.empty()) mesh.n = vertex_normals(mesh);

    std::vector<int> refined;
    Refinement refinement(mesh, render_from_object, edge_length);
    const std::vector<int> original = std::move(mesh.indices);
    for (size_t i = 0; i + 2 < original.size(); i += 3)
        refinement.refine(original[i], original[i + 1], original[i + 2], refined);
    mesh.indices = std::move(refined);

    for (size_t i = 0; i < mesh.p.size(); ++i) {
        TextureEvalContext ctx;
        ctx.p = mesh.p[i];
        ctx.uv = mesh.uv[i];
        const float d = displacement.evaluate(ctx);
        if (std::isfinite(d)) mesh.p[i] += mesh.n[i] * d;
    }
    mesh.n = vertex_normals(mesh);
    return mesh;
}

} // namespace caustica
