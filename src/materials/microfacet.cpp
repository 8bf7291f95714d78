#include "materials/microfacet.h"

namespace caustica {

TrowbridgeReitzDistribution::TrowbridgeReitzDistribution(float alpha_x, float alpha_y)
    : alpha_x_(alpha_x), alpha_y_(alpha_y) {
    // Smooth surfaces never evaluate D (their BxDFs use the specular models). A rough surface
    // may still be smooth along one axis, where alpha = 0 would make D a 0/0: the floor keeps
    // such anisotropic lobes finite, and at 1e-4 it is far below what a render resolves.
    if (effectively_smooth()) return;
    alpha_x_ = std::max(alpha_x_, 1e-4f);
    alpha_y_ = std::max(alpha_y_, 1e-4f);
}

TrowbridgeReitzDistribution TrowbridgeReitzDistribution::regularized() const {
    auto widen = [](float alpha) { return alpha < 0.3f ? std::clamp(2 * alpha, 0.1f, 0.3f) : alpha; };
    return {widen(alpha_x_), widen(alpha_y_)};
}

float TrowbridgeReitzDistribution::D(Vec3f wm) const {
    // The ellipsoid form of GGX, 1 / (pi ax ay ((x/ax)^2 + (y/ay)^2 + z^2)^2) for unit wm, which
    // equals the usual tan^2-based expression but stays finite at grazing normals.
    if (wm.z <= 0) return 0;
    float e = sqr(wm.x / alpha_x_) + sqr(wm.y / alpha_y_) + sqr(wm.z);
    return 1 / (Pi * alpha_x_ * alpha_y_ * sqr(e));
}

float TrowbridgeReitzDistribution::Lambda(Vec3f w) const {
    // Lambda = (sqrt(1 + alpha(phi)^2 tan^2(theta)) - 1) / 2, with alpha(phi)^2 tan^2(theta)
    // written as (ax^2 x^2 + ay^2 y^2) / z^2 (Heitz 2014, eq. 86 with the anisotropic alpha).
    float z2 = sqr(w.z);
    if (z2 == 0) return Infinity;
    float alpha2_tan2 = (sqr(alpha_x_ * w.x) + sqr(alpha_y_ * w.y)) / z2;
    return (std::sqrt(1 + alpha2_tan2) - 1) / 2;
}

float TrowbridgeReitzDistribution::D(Vec3f w, Vec3f wm) const {
    float cos_w = std::abs(w.z);
    if (cos_w == 0) return 0;
    // Visible from w's side: normals facing away from w are hidden. For w below the surface the
    // microsurface is seen from below, which by symmetry is the mirrored problem.
    float w_dot_m = w.z < 0 ? -dot(w, wm) : dot(w, wm);
    if (w_dot_m <= 0) return 0;
    return G1(w) / cos_w * D(wm) * w_dot_m;
}

float TrowbridgeReitzDistribution::reflection_pdf(Vec3f wo, Vec3f wm) const {
    float cos_o = std::abs(wo.z);
    if (cos_o == 0) return 0;
    return G1(wo) * D(wm) / (4 * cos_o);
}

Vec3f TrowbridgeReitzDistribution::sample_wm(Vec3f w, Vec2f u) const {
    // Heitz 2018, section 3: stretch the view direction so the distribution becomes the
    // hemisphere of a unit isotropic GGX (alpha = 1), sample the projected area of that
    // hemisphere seen from the stretched direction, and unstretch the resulting normal.
    Vec3f wv = w.z < 0 ? -w : w;
    Vec3f vh = normalize(Vec3f(alpha_x_ * wv.x, alpha_y_ * wv.y, wv.z));

    // Orthonormal basis around vh; T1 is horizontal so the half-disk warp below is along T2.
    float len2 = sqr(vh.x) + sqr(vh.y);
    Vec3f t1 = len2 > 0 ? Vec3f(-vh.y, vh.x, 0) / std::sqrt(len2) : Vec3f(1, 0, 0);
    Vec3f t2 = cross(vh, t1);

    // Uniform point on the unit disk; then the half of the disk behind the hemisphere's
    // silhouette is squeezed so that the projected area of the visible hemisphere is uniform.
    float r = std::sqrt(u.x);
    float phi = 2 * Pi * u.y;
    float p1 = r * std::cos(phi), p2 = r * std::sin(phi);
    float s = 0.5f * (1 + vh.z);
    p2 = (1 - s) * std::sqrt(std::max(0.f, 1 - sqr(p1))) + s * p2;

    // Lift to the hemisphere, then transform the normal back (inverse-transpose of the stretch).
    Vec3f nh = t1 * p1 + t2 * p2 + vh * safe_sqrt(1 - sqr(p1) - sqr(p2));
    return normalize(Vec3f(alpha_x_ * nh.x, alpha_y_ * nh.y, std::max(1e-6f, nh.z)));
}

} // namespace caustica
