// The Disney BSDF: Burley 2015, "Extending the Disney BRDF to a BSDF with Integrated Subsurface
// Scattering" (SIGGRAPH course notes), built on the Disney BRDF of Burley 2012, "Physically-Based
// Shading at Disney". With `subsurface` set (a solid with scatterDistance > 0), the Lambertian
// part of the diffuse lobe is replaced by a path-traced volume (section 2.5): see "Subsurface"
// below.
//
// The BSDF is a blend of three models (the notes' Figure 4), with weights
//   metallic BRDF     metallic
//   dielectric BRDF   (1 - metallic) (1 - specTrans)
//   specular BSDF     (1 - metallic) specTrans,
// plus two lobes outside the blend: sheen, weighted by 1 - metallic (it belongs to both
// non-metallic models, section 2.2), and clearcoat. The lobes are
//   - diffuse (dielectric BRDF): eq. 4, Lambert with Schlick-weight edge darkening plus the
//     roughness-dependent retro-reflection. On thin surfaces (section 2.6) the Lambertian part
//     is blended towards the Hanrahan-Krueger-like shape of the 2012 BRDF by `flatness` and
//     shares its energy with an isotropic diffuse transmission lobe through `diffTrans`;
//   - sheen: sheen (1 - cos theta_d)^5, tinted towards the base colour's hue by sheenTint;
//   - specular reflection (metallic and dielectric BRDFs): GGX with anisotropic roughness and
//     Heitz's height-correlated Smith G (section 3.3). The metal's Fresnel factor is Schlick's
//     with F0 = baseColor; the dielectric's is the exact Fresnel term blended by specularTint
//     towards Schlick's with the tinted F0 and the critical-angle fix of eq. 7 (section 3.1);
//   - specular BSDF on solids (section 2.2): Walter et al.'s rough dielectric with the exact
//     Fresnel term (DielectricBxDF: the 1/eta^2 factor in Radiance mode only, dispersion), its
//     transmission multiplied by sqrt(baseColor) (surface absorption; entering and leaving
//     through the surface applies it twice);
//   - thin specular transmission (section 2.6): the reflection lobe's microfacet model mirrored
//     to the other side, with roughness scaled by 0.65 eta - 0.35 (Figure 15), weighted by
//     1 - F and the full baseColor (one event stands for entering and leaving);
//   - clearcoat (2012 model, unchanged per section 3.3): GTR1 with alpha from clearcoatGloss,
//     Schlick with F0 = 0.04 (eta 1.5), separable Smith G of GGX with alpha 0.25, scaled by
//     clearcoat / 4.
//
// Sides. The solid specular BSDF is the only lobe that knows inside from outside (its eta is
// the inside's index over the outside's). The diffuse and specular reflection lobes are
// two-sided: seen from below they are the mirror image of the lobes seen from above, with
// relative index eta. For a thin surface both sides are outsides by definition; for a solid with
// specTrans < 1 the BRDF part is an opaque-surface model, and light that meets it from inside
// scatters back as it would from outside (no total internal reflection outside the specular
// BSDF). Sheen and clearcoat are layers on the outside: thin surfaces have them on both faces,
// solids only for light arriving from outside (from inside they would add reflection to total
// internal reflection, creating energy).
//
// Subsurface (random walk, section 2.5). The notes refactor the diffuse lobe (eq. 4) so that its
// Lambertian part f_Lambert (1 - F_L / 2)(1 - F_V / 2) can be swapped for subsurface scattering
// while the retro-reflection stays a surface effect. Here that part becomes a crossing of the
// surface: light from outside enters through a Lambertian transmission lobe
// (w / pi)(1 - F_V / 2) and walks through the interior medium (DisneyMaterial gives it the
// coefficients that reflect baseColor); from inside, a walk that reaches the surface leaves
// through the mirror-image lobe (w / pi)(1 - F_L / 2), where F is Schlick's weight of the
// OUTSIDE direction, so the pair is reciprocal and the product of the two crossings is eq. 4's
// edge darkening. The exit lobe's albedo is 41/42; the remaining 1/42 is reflected back inside by
// a constant (Lambertian) lobe, so the boundary neither creates nor loses energy. w is the
// dielectric BRDF's blend weight; the crossing is colourless (the colour comes from the volume).
// From inside only these two lobes and the specular BSDF act.
//
// Subsurface with a profile (diffusion or dipole, `profile_subsurface`). There is no interior
// volume: the path tracer samples where the light leaves from a radial profile (a separable
// BSSRDF, see DisneyMaterial). The profile does not depend on the direction in which light
// entered, so from outside the crossing is a discrete event rather than a direction: sample_f
// returns it with wi straight into the surface, flags BxDFDiffuseTransmission, pdf the lobe's
// selection probability and f |cos| = w (1 - F_V / 2), the share that enters; f() and pdf() leave
// it out, since no light scatters into a direction there (next-event estimation and the MIS
// densities of the other lobes must not see it). It is the only diffuse transmission a solid
// samples from outside, which is how the path tracer recognises it. The exit lobe is
// DisneySubsurfaceExitBxDF below. From inside, the lobes are the random walk's.
//
// Sampling picks one lobe with probability proportional to an estimate of its directional
// albedo at wo (any positive choice is unbiased; a good one keeps f |cos| / pdf near the total
// albedo). For non-delta samples f and pdf are the whole BSDF's: pdf is the sum over lobes of
// selection probability times the lobe's density, which is what f / pdf and MIS need. Delta
// lobes (roughness 0: mirror reflection, smooth refraction, straight-through thin transmission)
// return their own value with pdf = selection probability times the discrete probability.
#pragma once

