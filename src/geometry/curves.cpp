#include "geometry/curves.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace caustica {

namespace {

Vec3f lerp(float t, Vec3f a, Vec3f b) { return a * (1 - t) + b * t; }

// The point of a cubic Bezier segment at u, and its derivative, by de Casteljau's construction.
Vec3f evaluate_bezier(const std::array<Vec3f, 4> &cp, float u, Vec3f *derivative) {
    const Vec3f a = lerp(u, cp[0], cp[1]), b = lerp(u, cp[1], cp[2]), c = lerp(u, cp[2], cp[3]);
    const Vec3f d = lerp(u, a, b), e = lerp(u, b, c);
    // At u = 0 or 1 with repeated end points the chord is degenerate; the next control point
    // still gives the tangent's direction.
    Vec3f de = e - d;
    if (length_squared(de) == 0) de = u < 0.5f ? cp[2] - cp[0] : cp[3] - cp[1];
    *derivative = de * 3;
    return lerp(u, d, e);
}

// Unit normals interpolated by angle between a ribbon segment's end normals (pbrt-v4's slerp).
Vec3f ribbon_normal(const CurveSet::Segment &s, float u) {
    const float angle = std::acos(std::clamp(dot(s.n[0], s.n[1]), -1.f, 1.f));
    if (angle < 1e-5f) return s.n[0];
    const float inv_sin = 1 / std::sin(angle);
    return s.n[0] * (std::sin((1 - u) * angle) * inv_sin) + s.n[1] * (std::sin(u * angle) * inv_sin);
}

// v, rotated by `radians` about unit axis a (v perpendicular to a).
Vec3f rotate_about(Vec3f v, Vec3f a, float radians) {
    return v * std::cos(radians) + cross(a, v) * std::sin(radians);
}

// Raises a quadratic Bezier segment to the cubic with the same curve.
std::array<Vec3f, 4> elevate_quadratic(const std::array<Vec3f, 3> &q) {
    return {q[0], (q[0] + q[1] * 2) / 3.f, (q[1] * 2 + q[2]) / 3.f, q[2]};
}

// The Bezier control points of one segment of a uniform B-spline (by blossoming).
std::array<Vec3f, 3> quadratic_bspline_to_bezier(const Vec3f *p) {
    return {(p[0] + p[1]) * 0.5f, p[1], (p[1] + p[2]) * 0.5f};
}
std::array<Vec3f, 4> cubic_bspline_to_bezier(const Vec3f *p) {
    return {(p[0] + p[1] * 4 + p[2]) / 6.f, (p[1] * 2 + p[2]) / 3.f, (p[1] + p[2] * 2) / 3.f,
            (p[1] + p[2] * 4 + p[3]) / 6.f};
}

std::string count(size_t n) { return std::to_string(n); }

} // namespace

CurveSet::CurveSet(const Transform &render_from_object, bool reverse_orientation, CurveType type,
                   std::vector<Segment> segments)
    : render_from_object_(render_from_object),
      object_from_render_(render_from_object.inverse()),
      type_(type),
      flip_normal_(reverse_orientation != render_from_object.swaps_handedness()),
      segments_(std::move(segments)) {
    const Vec3f x = render_from_object.apply_vector({1, 0, 0}), y = render_from_object.apply_vector({0, 1, 0}),
                z = render_from_object.apply_vector({0, 0, 1});
    render_scale_ = std::cbrt(std::abs(dot(x, cross(y, z))));
    embree_vertices_.reserve(16 * segments_.size());
    for (const Segment &s : segments_) {
        // A width linear in u has the Bezier control values of its values at 0, 1/3, 2/3 and 1.
        for (int i = 0; i < 4; ++i) {
            const Vec3f p = render_from_object.apply_point(s.p[i]);
            const float width = lerp(i / 3.f, s.width[0], s.width[1]);
            embree_vertices_.insert(embree_vertices_.end(), {p.x, p.y, p.z, 0.5f * width * render_scale_});
        }
    }
}

