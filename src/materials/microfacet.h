// The Trowbridge-Reitz (GGX) microfacet distribution with anisotropic roughness.
//
// Distribution: Trowbridge and Reitz 1975, "Average irregularity representation of a rough
// surface for ray reflection"; Walter et al. 2007, "Microfacet Models for Refraction through
// Rough Surfaces". Masking: Smith's height-correlated form as derived by Heitz 2014,
// "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs". Sampling: the
// distribution of normals visible from a direction (Heitz 2018, "Sampling the GGX Distribution
// of Visible Normals"), which makes sample weights bounded by the masking term.
//
// All directions are in the local shading frame (normal +z); microfacet normals wm lie in the
// upper hemisphere.
#pragma once

#include "core/vecmath.h"

namespace caustica {

class TrowbridgeReitzDistribution {
  public:
    TrowbridgeReitzDistribution() = default;
    TrowbridgeReitzDistribution(float alpha_x, float alpha_y);

    // pbrt-v4's mapping from a user "roughness" to alpha when remaproughness is set: the square
    // root makes roughness perceptually more uniform.
    static float roughness_to_alpha(float roughness) { return std::sqrt(roughness); }

    // Below this alpha the lobe is narrower than float precision resolves reliably in the
    // half-vector Jacobians, so materials switch to the perfectly specular model (as pbrt-v4).
    bool effectively_smooth() const { return std::max(alpha_x_, alpha_y_) < 1e-3f; }
    // pbrt-v4's path regularisation (its "regularize" integrator parameter, after Kaplanyan and
    // Dachsbacher 2013, "Path space regularization for holistic and robust light transport"):
    // each alpha below 0.3 is doubled and kept in [0.1, 0.3], so that a smooth or near-smooth
    // lobe met after a diffuse bounce becomes glossy enough for light sampling and connections
    // to find what only chance finds through a delta (a caustic seen by a path tracer). Biased
    // by design: the blur is the price of the noise it removes.
    TrowbridgeReitzDistribution regularized() const;
    float alpha_x() const { return alpha_x_; }
    float alpha_y() const { return alpha_y_; }

    // Density of microfacet normals per unit projected area: integral of D(wm) cos(wm) = 1.
    float D(Vec3f wm) const;
    // Smith's auxiliary function: the masking of direction w is G1(w) = 1 / (1 + Lambda(w)).
    float Lambda(Vec3f w) const;
    float G1(Vec3f w) const { return 1 / (1 + Lambda(w)); }
    // Height-correlated masking-shadowing (Heitz 2014, eq. 99).
    float G(Vec3f wo, Vec3f wi) const { return 1 / (1 + Lambda(wo) + Lambda(wi)); }
    // Distribution of normals visible from w (Heitz 2014, eq. 38): G1(w) max(0, w.wm) D(wm) / cos(w).
    // Integrates to 1 over wm for every w.
    float D(Vec3f w, Vec3f wm) const;
    // Density of sample_wm(w, u) with respect to solid angle of wm.
    float pdf(Vec3f w, Vec3f wm) const { return D(w, wm); }
    // Density of wi = reflect(wo, wm) for wm drawn by sample_wm(wo, .), where wm is the half
    // vector of wo and wi in the same hemisphere: the visible-normal density times the Jacobian
    // 1 / (4 |wo.wm|) of the reflection map, in which wo.wm cancels, leaving G1(wo) D(wm) /
    // (4 |cos wo|). Such a half vector is always visible from wo (wo.(wo + wi) = 1 + wo.wi > 0),
    // but for nearly opposite grazing directions wo.wm is a cancellation that float rounding can
    // make zero or negative: dividing it out keeps the density exact there, so pdf() agrees
    // with sample_f() at every direction sampling returns.
    float reflection_pdf(Vec3f wo, Vec3f wm) const;
    // Samples a visible normal from the side of w (w may be below the surface; the normal is
    // always returned in the upper hemisphere).
    Vec3f sample_wm(Vec3f w, Vec2f u) const;

  private:
    float alpha_x_ = 1, alpha_y_ = 1;
};

} // namespace caustica
