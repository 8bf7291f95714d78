#include "geometry/bilinear_patch.h"

#include "core/sampling.h"
#include "geometry/vec3d.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace caustica {

namespace {

Vec3d lerp(double t, Vec3d a, Vec3d b) { return a * (1 - t) + b * t; }
Vec3f lerp(float t, Vec3f a, Vec3f b) { return a * (1 - t) + b * t; }
Vec2f lerp(float t, Vec2f a, Vec2f b) { return a * (1 - t) + b * t; }
// The determinant of the matrix with columns a, b, c.
double determinant(Vec3d a, Vec3d b, Vec3d c) { return dot(a, cross(b, c)); }

// The corners of a patch in double, and the derivatives of P at (u, v).
struct PatchCorners {
    Vec3d p00, p10, p01, p11;
    Vec3d point(double u, double v) const { return lerp(u, lerp(v, p00, p01), lerp(v, p10, p11)); }
    Vec3d dpdu(double v) const { return lerp(v, p10, p11) - lerp(v, p00, p01); }
    Vec3d dpdv(double u) const { return lerp(u, p01, p11) - lerp(u, p00, p10); }
};

PatchCorners corners_in_double(const std::array<Vec3f, 4> &c) {
    return {Vec3d(c[0]), Vec3d(c[1]), Vec3d(c[2]), Vec3d(c[3])};
}

// The unit normal of the patch's winding, dP/du x dP/dv, at uv. Where an edge has collapsed to a
// point (a patch that is a triangle) that product vanishes along it; the diagonals' cross product
// has the same orientation (twice dP/du x dP/dv for a parallelogram) and is the plane's normal
// for planar patches.
Vec3f winding_normal(const PatchCorners &c, Vec2f uv) {
    Vec3d winding = cross(c.dpdu(uv.y), c.dpdv(uv.x));
    if (!(length_squared(winding) > 0)) winding = cross(c.p11 - c.p00, c.p01 - c.p10);
    if (!(length_squared(winding) > 0)) return {0, 0, 1};
    return normalize(winding).to_float();
}

// Per-vertex values at a patch's corners v, interpolated bilinearly at uv.
template <typename T>
T interpolate(const std::vector<T> &values, const int *v, Vec2f uv) {
    return lerp(uv.x, lerp(uv.y, values[v[0]], values[v[2]]), lerp(uv.y, values[v[1]], values[v[3]]));
}

// The real roots of a u^2 + b u + c in increasing order; returns their number. A quadratic term
// that is negligible against the others (a patch that is nearly a parallelogram) leaves the
// linear equation.
int solve_quadratic(double a, double b, double c, double roots[2]) {
    if (std::abs(a) <= 1e-12 * (std::abs(b) + std::abs(c))) {
        if (b == 0) return 0;
        roots[0] = -c / b;
        return 1;
    }
    const double discriminant = b * b - 4 * a * c;
    if (discriminant < 0) return 0;
    // The root of larger magnitude first, then the other from the product c / a, which avoids
    // cancellation.
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    if (q == 0) {
        roots[0] = 0;
        return 1;
    }
    roots[0] = q / a;
    roots[1] = c / q;
    if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    return 2;
}

} // namespace

BilinearPatchMesh::BilinearPatchMesh(const Transform &render_from_object, bool reverse_orientation,
                                     std::vector<int> indices, std::vector<Vec3f> p, std::vector<Vec3f> n,
                                     std::vector<Vec2f> uv)
    : indices_(std::move(indices)),
      p_(std::move(p)),
      n_(std::move(n)),
      uv_(std::move(uv)),
      flip_normal_(reverse_orientation != render_from_object.swaps_handedness()) {
    for (Vec3f &q : p_) q = render_from_object.apply_point(q);
    for (Vec3f &m : n_) m = render_from_object.apply_normal(m);
}

std::array<Vec3f, 4> BilinearPatchMesh::corners(int patch) const {
    const int *v = &indices_[4 * size_t(patch)];
    return {p_[v[0]], p_[v[1]], p_[v[2]], p_[v[3]]};
}

Bounds3f BilinearPatchMesh::bounds(int patch) const {
    // The patch lies in the convex hull of its corners.
    Bounds3f b;
    for (Vec3f c : corners(patch)) b.expand(c);
    return b;
}

Bounds3f BilinearPatchMesh::bounds() const {
    Bounds3f b;
    for (int i = 0; i < patch_count(); ++i) b.expand(bounds(i));
    return b;
}