#include "materials/bxdf.h"
#include "materials/subsurface_exit_lobe.h"
#include "materials/dielectric_bxdf.h"
#include "materials/microfacet.h"

namespace caustica {

// The Disney BSDF's inputs at one surface point for the path's wavelengths. Scalars are
// expected in their documented ranges (DisneyMaterial clamps textured values to them).
struct DisneyParameters {
    SampledSpectrum base_color = SampledSpectrum(0.5f);  // [0, 1]
    // The base colour's luminance (CIE Y of the reflectance under an equal-energy illuminant):
    // specular and sheen tints are base_color / luminance, the colour's hue and saturation.
    float base_luminance = 0.5f;
    float metallic = 0;         // [0, 1]
    float roughness = 0.5f;     // [0, 1]
    float anisotropic = 0;      // [0, 1]
    float specular_tint = 0;    // [0, 1]
    float sheen = 0;            // >= 0
    float sheen_tint = 0.5f;    // [0, 1]
    float clearcoat = 0;        // >= 0
    float clearcoat_gloss = 1;  // [0, 1]
    float spec_trans = 0;       // [0, 1]
    // Index of the inside relative to the outside, per wavelength.
    SampledSpectrum eta = SampledSpectrum(1.5f);
    // One index for the whole spectrum where the model needs a single number: the thin-surface
    // transmission roughness scale. DisneyMaterial uses the index at the helium d line.
    float reference_eta = 1.5f;
    bool thin = false;
    // An interference film on the specular lobes (absent by default; thin_film.h). Over the
    // dielectric it replaces the interface's Fresnel reflectance, on the specular BSDF too; over
    // the metallic lobe, whose Schlick colour has no complex index, it lies on the real index
    // that reflects base_color at normal incidence.
    ThinFilm film;
    float diff_trans = 0;  // [0, 2], thin surfaces only
    float flatness = 0;    // [0, 1], thin surfaces only
    bool subsurface = false; // solids only: subsurface scattering (see above)
    // With subsurface: a profile (diffusion or dipole) instead of the random walk.
    bool profile_subsurface = false;
};

class DisneyBxDF final : public BxDF {
  public:
    explicit DisneyBxDF(const DisneyParameters &p);

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode mode) const override;
    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override;
    float pdf(Vec3f wo, Vec3f wi, TransportMode mode,
              SampleFlags flags = SampleFlags::All) const override;
    BxDFFlags flags() const override;
    // Those of the specular BSDF (a rough dispersive solid): its share of every density is then
    // per lane, the other lobes' are not.
    bool has_lane_lobes() const override { return present_[SpecularBSDF] && specular_bsdf_.has_lane_lobes(); }
    std::optional<BSDFSample> sample_f_as(int lane, Vec3f wo, float uc, Vec2f u, TransportMode mode) const override;

    // The 2012 mapping from roughness and anisotropic to GGX alphas: alpha = roughness^2,
    // stretched by aspect = sqrt(1 - 0.9 anisotropic) (alpha_x = alpha / aspect along dpdu).
    static TrowbridgeReitzDistribution specular_distribution(float roughness, float anisotropic);
    // Clearcoat's GTR1 (Berry) distribution: D(wm) = (a^2 - 1) / (pi ln(a^2) (1 + (a^2 - 1)
    // cos^2 theta_m)), normalised so that the projected microfacet area is 1. wm is a unit
    // vector: the denominator is evaluated as sin^2 + a^2 cos^2, which keeps its precision for
    // alpha = 0.001, where 1 - cos^2 would cancel.
    static float gtr1(Vec3f wm, float alpha);
    // Clearcoat alpha: 0.1 at gloss 0 down to 0.001 at gloss 1.
    static float clearcoat_alpha(float gloss) { return lerp(gloss, 0.1f, 0.001f); }
    // The thin-surface transmission roughness (Figure 15): roughness (0.65 eta - 0.35).
    static float thin_transmission_roughness(float roughness, float eta) {
        return clamp(roughness * (0.65f * eta - 0.35f), 0.f, 1.f);
    }