Bounds3f CurveSet::bounds() const {
    Bounds3f b;
    for (size_t i = 0; i < embree_vertices_.size(); i += 4) {
        const float r = embree_vertices_[i + 3];
        b.expand(Vec3f(embree_vertices_[i] - r, embree_vertices_[i + 1] - r, embree_vertices_[i + 2] - r));
        b.expand(Vec3f(embree_vertices_[i] + r, embree_vertices_[i + 1] + r, embree_vertices_[i + 2] + r));
    }
    return b;
}

Vec3f CurveSet::render_point(int segment, float u, Vec3f *tangent) const {
    const float *v = &embree_vertices_[16 * size_t(segment)];
    const std::array<Vec3f, 4> cp{Vec3f(v[0], v[1], v[2]), Vec3f(v[4], v[5], v[6]), Vec3f(v[8], v[9], v[10]),
                                  Vec3f(v[12], v[13], v[14])};
    const Vec3f p = evaluate_bezier(cp, u, tangent);
    *tangent = normalize(*tangent);
    return p;
}

float CurveSet::render_width(int segment, float u) const {
    const Segment &s = segments_[segment];
    return lerp(u, s.width[0], s.width[1]) * render_scale_;
}

bool CurveSet::covers(int segment, float u, Vec3f o, Vec3f d, float t) const {
    if (type_ != CurveType::Ribbon) return true;
    const Segment &s = segments_[segment];
    u = std::clamp(u, 0.f, 1.f);
    const Vec3f p = object_from_render_.apply_point(o + d * t);
    const Vec3f direction = normalize(object_from_render_.apply_vector(d));
    Vec3f unused;
    const Vec3f offset = p - evaluate_bezier(s.p, u, &unused);
    // The distance from the curve across the ray, as pbrt-v4 measures it in the plane that
    // faces the ray.
    const float distance = length(offset - direction * dot(offset, direction));
    const float width = lerp(u, s.width[0], s.width[1]) * std::abs(dot(ribbon_normal(s, u), direction));
    return distance <= 0.5f * width;
}

void CurveSet::interaction(int segment, float u, const Ray &ray, float t, SurfaceInteraction *si) const {
    const Segment &s = segments_[segment];
    u = std::clamp(u, 0.f, 1.f);
    // As pbrt-v4, in object space (the ray parameter is the same there).
    const Vec3f p = object_from_render_.apply_point(ray.at(t));
    const Vec3f d = object_from_render_.apply_vector(ray.d);
    Vec3f dpdu;
    const Vec3f centre = evaluate_bezier(s.p, u, &dpdu);
    const float width = lerp(u, s.width[0], s.width[1]);
    // dp/dv spans the width: across the curve, facing the ray (flat and cylinder) or
    // perpendicular to the ribbon's normal.
    Vec3f across = type_ == CurveType::Ribbon ? cross(ribbon_normal(s, u), dpdu) : cross(d, dpdu);
    if (length_squared(across) == 0) {
        Vec3f unused;
        coordinate_system(normalize(dpdu), &across, &unused);
    }
    across = normalize(across);
    // A curve that narrows to nothing (width1 0, as hair tips often do) can be met where its
    // width is 0: v is then the middle, and the normal comes from the unit direction across.
    const float v = width > 0 ? std::clamp(0.5f + dot(p - centre, across) / width, 0.f, 1.f) : 0.5f;
    if (type_ == CurveType::Cylinder) {
        // pbrt-v4 turns dp/dv about the tangent from +90 degrees at v = 0 to -90 at v = 1, so
        // that the normal sweeps across the ribbon as a tube's would.
        const float theta = Pi * (v - 0.5f);
        across = rotate_about(across, normalize(dpdu), -theta);
    }
    const Vec3f dpdv = across * width;
    Vec3f n = normalize(cross(dpdu, across));
    if (flip_normal_) n = -n;

    si->p = ray.at(t);
    si->n = normalize(render_from_object_.apply_normal(n));
    si->uv = {u, v};
    si->dpdu = render_from_object_.apply_vector(dpdu);
    si->dpdv = render_from_object_.apply_vector(dpdv);
    si->shading.n = si->n;
    si->shading.dpdu = si->dpdu;
    si->shading.dpdv = si->dpdv;
}