int BilinearPatchMesh::hits(int patch, Vec3f o_f, Vec3f d_f, float t_max, Hit out[2]) const {
    const PatchCorners c = corners_in_double(corners(patch));
    const Vec3d o(o_f), d(d_f);
    // The ray and the line of constant u, from lerp(u, p00, p10) to lerp(u, p01, p11), are
    // coplanar where det(lerp(u, p00, p10) - o, d, line direction) = 0: a quadratic in u whose
    // values at u = 0 and 1 and leading coefficient are these.
    const double a = dot(cross(c.p10 - c.p00, c.p01 - c.p11), d);
    const double c0 = dot(cross(c.p00 - o, d), c.p01 - c.p00);
    const double b = dot(cross(c.p10 - o, d), c.p11 - c.p10) - (a + c0);
    double roots[2];
    const int root_count = solve_quadratic(a, b, c0, roots);
    int count = 0;
    for (int i = 0; i < root_count; ++i) {
        const double u = roots[i];
        if (!(u >= 0 && u <= 1) || (i == 1 && u == roots[0])) continue;
        // o + t d = origin + v line: solved with the common perpendicular of d and the line.
        const Vec3d origin = lerp(u, c.p00, c.p10), line = lerp(u, c.p01, c.p11) - origin;
        const Vec3d delta = origin - o, perpendicular = cross(d, line);
        const double p2 = length_squared(perpendicular);
        if (p2 == 0) continue;
        const double v = determinant(delta, d, perpendicular) / p2;
        const double t = determinant(delta, line, perpendicular) / p2;
        const bool on_patch = v >= 0 && v <= 1;
        const bool ahead = t > 0 && t < double(t_max) && t < double(std::numeric_limits<float>::max());
        if (!on_patch || !ahead) continue;
        const float t_f = float(t);
        if (!(t_f > 0) || !(t_f < t_max)) continue;
        out[count++] = {t_f, {float(u), float(v)}};
    }
    if (count == 2 && out[1].t < out[0].t) std::swap(out[0], out[1]);
    return count;
}

Vec3f BilinearPatchMesh::point(int patch, Vec2f uv) const {
    return corners_in_double(corners(patch)).point(uv.x, uv.y).to_float();
}

Vec3f BilinearPatchMesh::oriented(Vec3f n, Vec3f n_interpolated) const {
    if (!n_.empty()) return length_squared(n_interpolated) > 0 ? face_forward(n, n_interpolated) : n;
    return flip_normal_ ? -n : n;
}

Vec3f BilinearPatchMesh::normal(int patch, Vec2f uv) const {
    const Vec3f n = winding_normal(corners_in_double(corners(patch)), uv);
    return oriented(n, n_.empty() ? Vec3f{} : interpolate(n_, &indices_[4 * size_t(patch)], uv));
}

Vec2f BilinearPatchMesh::texture_uv(int patch, Vec2f uv) const {
    return uv_.empty() ? uv : interpolate(uv_, &indices_[4 * size_t(patch)], uv);
}

float BilinearPatchMesh::area_element(int patch, Vec2f uv) const {
    const PatchCorners c = corners_in_double(corners(patch));
    return float(length(cross(c.dpdu(uv.y), c.dpdv(uv.x))));
}

float BilinearPatchMesh::error_scale(int patch) const {
    float scale = 0;
    for (Vec3f c : corners(patch)) scale = std::max(scale, max_component(abs(c)));
    return scale;
}

Vec2f BilinearPatchMesh::parameters_of(int patch, Vec3f p_f) const {
    const PatchCorners c = corners_in_double(corners(patch));
    const Vec3d p(p_f);
    double u = 0.5, v = 0.5;
    // Gauss-Newton on |P(u, v) - p|^2; P is bilinear, so a few steps reach float precision.
    for (int step = 0; step < 8; ++step) {
        const Vec3d r = c.point(u, v) - p, pu = c.dpdu(v), pv = c.dpdv(u);
        const double a = dot(pu, pu), b = dot(pu, pv), d = dot(pv, pv);
        const double det = a * d - b * b;
        if (!(det > 0)) break;
        const double gu = dot(pu, r), gv = dot(pv, r);
        const double du = (d * gu - b * gv) / det, dv = (a * gv - b * gu) / det;
        u = std::clamp(u - du, 0.0, 1.0);
        v = std::clamp(v - dv, 0.0, 1.0);
        if (std::abs(du) + std::abs(dv) < 1e-9) break;
    }
    return {float(u), float(v)};
}

