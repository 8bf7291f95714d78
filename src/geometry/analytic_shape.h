// Shapes with closed-form surfaces (spheres, disks), intersected by our own double-precision code
// rather than as triangles. Each is defined in object space and placed by an affine
// render-from-object transform; all public quantities are in render space.
#pragma once

#include "core/transform.h"
#include "geometry/interaction.h"
#include "geometry/shape.h"
#include "geometry/vec3d.h"

#include <optional>

namespace caustica {

class AnalyticShape : public Shape {
  public:
    // Ray parameter of the first hit with 0 < t < t_max.
    std::optional<float> intersect_t(Vec3f o, Vec3f d, float t_max) const {
        return nth_hit(o, d, t_max, 0);
    }
    // Ray parameter of hit n (0: the first) with 0 < t < t_max, in increasing t. Rays see past
    // an alpha cut-out to the next hit of the same shape (a sphere's far side) this way.
    virtual std::optional<float> nth_hit(Vec3f o, Vec3f d, float t_max, int n) const = 0;
    // The surface record of the hit that intersect_t reported at ray parameter t. The point is
    // projected onto the exact surface rather than taken as o + t d, which robust spawning of
    // continuation rays depends on.
    virtual SurfaceInteraction interaction(const Ray &ray, float t) const = 0;

    std::optional<Hit> intersect(Vec3f o, Vec3f d, float t_max) const override;

    const Transform &render_from_object() const { return render_from_object_; }
    bool reverse_orientation() const { return reverse_orientation_; }

  protected:
    AnalyticShape(const Transform &render_from_object, bool reverse_orientation);

    Vec3d object_point(Vec3f p) const {
        return transform_point(render_from_object_.inverse_matrix(), Vec3d(p));
    }
    Vec3d object_vector(Vec3f v) const {
        return transform_vector(render_from_object_.inverse_matrix(), Vec3d(v));
    }
    Vec3d render_point(Vec3d p) const { return transform_point(render_from_object_.matrix(), p); }
    Vec3f render_vector(Vec3d v) const {
        return transform_vector(render_from_object_.matrix(), v).to_float();
    }
    // Unit render-space normal of object-space normal n, flipped per the orientation rule
    // (outward normal flipped when reverse_orientation XOR the transform swaps handedness).
    Vec3f render_normal(Vec3d n_object) const;
    // Factor by which the transform scales area at a surface point with object-space unit normal
    // n (Nanson's formula: dA_render = |det M| |M^-T n| dA_object).
    double area_scale(Vec3d n_object) const;
    // Conservative render-space bounds of an object-space box.
    Bounds3f render_bounds(Vec3d lo, Vec3d hi) const;
    // Converts a density per object-space solid angle at ref (object point ref_object) for the
    // surface point p_object with unit normal n_object into a density per render-space solid
    // angle. The identity for similarity transforms.
    double object_to_render_solid_angle_pdf(double pdf, Vec3d ref_object, Vec3d p_object,
                                            Vec3d n_object) const;
    // Converts a density per render-space area at p_object into one per render-space solid
    // angle at ref_object; 0 where the direction is tangent to the surface.
    double render_area_to_solid_angle_pdf(double pdf_area, Vec3d ref_object, Vec3d p_object,
                                          Vec3d n_object) const;

    // Rotations, translations and uniform scales keep solid angles proportional, so densities in
    // solid angle carry over from object space unchanged.
    bool is_similarity() const { return is_similarity_; }
    bool flip_normal() const { return flip_normal_; }

  private:
    Transform render_from_object_;
    bool reverse_orientation_;
    bool flip_normal_;
    bool is_similarity_;
    double abs_determinant_;
};

} // namespace caustica