std::shared_ptr<CurveSet> create_curves(const Transform &render_from_object, bool reverse_orientation,
                                        const ParameterDictionary &params) {
    const float width = params.get_one_float("width", 1);
    const float width0 = params.get_one_float("width0", width), width1 = params.get_one_float("width1", width);
    for (const char *name : {"width", "width0", "width1"})
        if (params.has(name) && !(params.get_one_float(name, 1) >= 0 && std::isfinite(params.get_one_float(name, 1))))
            throw InputError(params.location(name), std::string("curve: \"") + name + "\" must be a non-negative number");
    const int degree = params.get_one_int("degree", 3);
    if (degree != 2 && degree != 3)
        throw InputError(params.location("degree"),
                         "curve: degree " + std::to_string(degree) + "; only 2 and 3 are supported");
    const std::string basis = params.get_one_string("basis", "bezier");
    if (basis != "bezier" && basis != "bspline")
        throw InputError(params.location("basis"),
                         "curve: basis \"" + basis + "\"; only \"bezier\" and \"bspline\" are supported");
    const std::string type_name = params.get_one_string("type", "flat");
    CurveType type;
    if (type_name == "flat") type = CurveType::Flat;
    else if (type_name == "ribbon") type = CurveType::Ribbon;
    else if (type_name == "cylinder") type = CurveType::Cylinder;
    else
        throw InputError(params.location("type"),
                         "curve: type \"" + type_name + "\"; expected \"flat\", \"ribbon\" or \"cylinder\"");
    params.get_one_int("splitdepth", 3);

    const std::vector<Vec3f> cp = params.get_point3_array("P");
    for (const Vec3f &p : cp)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw InputError(params.location("P"), "curve: a control point is not finite");
    size_t segment_count;
    if (basis == "bezier") {
        // The first segment takes degree + 1 points; each next one shares the last of them.
        if (cp.size() < size_t(degree) + 1 || (cp.size() - 1) % degree != 0)
            throw InputError(params.location("P"), "curve: " + count(cp.size()) + " control points; a degree " +
                                                       std::to_string(degree) + " Bezier curve needs " +
                                                       std::to_string(degree + 1) + " + n * " +
                                                       std::to_string(degree) + " of them");
        segment_count = (cp.size() - 1) / degree;
    } else {
        if (cp.size() < size_t(degree) + 1)
            throw InputError(params.location("P"), "curve: " + count(cp.size()) + " control points; a degree " +
                                                       std::to_string(degree) + " B-spline needs at least " +
                                                       std::to_string(degree + 1));
        segment_count = cp.size() - degree;
    }

    std::vector<Vec3f> normals = params.get_normal_array("N");
    if (type == CurveType::Ribbon) {
        if (normals.size() != segment_count + 1)
            throw InputError(params.location("N"), "curve: a ribbon of " + count(segment_count) + " segments needs " +
                                                       count(segment_count + 1) + " normals \"N\", not " +
                                                       count(normals.size()));
        for (Vec3f &n : normals) {
            if (!(length_squared(n) > 0) || !std::isfinite(length_squared(n)))
                throw InputError(params.location("N"), "curve: a normal \"N\" is zero or not finite");
            n = normalize(n);
        }
    } else if (!normals.empty()) {
        warning(params.location("N"), "curve: normals \"N\" are used only by \"ribbon\" curves; ignored");
    }

    std::vector<CurveSet::Segment> segments(segment_count);
    for (size_t i = 0; i < segment_count; ++i) {
        CurveSet::Segment &s = segments[i];
        if (basis == "bezier") {
            const Vec3f *q = &cp[i * degree];
            s.p = degree == 2 ? elevate_quadratic({q[0], q[1], q[2]}) : std::array<Vec3f, 4>{q[0], q[1], q[2], q[3]};
        } else {
            s.p = degree == 2 ? elevate_quadratic(quadratic_bspline_to_bezier(&cp[i])) : cubic_bspline_to_bezier(&cp[i]);
        }
        s.width[0] = lerp(float(i) / segment_count, width0, width1);
        s.width[1] = lerp(float(i + 1) / segment_count, width0, width1);
        if (type == CurveType::Ribbon) s.n[0] = normals[i], s.n[1] = normals[i + 1];
    }
    return std::make_shared<CurveSet>(render_from_object, reverse_orientation, type, std::move(segments));
}

}  // namespace caustica
