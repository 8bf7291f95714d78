// pbrt-v4's "curve" shape: cubic Bezier segments (from Bezier or uniform B-spline control points
// of degree 2 or 3) swept to a width that varies linearly along the curve, in three kinds:
//   flat     a ribbon that always faces the ray (for hair seen from afar);
//   ribbon   a ribbon oriented by normals given at the segment ends (blades of grass);
//   cylinder the flat ribbon with its normal turned across the width to look like a tube.
// Embree intersects them as its flat (ray-facing) Bezier curves; a ribbon is, as in pbrt-v4, the
// ray-facing curve narrowed to its width times |cos| of the angle between its normal and the
// ray (covers()). The surface record of a hit is computed here as pbrt-v4's Curve does it, in
// object space: u runs along each segment
// from 0 to 1, v across the width from 0 to 1 (the hair BSDF reads v as the offset h = 2 v - 1),
// dp/du is the curve's tangent, dp/dv points across the width, and the normal is their cross
// product (flipped by ReverseOrientation XOR a handedness-swapping transform).
//
// Differences from pbrt-v4: Embree tests the ray against widths in render space, where pbrt-v4
// tests in object space; the two agree unless the object-to-render transform scales unevenly
// (Embree is then given the mean scale). Embree's flat curves are sequences of ray-facing quads
// (CurveSet sets their tessellation rate) where pbrt-v4 subdivides recursively.
#pragma once

#include "core/error.h"
#include "core/transform.h"
#include "geometry/interaction.h"
#include "params/parameters.h"

#include <array>
#include <memory>
#include <vector>

namespace caustica {

enum class CurveType { Flat, Ribbon, Cylinder };

class CurveSet {
  public:
    // One cubic Bezier segment in object space: control points, full widths at its ends, and
    // (ribbons only) unit normals at its ends.
    struct Segment {
        std::array<Vec3f, 4> p;
        float width[2];
        Vec3f n[2];
    };

    CurveSet(const Transform &render_from_object, bool reverse_orientation, CurveType type,
             std::vector<Segment> segments);

    CurveType type() const { return type_; }
    int segment_count() const { return int(segments_.size()); }
    // For Embree: four (x, y, z, radius) control points per segment in render space.
    const std::vector<float> &embree_vertices() const { return embree_vertices_; }
    Bounds3f bounds() const;


    // The render-space point on a segment's centre line at u, and its unit tangent there; the
    // width there.
    Vec3f render_point(int segment, float u, Vec3f *tangent) const;
    float render_width(int segment, float u) const;

    // Whether a hit that Embree found on the full-width ray-facing segment at u, by ray o + t d
    // (render space), lies on the curve: always, except on a ribbon seen at an angle.
    bool covers(int segment, float u, Vec3f o, Vec3f d, float t) const;

    // The surface record of the hit of segment at its parameter u, by ray (render space) at t.
    // Leaves wo, t, material and the other attributes of the primitive to the caller.
    void interaction(int segment, float u, const Ray &ray, float t, SurfaceInteraction *si) const;

  private:
    Transform render_from_object_, object_from_render_;
    CurveType type_;
    bool flip_normal_;
    float render_scale_;  // the transform's mean scale: |det|^(1/3)
    std::vector<Segment> segments_;
    std::vector<float> embree_vertices_;
};

// The segments of a "curve" directive's parameters (P, basis, degree, width, width0, width1,
// type, N; splitdepth is read and has nothing to do, as Embree subdivides by itself). Bad
// counts, an unknown basis, degree or type, and a ribbon without normals are InputErrors at the
// parameter, where pbrt-v4 reports them and skips the shape.
std::shared_ptr<CurveSet> create_curves(const Transform &render_from_object, bool reverse_orientation,
                                        const ParameterDictionary &params);

}  // namespace caustica