  private:
    // The lobes sampling chooses between.
    enum Lobe { Diffuse, DiffuseTransmission, SpecularReflection, SpecularBSDF, ThinTransmission,
                Clearcoat, Subsurface, InternalReflection, LobeCount };
    struct LobeProbabilities {
        float p[LobeCount] = {};
    };
    LobeProbabilities lobe_probabilities(Vec3f wo, SampleFlags flags) const;
    // sample_f, with the specular BSDF sampled as wavelength `lane` (BxDF::sample_f_as), or as it
    // chooses (lane < 0).
    std::optional<BSDFSample> sample(Vec3f wo, float uc, Vec2f u, TransportMode mode, SampleFlags flags,
                                     int lane) const;
    // Sheen and clearcoat are layers on the outside: a solid's inside (wo.z < 0) has neither,
    // while both faces of a thin surface are outsides.
    bool coated(Vec3f wo) const { return thin_ || wo.z > 0; }
    bool lobe_present(int lobe, bool coated, bool inside) const;
    // The random-walk subsurface lobes (both are zero unless subsurface_): the crossing of the
    // surface, and the reflection back inside of what the exit lobe does not transmit.
    SampledSpectrum subsurface_f(Vec3f wo, Vec3f wi) const;
    float subsurface_pdf(Vec3f wo, Vec3f wi, const LobeProbabilities &lobes) const;

    // The two-sided lobes, evaluated with wo in the upper hemisphere (the caller mirrors both
    // directions when wo is below): reflection for wi.z > 0, transmission for wi.z < 0.
    SampledSpectrum upper_f(Vec3f wo, Vec3f wi, bool coated) const;
    float upper_pdf(Vec3f wo, Vec3f wi, const LobeProbabilities &lobes) const;
    SampledSpectrum diffuse_f(Vec3f wo, Vec3f wi, bool coated) const;
    SampledSpectrum specular_reflection_f(Vec3f wo, Vec3f wi) const;
    SampledSpectrum thin_transmission_f(Vec3f wo, Vec3f wi) const;
    float clearcoat_f(Vec3f wo, Vec3f wi, bool coated) const;
    // Fresnel factor of the reflection lobe for cosine cos_d between wo and the microfacet.
    SampledSpectrum specular_reflectance(float cos_d) const;
    // Exact dielectric reflectance of each wavelength for cos_d (light from outside), under the
    // film if there is one.
    SampledSpectrum dielectric_reflectance(float cos_d) const;

    SampledSpectrum base_color_, sqrt_base_color_, sheen_color_, tinted_f0_, eta_;
    ThinFilm film_;
    // With a film: the real index whose normal-incidence reflectance is base_color, per lane.
    SampledSpectrum metal_eta_;
    float metallic_weight_, dielectric_weight_, specular_bsdf_weight_, sheen_weight_;
    float roughness_, specular_tint_, clearcoat_, clearcoat_alpha_;
    bool thin_, subsurface_, profile_subsurface_;
    float diff_trans_, flatness_;
    float lambert_share_;  // of the diffuse lobe's Lambertian part: 1 - diffTrans / 2, 0 with subsurface
    TrowbridgeReitzDistribution specular_, thin_transmission_, clearcoat_masking_;
    DielectricBxDF specular_bsdf_;
    // Which lobes can be non-zero (from the parameters alone; see lobe_present for the sides).
    bool present_[LobeCount] = {};
    bool diffuse_present_ = false, sheen_present_ = false;
};

// Where light that entered a profile-subsurface solid leaves it (DisneyBxDF above): the
// mirror image of the crossing, (1 - F_L / 2) / pi for wo inside (below the normal; the light
// arrives through the interior, so the caller puts wo there) and wi outside. It is eq. 4's Lambertian part without its base colour, its view factor
// and its blend weight w, which the profile and the entry carry, so that a vanishing scatter
// distance reproduces eq. 4 exactly. Its albedo is 41/42 (what the diffuse BRDF loses too); it is
// deliberately not renormalised to 1 as pbrt-v3's Sw is, which would reflect 42/41 of the BRDF.
// Sampled by the cosine density.
class DisneySubsurfaceExitBxDF final : public SubsurfaceExitLobe {
  protected:
    float exit_value(float cos_i) const override;
};

} // namespace caustica
