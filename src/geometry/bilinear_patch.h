// pbrt-v4's "bilinearmesh" as exact bilinear patches: each patch is the surface
//   P(u, v) = (1 - u)(1 - v) p00 + u (1 - v) p10 + (1 - u) v p01 + u v p11,  (u, v) in [0, 1]^2,
// a piece of a hyperbolic paraboloid when its corners are not coplanar. Embree has no such
// primitive, so patches are Embree user geometry intersected by Reshetov's method (Ray Tracing
// Gems, chapter 8, 2019, as in pbrt-v4): the ray meets the line of constant u where it is
// coplanar with it, a quadratic in u, and then v and t follow from the line-line intersection.
// The arithmetic is in double, as for the other analytic shapes.
//
// Patches whose positions, normals and uv are all affine in (u, v) (parallelograms) are the two
// triangles they split into, and are rendered as such (bilinear_mesh.h); this class holds the
// others.
#pragma once

#include "core/transform.h"
#include "geometry/interaction.h"
#include "geometry/shape.h"

#include <array>
#include <memory>
#include <vector>

namespace caustica {

class BilinearPatchMesh {
  public:
    // Moves positions and normals to render space. The caller has validated the arrays:
    // indices come in fours within [0, p.size()), n and uv are empty or one per vertex.
    BilinearPatchMesh(const Transform &render_from_object, bool reverse_orientation, std::vector<int> indices,
                      std::vector<Vec3f> p, std::vector<Vec3f> n, std::vector<Vec2f> uv);

    int patch_count() const { return int(indices_.size() / 4); }
    Bounds3f bounds() const;
    Bounds3f bounds(int patch) const;
    // Corners p00, p10, p01, p11 in render space.
    std::array<Vec3f, 4> corners(int patch) const;

    // A hit of the ray o + t d: its ray parameter and the patch parameters (u, v).
    struct Hit {
        float t;
        Vec2f uv;
    };
    // The ray's hits with the patch for 0 < t < t_max, nearest first; returns their number (at
    // most 2).
    int hits(int patch, Vec3f o, Vec3f d, float t_max, Hit out[2]) const;

    // The surface record at patch parameters uv: the point interpolated from the corners, the
    // texture coordinates and shading normal interpolated bilinearly (pbrt-v4), dp/du and dp/dv
    // with respect to the texture coordinates when the mesh has them, and pbrt-v4's orientation
    // rule for the normal. Leaves wo, t, material and the primitive's other attributes to the
    // caller.
    void interaction(int patch, Vec2f uv, SurfaceInteraction *si) const;
    // Point and oriented geometric normal at patch parameters uv.
    Vec3f point(int patch, Vec2f uv) const;
    Vec3f normal(int patch, Vec2f uv) const;
    // Texture coordinates at patch parameters uv (uv itself when the mesh has none).
    Vec2f texture_uv(int patch, Vec2f uv) const;
    // |dP/du x dP/dv| at uv: the area element of the patch parameters.
    float area_element(int patch, Vec2f uv) const;
    // The largest coordinate magnitude of the corners (SurfaceInteraction::error_scale).
    float error_scale(int patch) const;
    // The patch parameters of a point on (or within rounding of) the patch, by Newton's method
    // on the nearest point.
    Vec2f parameters_of(int patch, Vec3f p) const;

  private:
    // The unit normal n of the patch's winding, turned by pbrt-v4's orientation rule: to the side
    // of the interpolated normal where the mesh has normals, else flipped by flip_normal_.
    Vec3f oriented(Vec3f n, Vec3f n_interpolated) const;

    std::vector<int> indices_;
    std::vector<Vec3f> p_, n_;
    std::vector<Vec2f> uv_;
    bool flip_normal_ = false; // reverse_orientation XOR the transform swaps handedness
};

// One patch of a BilinearPatchMesh seen as a Shape, so that an area light can be attached to
// each patch of an emissive mesh. Points are sampled as in pbrt-v4: (u, v) with density
// proportional to the bilinear interpolation of the area element at the corners, which is
// nearly uniform by area, with the exact density per area that this implies.
class BilinearPatch : public Shape {
  public:
    BilinearPatch(std::shared_ptr<const BilinearPatchMesh> mesh, int index);

    float area() const override { return area_; }
    Bounds3f bounds() const override { return mesh_->bounds(index_); }
    std::optional<ShapeSample> sample(Vec2f u) const override;
    using Shape::sample;
    float pdf(Vec3f ref, Vec3f wi) const override;
    float pdf_area(Vec3f p) const override;
    bool samples_uniformly_by_area() const override { return false; }
    std::optional<Hit> intersect(Vec3f o, Vec3f d, float t_max) const override;

  private:
    // Density of sample(u) per unit of (u, v) at uv.
    float parameter_pdf(Vec2f uv) const;

    std::shared_ptr<const BilinearPatchMesh> mesh_;
    int index_;
    float corner_area_elements_[4];
    float area_;
};

} // namespace caustica
