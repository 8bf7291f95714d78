#include "geometry/triangle_mesh.h"

#include <string>

namespace caustica {

TriangleMesh::TriangleMesh(const Transform &render_from_object, bool reverse_orientation,
                           std::vector<int> indices, std::vector<Vec3f> p, std::vector<Vec3f> n,
                           std::vector<Vec2f> uv, const SourceLocation &loc,
                           const std::string &what)
    : p_(std::move(p)), n_(std::move(n)), uv_(std::move(uv)),
      reverse_orientation_(reverse_orientation),
      swaps_handedness_(render_from_object.swaps_handedness()) {
    if (p_.empty()) throw InputError(loc, what + ": no vertex positions \"P\" given");
    if (indices.size() % 3 != 0)
        throw InputError(loc, what + ": number of vertex indices (" +
                                  std::to_string(indices.size()) + ") is not a multiple of 3");
    if (!n_.empty() && n_.size() != p_.size())
        throw InputError(loc, what + ": " + std::to_string(n_.size()) + " normals \"N\" for " +
                                  std::to_string(p_.size()) + " vertices");
    if (!uv_.empty() && uv_.size() != p_.size())
        throw InputError(loc, what + ": " + std::to_string(uv_.size()) + " \"uv\" values for " +
                                  std::to_string(p_.size()) + " vertices");
    for (int index : indices)
        if (index < 0 || size_t(index) >= p_.size())
            throw InputError(loc, what + ": vertex index " + std::to_string(index) +
                                      " is out of range [0, " + std::to_string(p_.size()) + ")");

    for (Vec3f &v : p_) {
        if (!is_finite(v)) throw InputError(loc, what + ": vertex position is not finite");
        v = render_from_object.apply_point(v);
    }
    // Embree reads vertices with 16-byte loads, so the last one needs 4 readable bytes after it;
    // a spare element of capacity provides them (the buffer is shared with Embree, not copied).
    p_.reserve(p_.size() + 1);
    // Like pbrt-v4, ReverseOrientation also reverses the given normals, so it keeps its effect on
    // meshes whose geometric normal follows the shading normal.
    for (Vec3f &v : n_) {
        v = render_from_object.apply_normal(v);
        if (reverse_orientation) v = -v;
    }

    // Zero-area triangles have no normal and would give NaN shading frames and sampling pdfs.
    indices_.reserve(indices.size());
    size_t dropped = 0;
    for (size_t i = 0; i < indices.size(); i += 3) {
        Vec3f p0 = p_[indices[i]], p1 = p_[indices[i + 1]], p2 = p_[indices[i + 2]];
        if (length_squared(cross(p1 - p0, p2 - p0)) == 0) {
            ++dropped;
            continue;
        }
        indices_.insert(indices_.end(), {indices[i], indices[i + 1], indices[i + 2]});
    }
    if (dropped > 0)
        warning(loc, what + ": dropped " + std::to_string(dropped) + " of " +
                         std::to_string(indices.size() / 3) + " triangles with zero area");
    frames_.resize(triangle_count());
    for (int t = 0; t < triangle_count(); ++t) frames_[t] = compute_frame(t);
}

float TriangleMesh::area(int triangle) const {
    auto v = vertices(triangle);
    return 0.5f * length(cross(p_[v[1]] - p_[v[0]], p_[v[2]] - p_[v[0]]));
}

Bounds3f TriangleMesh::bounds() const {
    Bounds3f b;
    for (int index : indices_) b.expand(p_[index]);
    return b;
}

Vec3f TriangleMesh::point(int triangle, const float b[3]) const {
    auto v = vertices(triangle);
    return p_[v[0]] * b[0] + p_[v[1]] * b[1] + p_[v[2]] * b[2];
}

Vec3f TriangleMesh::interpolated_normal(int triangle, const float b[3]) const {
    if (n_.empty()) return {};
    auto v = vertices(triangle);
    return n_[v[0]] * b[0] + n_[v[1]] * b[1] + n_[v[2]] * b[2];
}

Vec3f TriangleMesh::oriented_normal(Vec3f ng, Vec3f n_interpolated) const {
    if (reverse_orientation_ != swaps_handedness_) ng = -ng;
    if (length_squared(n_interpolated) > 0) ng = face_forward(ng, n_interpolated);
    return ng;
}

Vec3f TriangleMesh::normal(int triangle, const float b[3]) const {
    return oriented_normal(frames_[triangle].n_winding, interpolated_normal(triangle, b));
}

void TriangleMesh::triangle_uvs(int triangle, Vec2f uv[3]) const {
    if (uv_.empty()) {
        // pbrt's default parameterization of a triangle without "uv".
        uv[0] = {0, 0};
        uv[1] = {1, 0};
        uv[2] = {1, 1};
        return;
    }
    auto v = vertices(triangle);
    for (int i = 0; i < 3; ++i) uv[i] = uv_[v[i]];
}

Vec2f TriangleMesh::uv(int triangle, const float b[3]) const {
    Vec2f t[3];
    triangle_uvs(triangle, t);
    return t[0] * b[0] + t[1] * b[1] + t[2] * b[2];
}

TriangleMesh::TriangleFrame TriangleMesh::compute_frame(int triangle) const {
    auto v = vertices(triangle);
    Vec3f p0 = p_[v[0]], p1 = p_[v[1]], p2 = p_[v[2]];
    Vec2f t[3];
    triangle_uvs(triangle, t);
    TriangleFrame frame;
    frame.n_winding = normalize(cross(p0 - p2, p1 - p2));
    frame.error_scale = max_component(max(abs(p0), max(abs(p1), abs(p2))));

    // Partial derivatives from the linear map between uv and position over the triangle:
    // dp02 = duv02.u dpdu + duv02.v dpdv, dp12 = duv12.u dpdu + duv12.v dpdv.
    Vec2f duv02 = t[0] - t[2], duv12 = t[1] - t[2];
    Vec3f dp02 = p0 - p2, dp12 = p1 - p2;
    double determinant = double(duv02.x) * duv12.y - double(duv02.y) * duv12.x;
    bool degenerate_uv = std::abs(determinant) < 1e-9;
    if (!degenerate_uv) {
        float inv = float(1 / determinant);
        frame.dpdu = (dp02 * duv12.y - dp12 * duv02.y) * inv;
        frame.dpdv = (dp12 * duv02.x - dp02 * duv12.x) * inv;
    }
    if (degenerate_uv || length_squared(cross(frame.dpdu, frame.dpdv)) == 0 ||
        !is_finite(frame.dpdu) || !is_finite(frame.dpdv))
        coordinate_system(-frame.n_winding, &frame.dpdu, &frame.dpdv); // pbrt-v4's axis choice
    return frame;
}

void TriangleMesh::interaction(int triangle, const float b[3], SurfaceInteraction *si) const {
    auto v = vertices(triangle);
    Vec2f t[3];
    triangle_uvs(triangle, t);
    const TriangleFrame &frame = frames_[triangle];

    si->p = p_[v[0]] * b[0] + p_[v[1]] * b[1] + p_[v[2]] * b[2];
    si->error_scale = error_scale(triangle);
    si->uv = t[0] * b[0] + t[1] * b[1] + t[2] * b[2];
    si->face_index = triangle;
    si->dpdu = frame.dpdu;
    si->dpdv = frame.dpdv;
    Vec3f n_interpolated = interpolated_normal(triangle, b);
    si->n = oriented_normal(frame.n_winding, n_interpolated);
    si->shading.n = si->n;
    si->shading.dpdu = si->dpdu;
    si->shading.dpdv = si->dpdv;
    if (n_.empty()) return;

    // The interpolated normal, or the geometric one where it vanishes.
    si->set_shading_normal(length_squared(n_interpolated) > 0 ? normalize(n_interpolated) : si->n);
}

} // namespace caustica