void BilinearPatchMesh::interaction(int patch, Vec2f uv, SurfaceInteraction *si) const {
    const PatchCorners c = corners_in_double(corners(patch));
    const int *v = &indices_[4 * size_t(patch)];
    si->p = c.point(uv.x, uv.y).to_float();
    si->error_scale = error_scale(patch);
    si->face_index = patch;
    Vec3d dpdu = c.dpdu(uv.y), dpdv = c.dpdv(uv.x);
    const Vec3d n_winding = cross(dpdu, dpdv);
    si->uv = uv_.empty() ? uv : interpolate(uv_, v, uv);
    if (!uv_.empty()) {
        // Derivatives with respect to the texture coordinates (s, t): through the inverse of the
        // Jacobian d(s, t)/d(u, v) of the bilinear map of the uv corners. pbrt-v4 inverts each
        // entry separately, which agrees when the uv map is axis-aligned. A Jacobian that
        // mirrors turns dp/dt over, so that dp/ds x dp/dt keeps the patch's orientation, as in
        // pbrt-v4.
        const Vec2f st_u = lerp(uv.y, uv_[v[1]], uv_[v[3]]) - lerp(uv.y, uv_[v[0]], uv_[v[2]]);
        const Vec2f st_v = lerp(uv.x, uv_[v[2]], uv_[v[3]]) - lerp(uv.x, uv_[v[0]], uv_[v[1]]);
        const double det = double(st_u.x) * st_v.y - double(st_v.x) * st_u.y;
        if (std::abs(det) > 1e-12) {
            // (du, dv)/ds and (du, dv)/dt are the columns of the inverse Jacobian.
            const Vec3d dpds = (dpdu * st_v.y - dpdv * st_u.y) / det;
            Vec3d dpdt = (dpdv * st_u.x - dpdu * st_v.x) / det;
            if (dot(cross(dpds, dpdt), n_winding) < 0) dpdt = -dpdt;
            dpdu = dpds;
            dpdv = dpdt;
        }
    }
    si->dpdu = dpdu.to_float();
    si->dpdv = dpdv.to_float();
    const Vec3f n_interpolated = n_.empty() ? Vec3f{} : interpolate(n_, v, uv);
    si->n = oriented(winding_normal(c, uv), n_interpolated);
    si->shading.n = si->n;
    si->shading.dpdu = si->dpdu;
    si->shading.dpdv = si->dpdv;
    if (length_squared(n_interpolated) > 0) si->set_shading_normal(normalize(n_interpolated));
}

BilinearPatch::BilinearPatch(std::shared_ptr<const BilinearPatchMesh> mesh, int index)
    : mesh_(std::move(mesh)), index_(index) {
    static const Vec2f corner_uv[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    for (int k = 0; k < 4; ++k) corner_area_elements_[k] = mesh_->area_element(index_, corner_uv[k]);
    // The area element is the length of a vector linear in (u, v) (dP/du x dP/dv has no uv
    // term), smooth over the patch: 8 x 8 midpoint samples give the area well within the
    // precision that light selection needs.
    constexpr int n = 8;
    double area = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            area += mesh_->area_element(index_, {(i + 0.5f) / n, (j + 0.5f) / n});
    area_ = float(area / (n * n));
}

float BilinearPatch::parameter_pdf(Vec2f uv) const { return bilinear_pdf(uv, corner_area_elements_); }

std::optional<ShapeSample> BilinearPatch::sample(Vec2f u) const {
    const Vec2f uv = sample_bilinear(u, corner_area_elements_);
    const float element = mesh_->area_element(index_, uv);
    if (!(element > 0)) return std::nullopt;
    ShapeSample s;
    s.p = mesh_->point(index_, uv);
    s.n = mesh_->normal(index_, uv);
    s.error_scale = mesh_->error_scale(index_);
    s.uv = mesh_->texture_uv(index_, uv);
    s.pdf = parameter_pdf(uv) / element;
    return s;
}

float BilinearPatch::pdf_area(Vec3f p) const {
    const Vec2f uv = mesh_->parameters_of(index_, p);
    const float element = mesh_->area_element(index_, uv);
    return element > 0 ? parameter_pdf(uv) / element : 0;
}

float BilinearPatch::pdf(Vec3f ref, Vec3f wi) const {
    BilinearPatchMesh::Hit hits[2];
    if (mesh_->hits(index_, ref, wi, Infinity, hits) == 0) return 0;
    const Vec2f uv = hits[0].uv;
    const Vec3f p = mesh_->point(index_, uv);
    const float cos_light = abs_dot(mesh_->normal(index_, uv), normalize(wi));
    const float element = mesh_->area_element(index_, uv);
    if (cos_light == 0 || !(element > 0)) return 0;
    const float pdf = parameter_pdf(uv) / element * distance_squared(ref, p) / cos_light;
    return std::isfinite(pdf) ? pdf : 0;
}

std::optional<Shape::Hit> BilinearPatch::intersect(Vec3f o, Vec3f d, float t_max) const {
    BilinearPatchMesh::Hit hits[2];
    if (mesh_->hits(index_, o, d, t_max, hits) == 0) return std::nullopt;
    const Vec2f uv = hits[0].uv;
    return Hit{hits[0].t, mesh_->point(index_, uv), mesh_->normal(index_, uv), mesh_->texture_uv(index_, uv)};
}

} // namespace caustica
