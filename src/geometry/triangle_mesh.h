// Triangle meshes stored in render space, shared by the Embree geometry (intersection) and the
// per-triangle Shapes that area lights sample.
#pragma once

#include "core/error.h"
#include "core/transform.h"
#include "geometry/interaction.h"

#include <array>
#include <vector>

namespace caustica {

class TriangleMesh {
  public:
    // Transforms positions and normals to render space. Throws InputError for indices outside
    // [0, p.size()), an index count that is not a multiple of 3, non-finite positions, or
    // per-vertex arrays whose length differs from p's. Triangles with zero area in render space
    // (which would have no normal) are dropped with a warning naming how many.
    // `what` names the directive in messages ("trianglemesh", "plymesh 'bunny.ply'").
    TriangleMesh(const Transform &render_from_object, bool reverse_orientation,
                 std::vector<int> indices, std::vector<Vec3f> p, std::vector<Vec3f> n,
                 std::vector<Vec2f> uv, const SourceLocation &loc = {},
                 const std::string &what = "trianglemesh");

    int triangle_count() const { return int(indices_.size() / 3); }
    int vertex_count() const { return int(p_.size()); }
    const std::vector<int> &indices() const { return indices_; }
    // Render space, with capacity for one more element (Embree shares this buffer).
    const std::vector<Vec3f> &positions() const { return p_; }
    const std::vector<Vec3f> &normals() const { return n_; }   // empty if none given
    const std::vector<Vec2f> &uvs() const { return uv_; }      // empty if none given
    bool reverse_orientation() const { return reverse_orientation_; }
    bool transform_swaps_handedness() const { return swaps_handedness_; }

    std::array<int, 3> vertices(int triangle) const {
        return {indices_[3 * triangle], indices_[3 * triangle + 1], indices_[3 * triangle + 2]};
    }
    float area(int triangle) const;
    Bounds3f bounds() const;

    // Point, oriented geometric normal and uv at barycentrics b (b[0] + b[1] + b[2] = 1).
    Vec3f point(int triangle, const float b[3]) const;
    Vec3f normal(int triangle, const float b[3]) const;
    Vec2f uv(int triangle, const float b[3]) const;
    // The largest coordinate magnitude of the triangle's vertices, which the rounding error of a
    // point interpolated from them is proportional to (SurfaceInteraction::error_scale).
    float error_scale(int triangle) const { return frames_[triangle].error_scale; }

    // Fills the surface record at barycentrics b, the point interpolated from the vertices so
    // that it lies on the triangle (robust spawning depends on it). Leaves wo, t, material and
    // the other attributes of the primitive to the caller.
    void interaction(int triangle, const float b[3], SurfaceInteraction *si) const;

  private:
    // pbrt-v4's orientation rule: n = normalize(cross(p0 - p2, p1 - p2)); with per-vertex
    // normals it is flipped to the side of the interpolated normal, otherwise it is flipped when
    // reverse_orientation XOR the transform swaps handedness.
    Vec3f oriented_normal(Vec3f n_geometric, Vec3f n_interpolated) const;
    Vec3f interpolated_normal(int triangle, const float b[3]) const;
    void triangle_uvs(int triangle, Vec2f uv[3]) const;

    // What is constant over a triangle, computed once at construction because every ray hit needs
    // it: the unit normal of the vertex winding (before orientation) and the position
    // derivatives. This halves the cost of a hit on small scenes, where traversal is cheap.
    struct TriangleFrame {
        Vec3f n_winding, dpdu, dpdv;
        float error_scale;
    };
    TriangleFrame compute_frame(int triangle) const;

    std::vector<int> indices_;
    std::vector<TriangleFrame> frames_;
    std::vector<Vec3f> p_, n_;
    std::vector<Vec2f> uv_;
    bool reverse_orientation_ = false, swaps_handedness_ = false;
};

} // namespace caustica
