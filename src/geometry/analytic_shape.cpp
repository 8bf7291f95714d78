#include "geometry/analytic_shape.h"

namespace caustica {

AnalyticShape::AnalyticShape(const Transform &render_from_object, bool reverse_orientation)
    : render_from_object_(render_from_object), reverse_orientation_(reverse_orientation),
      flip_normal_(reverse_orientation != render_from_object.swaps_handedness()) {
    const auto &m = render_from_object.matrix().m;
    double l[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) l[i][j] = m[i][j];
    abs_determinant_ = std::abs(l[0][0] * (l[1][1] * l[2][2] - l[1][2] * l[2][1]) -
                                l[0][1] * (l[1][0] * l[2][2] - l[1][2] * l[2][0]) +
                                l[0][2] * (l[1][0] * l[2][1] - l[1][1] * l[2][0]));
    // A similarity has L^T L = s^2 I; allow float rounding of the matrix entries.
    double gram[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            gram[i][j] = 0;
            for (int k = 0; k < 3; ++k) gram[i][j] += l[k][i] * l[k][j];
        }
    double s2 = (gram[0][0] + gram[1][1] + gram[2][2]) / 3;
    is_similarity_ = s2 > 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(gram[i][j] - (i == j ? s2 : 0)) > 1e-5 * s2) is_similarity_ = false;
}

std::optional<Shape::Hit> AnalyticShape::intersect(Vec3f o, Vec3f d, float t_max) const {
    std::optional<float> t = intersect_t(o, d, t_max);
    if (!t) return std::nullopt;
    SurfaceInteraction si = interaction(Ray{o, d, t_max}, *t);
    return Hit{*t, si.p, si.n, si.uv};
}

Vec3f AnalyticShape::render_normal(Vec3d n_object) const {
    if (flip_normal_) n_object = -n_object;
    return normalize(transform_normal(render_from_object_.inverse_matrix(), n_object)).to_float();
}

double AnalyticShape::area_scale(Vec3d n_object) const {
    return abs_determinant_ * length(transform_normal(render_from_object_.inverse_matrix(), n_object));
}

Bounds3f AnalyticShape::render_bounds(Vec3d lo, Vec3d hi) const {
    Bounds3f b;
    for (int corner = 0; corner < 8; ++corner) {
        Vec3d p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
        Vec3d r = render_point(p);
        // Round outwards so that the float box contains the exact one.
        b.expand(Vec3f{std::nextafter(float(r.x), -Infinity), std::nextafter(float(r.y), -Infinity),
                       std::nextafter(float(r.z), -Infinity)});
        b.expand(Vec3f{std::nextafter(float(r.x), Infinity), std::nextafter(float(r.y), Infinity),
                       std::nextafter(float(r.z), Infinity)});
    }
    return b;
}

double AnalyticShape::render_area_to_solid_angle_pdf(double pdf_area, Vec3d ref_object,
                                                     Vec3d p_object, Vec3d n_object) const {
    Vec3d ref = render_point(ref_object), p = render_point(p_object);
    Vec3d n = transform_normal(render_from_object_.inverse_matrix(), n_object);
    Vec3d wi = p - ref;
    double dist2 = length_squared(wi);
    double cos_light = std::abs(dot(normalize(n), wi)) / std::sqrt(dist2);
    if (!(cos_light > 0) || !(dist2 > 0)) return 0;
    return pdf_area * dist2 / cos_light;
}

double AnalyticShape::object_to_render_solid_angle_pdf(double pdf, Vec3d ref_object,
                                                       Vec3d p_object, Vec3d n_object) const {
    if (is_similarity_) return pdf;
    // Object solid angle -> object area -> render area -> render solid angle.
    Vec3d to_ref = ref_object - p_object;
    double dist2 = length_squared(to_ref);
    double cos_object = std::abs(dot(n_object, to_ref)) / std::sqrt(dist2);
    double pdf_area = pdf * cos_object / dist2 / area_scale(n_object);
    return render_area_to_solid_angle_pdf(pdf_area, ref_object, p_object, n_object);
}

} // namespace caustica
