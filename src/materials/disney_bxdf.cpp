#include "materials/disney_bxdf.h"

#include "core/sampling.h"
#include "materials/fresnel.h"

namespace caustica {

namespace {

// Schlick's weight (1 - cos)^5, the grazing factor shared by the diffuse, sheen and Schlick
// Fresnel terms.
float schlick_weight(float cos_theta) {
    float m = clamp(1 - cos_theta, 0.f, 1.f);
    float m2 = m * m;
    return m2 * m2 * m;
}

// Schlick's approximation with Burley 2015's critical-angle correction (eq. 7): when the light
// goes towards the optically thinner side (eta < 1) the weight is taken at the refracted angle,
// and beyond the critical angle everything is reflected.
float fresnel_schlick_critical(float f0, float cos_i, float eta) {
    if (eta >= 1) return fresnel_schlick(f0, cos_i);
    float cos2_t = 1 - (1 - sqr(cos_i)) / sqr(eta);
    if (cos2_t <= 0) return 1;
    return fresnel_schlick(f0, std::sqrt(cos2_t));
}

// Reflectance of a dielectric interface at normal incidence.
float normal_incidence_reflectance(float eta) { return sqr((eta - 1) / (eta + 1)); }

Vec3f mirror_z(Vec3f w) { return {w.x, w.y, -w.z}; }

// Clearcoat's fixed index of refraction 1.5 (Burley 2012) as Schlick's F0.
constexpr float ClearcoatF0 = 0.04f;
// Clearcoat's masking: GGX Smith G1 with this fixed alpha (Burley 2012).
constexpr float ClearcoatMaskingAlpha = 0.25f;

// Albedo estimates for lobe selection, from integrating the lobes over the hemisphere (cos_o
// is the viewing cosine, fv = (1 - cos_o)^5): the Lambertian part of eq. 4 reflects about
// 1 - fv / 2; the retro-reflection adds about roughness (0.06 + fv) (0.06 roughness at normal
// incidence, ~roughness at grazing); sheen reflects about 0.1 sheen fv (it is a grazing
// lobe). Any positive values keep the estimator unbiased; these keep its variance low.
constexpr float RetroAlbedoAtNormal = 0.06f;
constexpr float SheenAlbedoScale = 0.1f;
// Lower bound on a present lobe's selection weight, as a fraction of its blend weight: the
// estimates above can vanish for some wo (e.g. Schlick's weight at normal incidence) while the
// lobe still contributes to other directions, and an unsampled lobe would bias the estimator.
constexpr float MinimumSelectionFraction = 0.01f;

} // namespace

TrowbridgeReitzDistribution DisneyBxDF::specular_distribution(float roughness, float anisotropic) {
    float aspect = std::sqrt(1 - 0.9f * clamp(anisotropic, 0.f, 1.f));
    float alpha = sqr(roughness);
    return {alpha / aspect, alpha * aspect};
}

float DisneyBxDF::gtr1(Vec3f wm, float alpha) {
    if (wm.z <= 0) return 0;
    float a2 = sqr(alpha);
    return (a2 - 1) / (Pi * std::log(a2) * (sqr(wm.x) + sqr(wm.y) + a2 * sqr(wm.z)));
}

DisneyBxDF::DisneyBxDF(const DisneyParameters &p)
    : eta_(p.eta),
      film_(p.film),
      metallic_weight_(p.metallic),
      dielectric_weight_((1 - p.metallic) * (1 - p.spec_trans)),
      specular_bsdf_weight_((1 - p.metallic) * p.spec_trans),
      sheen_weight_((1 - p.metallic) * p.sheen),
      roughness_(p.roughness),
      specular_tint_(p.specular_tint),
      clearcoat_(p.clearcoat),
      clearcoat_alpha_(clearcoat_alpha(p.clearcoat_gloss)),
      thin_(p.thin),
      subsurface_(p.subsurface && !p.thin),
      profile_subsurface_(subsurface_ && p.profile_subsurface),
      diff_trans_(p.thin ? p.diff_trans : 0),
      flatness_(p.thin ? p.flatness : 0),
      specular_(specular_distribution(p.roughness, p.anisotropic)),
      thin_transmission_(specular_distribution(thin_transmission_roughness(p.roughness, p.reference_eta),
                                               p.anisotropic)),
      clearcoat_masking_(ClearcoatMaskingAlpha, ClearcoatMaskingAlpha),
      specular_bsdf_(p.eta, specular_, p.film) {
    SampledSpectrum tint(1.f);
    for (int i = 0; i < NumWavelengths; ++i) {
        base_color_[i] = clamp(p.base_color[i], 0.f, 1.f);
        if (p.base_luminance > 0) tint[i] = base_color_[i] / p.base_luminance;
    }
    sqrt_base_color_ = sqrt(base_color_);
    // Inverting F0 = ((n - 1) / (n + 1))^2; a white metal's n is kept finite.
    for (int i = 0; i < NumWavelengths; ++i) {
        const float r = std::min(std::sqrt(base_color_[i]), 0.999f);
        metal_eta_[i] = (1 + r) / (1 - r);
    }
    sheen_color_ = lerp(p.sheen_tint, SampledSpectrum(1.f), tint);
    for (int i = 0; i < NumWavelengths; ++i)
        tinted_f0_[i] = clamp(normal_incidence_reflectance(eta_[i]) * tint[i], 0.f, 1.f);

    bool base = !base_color_.is_black();
    lambert_share_ = subsurface_ ? 0 : 1 - diff_trans_ / 2;
    diffuse_present_ = dielectric_weight_ > 0 && base && (lambert_share_ > 0 || roughness_ > 0);
    sheen_present_ = sheen_weight_ > 0 && !sheen_color_.is_black();
    present_[Diffuse] = diffuse_present_ || sheen_present_;
    present_[DiffuseTransmission] = thin_ && dielectric_weight_ > 0 && diff_trans_ > 0 && base;
    present_[SpecularReflection] = metallic_weight_ > 0 || dielectric_weight_ > 0 ||
                                   (thin_ && specular_bsdf_weight_ > 0);
    present_[SpecularBSDF] = !thin_ && specular_bsdf_weight_ > 0;
    present_[ThinTransmission] = thin_ && specular_bsdf_weight_ > 0 && base;
    present_[Clearcoat] = clearcoat_ > 0;
    present_[Subsurface] = present_[InternalReflection] = subsurface_ && dielectric_weight_ > 0;
}

bool DisneyBxDF::lobe_present(int lobe, bool coated, bool inside) const {
    if (subsurface_ && inside)
        return (lobe == Subsurface || lobe == InternalReflection || lobe == SpecularBSDF) && present_[lobe];
    if (lobe == InternalReflection) return false;
    if (lobe == Diffuse) return diffuse_present_ || (coated && sheen_present_);
    if (lobe == Clearcoat) return coated && present_[Clearcoat];
    return present_[lobe];
}

BxDFFlags DisneyBxDF::flags() const {
    BxDFFlags f = BxDFUnset;
    if (present_[Diffuse]) f = f | BxDFDiffuseReflection;
    if (present_[DiffuseTransmission]) f = f | BxDFDiffuseTransmission;
    if (present_[SpecularReflection])
        f = f | (specular_.effectively_smooth() ? BxDFSpecularReflection : BxDFGlossyReflection);
    if (present_[SpecularBSDF]) f = f | specular_bsdf_.flags();
    if (present_[ThinTransmission])
        f = f | (thin_transmission_.effectively_smooth() ? BxDFSpecularTransmission
                                                         : BxDFGlossyTransmission);
    if (present_[Clearcoat]) f = f | BxDFGlossyReflection;
    if (present_[Subsurface]) f = f | BxDFDiffuseTransmission | BxDFDiffuseReflection;
    return f;
}

SampledSpectrum DisneyBxDF::dielectric_reflectance(float cos_d) const {
    SampledSpectrum r;
    for (int i = 0; i < NumWavelengths; ++i)
        r[i] = film_.present() ? film_.over_dielectric(cos_d, eta_[i], i) : fresnel_dielectric(cos_d, eta_[i]);
    return r;
}

SampledSpectrum DisneyBxDF::specular_reflectance(float cos_d) const {
    SampledSpectrum r;
    if (metallic_weight_ > 0)
        r += (film_.present() ? film_.over_conductor(cos_d, metal_eta_, SampledSpectrum(0.f))
                              : fresnel_schlick(base_color_, cos_d)) *
             metallic_weight_;
    if (dielectric_weight_ > 0) {
        const SampledSpectrum exact = dielectric_reflectance(cos_d);
        for (int i = 0; i < NumWavelengths; ++i) {
            float tinted = fresnel_schlick_critical(tinted_f0_[i], cos_d, eta_[i]);
            r[i] += dielectric_weight_ * lerp(specular_tint_, exact[i], tinted);
        }
    }
    // A thin surface's specular BSDF reflects through this lobe (solids use specular_bsdf_).
    if (thin_ && specular_bsdf_weight_ > 0) r += dielectric_reflectance(cos_d) * specular_bsdf_weight_;
    return r;
}

DisneyBxDF::LobeProbabilities DisneyBxDF::lobe_probabilities(Vec3f wo, SampleFlags flags) const {
    float cos_o = std::abs(wo.z), fv = schlick_weight(cos_o);
    bool coated = this->coated(wo);
    bool reflection = allows(flags, SampleFlags::Reflection);
    bool transmission = allows(flags, SampleFlags::Transmission);
    float estimate[LobeCount] = {}, weight[LobeCount] = {};
    bool allowed[LobeCount] = {};

    allowed[Diffuse] = reflection;
    weight[Diffuse] = dielectric_weight_ + (coated ? sheen_weight_ : 0);
    estimate[Diffuse] = dielectric_weight_ * base_color_.average() *
                        (lambert_share_ * (1 - fv / 2) + roughness_ * (RetroAlbedoAtNormal + fv));
    if (coated) estimate[Diffuse] += sheen_weight_ * sheen_color_.average() * SheenAlbedoScale * fv;

    allowed[DiffuseTransmission] = transmission;
    weight[DiffuseTransmission] = dielectric_weight_;
    estimate[DiffuseTransmission] = dielectric_weight_ * base_color_.average() * diff_trans_ / 2;

    allowed[SpecularReflection] = reflection;
    weight[SpecularReflection] = metallic_weight_ + dielectric_weight_ + (thin_ ? specular_bsdf_weight_ : 0);
    if (present_[SpecularReflection]) estimate[SpecularReflection] = specular_reflectance(cos_o).average();

    // The solid specular BSDF chooses between its own reflection and refraction; its estimate
    // covers whichever of the two the flags allow.
    allowed[SpecularBSDF] = reflection || transmission;
    weight[SpecularBSDF] = specular_bsdf_weight_;
    if (present_[SpecularBSDF]) {
        float r = fresnel_dielectric(wo.z, eta_[0]);
        estimate[SpecularBSDF] = specular_bsdf_weight_ * ((reflection ? r : 0) +
                                                          (transmission ? (1 - r) * sqrt_base_color_.average() : 0));
    }

    allowed[ThinTransmission] = transmission;
    weight[ThinTransmission] = specular_bsdf_weight_;
    if (present_[ThinTransmission])
        estimate[ThinTransmission] = specular_bsdf_weight_ * base_color_.average() *
                                     (1 - dielectric_reflectance(cos_o).average());

    allowed[Clearcoat] = reflection;
    weight[Clearcoat] = clearcoat_ / 4;
    estimate[Clearcoat] = clearcoat_ / 4 * fresnel_schlick(ClearcoatF0, cos_o);

    // Light from outside enters with the Lambertian share and returns coloured by the volume;
    // from inside it leaves with probability 41/42 and is reflected back with 1/42.
    bool inside = wo.z < 0;
    allowed[Subsurface] = transmission;
    weight[Subsurface] = dielectric_weight_;
    estimate[Subsurface] = dielectric_weight_ * (inside ? 41.f / 42 : base_color_.average() * (1 - fv / 2));
    allowed[InternalReflection] = reflection;
    weight[InternalReflection] = dielectric_weight_ / 42;
    estimate[InternalReflection] = dielectric_weight_ / 42;

    LobeProbabilities lobes;
    float total = 0;
    for (int k = 0; k < LobeCount; ++k) {
        if (!lobe_present(k, coated, inside) || !allowed[k]) continue;
        lobes.p[k] = std::max(estimate[k], MinimumSelectionFraction * weight[k]);
        total += lobes.p[k];
    }
    if (total > 0)
        for (float &p : lobes.p) p /= total;
    return lobes;
}

SampledSpectrum DisneyBxDF::diffuse_f(Vec3f wo, Vec3f wi, bool coated) const {
    Vec3f wh = normalize(wo + wi);
    float cos_d = dot(wi, wh);
    SampledSpectrum sheen;
    if (coated && sheen_present_) sheen = sheen_color_ * (sheen_weight_ * schlick_weight(cos_d));
    if (!diffuse_present_) return sheen;
    float fl = schlick_weight(wi.z), fv = schlick_weight(wo.z);
    // Eq. 4: the Lambertian ("subsurface") part with the smooth-surface Fresnel edge factors,
    // limited to a darkening of 1/2 at grazing angles ...
    float lambert = (1 - fl / 2) * (1 - fv / 2);
    if (flatness_ > 0) {
        // ... which on thin surfaces flatness blends with the 2012 BRDF's Hanrahan-Krueger-
        // inspired shape (flatter at normal incidence, brighter at grazing angles) ...
        float fss90 = sqr(cos_d) * roughness_;
        float fss = lerp(fl, 1.f, fss90) * lerp(fv, 1.f, fss90);
        float hanrahan_krueger = 1.25f * (fss * (1 / (wi.z + wo.z) - 0.5f) + 0.5f);
        lambert = lerp(flatness_, lambert, hanrahan_krueger);
    }
    // ... and shares with diffuse transmission; the retro-reflection is a microsurface effect
    // that neither flatness nor diffTrans change.
    float rr = 2 * roughness_ * sqr(cos_d);
    float retro = rr * (fl + fv + fl * fv * (rr - 1));
    float diffuse = dielectric_weight_ * InvPi * (lambert_share_ * lambert + retro);
    return base_color_ * diffuse + sheen;
}

SampledSpectrum DisneyBxDF::specular_reflection_f(Vec3f wo, Vec3f wi) const {
    if (!present_[SpecularReflection] || specular_.effectively_smooth()) return {};
    Vec3f wm = normalize(wo + wi);
    float g = specular_.D(wm) * specular_.G(wo, wi) / (4 * wo.z * wi.z);
    return specular_reflectance(dot(wo, wm)) * g;
}

SampledSpectrum DisneyBxDF::thin_transmission_f(Vec3f wo, Vec3f wi) const {
    if (!present_[ThinTransmission] || thin_transmission_.effectively_smooth()) return {};
    // The reflection model with wi mirrored through the surface: the refraction into and out of
    // the sheet cancel, leaving the blur of the microfacets.
    Vec3f wr = mirror_z(wi);
    Vec3f wm = normalize(wo + wr);
    SampledSpectrum t = SampledSpectrum(1.f) - dielectric_reflectance(dot(wo, wm));
    float g = thin_transmission_.D(wm) * thin_transmission_.G(wo, wr) / (4 * wo.z * wr.z);
    return base_color_ * t * (specular_bsdf_weight_ * g);
}

float DisneyBxDF::clearcoat_f(Vec3f wo, Vec3f wi, bool coated) const {
    if (!coated || !present_[Clearcoat]) return 0;
    Vec3f wm = normalize(wo + wi);
    float d = gtr1(wm, clearcoat_alpha_);
    float f = fresnel_schlick(ClearcoatF0, dot(wo, wm));
    float g = clearcoat_masking_.G1(wo) * clearcoat_masking_.G1(wi);
    return clearcoat_ / 4 * d * f * g / (4 * wo.z * wi.z);
}

SampledSpectrum DisneyBxDF::subsurface_f(Vec3f wo, Vec3f wi) const {
    if (!present_[Subsurface]) return {};
    float crossing = dielectric_weight_ * InvPi;
    // A profile's entry is a discrete event (sample_f), not a direction.
    if (wo.z > 0 && profile_subsurface_) return {};
    if (wo.z > 0) return SampledSpectrum(wi.z < 0 ? crossing * (1 - schlick_weight(wo.z) / 2) : 0.f);
    return SampledSpectrum(wi.z > 0 ? crossing * (1 - schlick_weight(wi.z) / 2) : crossing / 42);
}

float DisneyBxDF::subsurface_pdf(Vec3f wo, Vec3f wi, const LobeProbabilities &lobes) const {
    if (wo.z > 0 && profile_subsurface_) return 0;
    if (wo.z > 0) return wi.z < 0 ? lobes.p[Subsurface] * cosine_hemisphere_pdf(-wi.z) : 0;
    return wi.z > 0 ? lobes.p[Subsurface] * cosine_hemisphere_pdf(wi.z)
                    : lobes.p[InternalReflection] * cosine_hemisphere_pdf(-wi.z);
}

SampledSpectrum DisneyBxDF::upper_f(Vec3f wo, Vec3f wi, bool coated) const {
    if (wi.z > 0)
        return diffuse_f(wo, wi, coated) + specular_reflection_f(wo, wi) +
               SampledSpectrum(clearcoat_f(wo, wi, coated));
    SampledSpectrum t = thin_transmission_f(wo, wi);
    if (present_[DiffuseTransmission]) t += base_color_ * (dielectric_weight_ * diff_trans_ / 2 * InvPi);
    return t;
}

SampledSpectrum DisneyBxDF::f(Vec3f wo, Vec3f wi, TransportMode mode) const {
    if (wo.z == 0 || wi.z == 0) return {};
    SampledSpectrum result;
    if (present_[SpecularBSDF]) {
        SampledSpectrum s = specular_bsdf_.f(wo, wi, mode) * specular_bsdf_weight_;
        result += same_hemisphere(wo, wi) ? s : s * sqrt_base_color_;
    }
    if (subsurface_) {
        result += subsurface_f(wo, wi);
        if (wo.z < 0) return result;
    }
    bool coated = this->coated(wo);
    if (wo.z < 0) {
        wo = mirror_z(wo);
        wi = mirror_z(wi);
    }
    return result + upper_f(wo, wi, coated);
}

float DisneyBxDF::upper_pdf(Vec3f wo, Vec3f wi, const LobeProbabilities &lobes) const {
    float pdf = 0;
    if (wi.z > 0) {
        pdf += lobes.p[Diffuse] * cosine_hemisphere_pdf(wi.z);
        Vec3f h = wo + wi, wm = normalize(h);
        // Jacobian of the reflection half-vector map: d(wm)/d(wi) = 1 / (4 wo.wm), where
        // wo.wm = (1 + wo.wi) / |wo + wi| = |wo + wi| / 2 for unit vectors. For nearly opposite
        // grazing directions the dot product is a cancellation that rounding made negative (a
        // negative density); the length is accurate. The GGX lobes' visible-normal density
        // cancels wo.wm altogether (reflection_pdf).
        float jacobian = 1 / (2 * length(h));
        if (lobes.p[SpecularReflection] > 0 && !specular_.effectively_smooth())
            pdf += lobes.p[SpecularReflection] * specular_.reflection_pdf(wo, wm);
        if (lobes.p[Clearcoat] > 0)
            pdf += lobes.p[Clearcoat] * gtr1(wm, clearcoat_alpha_) * wm.z * jacobian;
    } else {
        pdf += lobes.p[DiffuseTransmission] * cosine_hemisphere_pdf(-wi.z);
        if (lobes.p[ThinTransmission] > 0 && !thin_transmission_.effectively_smooth()) {
            Vec3f wm = normalize(wo + mirror_z(wi));
            pdf += lobes.p[ThinTransmission] * thin_transmission_.reflection_pdf(wo, wm);
        }
    }
    return pdf;
}

float DisneyBxDF::pdf(Vec3f wo, Vec3f wi, TransportMode mode, SampleFlags flags) const {
    if (wo.z == 0 || wi.z == 0) return 0;
    LobeProbabilities lobes = lobe_probabilities(wo, flags);
    float pdf = 0;
    if (lobes.p[SpecularBSDF] > 0) pdf += lobes.p[SpecularBSDF] * specular_bsdf_.pdf(wo, wi, mode, flags);
    if (subsurface_) {
        pdf += subsurface_pdf(wo, wi, lobes);
        if (wo.z < 0) return pdf;
    }
    if (wo.z < 0) {
        wo = mirror_z(wo);
        wi = mirror_z(wi);
    }
    return pdf + upper_pdf(wo, wi, lobes);
}

std::optional<BSDFSample> DisneyBxDF::sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                               SampleFlags flags) const {
    return sample(wo, uc, u, mode, flags, -1);
}

std::optional<BSDFSample> DisneyBxDF::sample_f_as(int lane, Vec3f wo, float uc, Vec2f u, TransportMode mode) const {
    return sample(wo, uc, u, mode, SampleFlags::All, has_lane_lobes() ? lane : -1);
}

std::optional<BSDFSample> DisneyBxDF::sample(Vec3f wo, float uc, Vec2f u, TransportMode mode, SampleFlags flags,
                                             int lane) const {
    if (wo.z == 0) return {};
    LobeProbabilities lobes = lobe_probabilities(wo, flags);
    // Choose a lobe with uc and rescale uc to [0, 1) for the lobe's own use.
    int lobe = -1;
    float cdf = 0, lobe_start = 0;
    for (int k = 0; k < LobeCount; ++k) {
        if (lobes.p[k] == 0) continue;
        lobe = k;
        lobe_start = cdf;
        cdf += lobes.p[k];
        if (uc < cdf) break;
    }
    if (lobe < 0) return {};
    float p = lobes.p[lobe];
    float uc_lobe = clamp((uc - lobe_start) / p, 0.f, OneMinusEpsilon);

    BSDFSample s;
    if (lobe == SpecularBSDF) {
        std::optional<BSDFSample> g = lane < 0 ? specular_bsdf_.sample_f(wo, uc_lobe, u, mode, flags)
                                               : specular_bsdf_.sample_f_as(lane, wo, uc_lobe, u, mode);
        if (!g) return {};
        if (g->is_specular()) {
            g->f *= specular_bsdf_weight_;
            if (g->is_transmission()) g->f *= sqrt_base_color_;
            g->pdf *= p;
            return g;
        }
        s = *g;
    } else if (lobe == Subsurface && wo.z > 0 && profile_subsurface_) {
        // The profile's entry: straight in (|cos| = 1), carrying the share that enters.
        s.wi = Vec3f(0, 0, -1);
        s.f = SampledSpectrum(dielectric_weight_ * (1 - schlick_weight(wo.z) / 2));
        s.pdf = p;
        s.flags = BxDFDiffuseTransmission;
        return s;
    } else if (lobe == Subsurface || lobe == InternalReflection) {
        // Cosine-distributed on the side the lobe leads to: the crossing goes to the other
        // side of wo, the internal reflection stays inside.
        Vec3f i = sample_cosine_hemisphere(u);
        bool upper = (lobe == Subsurface) == (wo.z < 0);
        s.wi = upper ? i : mirror_z(i);
        s.flags = lobe == Subsurface ? BxDFDiffuseTransmission : BxDFDiffuseReflection;
    } else {
        // The two-sided lobes sample with wo mirrored into the upper hemisphere.
        bool mirrored = wo.z < 0;
        Vec3f o = mirrored ? mirror_z(wo) : wo, i;
        switch (lobe) {
        case Diffuse:
            i = sample_cosine_hemisphere(u);
            s.flags = BxDFDiffuseReflection;
            break;
        case DiffuseTransmission:
            i = mirror_z(sample_cosine_hemisphere(u));
            s.flags = BxDFDiffuseTransmission;
            break;
        case SpecularReflection:
            if (specular_.effectively_smooth()) {
                s.wi = Vec3f(-wo.x, -wo.y, wo.z);
                s.f = specular_reflectance(o.z) / o.z;
                s.pdf = p;
                s.flags = BxDFSpecularReflection;
                return s;
            }
            i = reflect(o, specular_.sample_wm(o, u));
            s.flags = BxDFGlossyReflection;
            break;
        case ThinTransmission:
            if (thin_transmission_.effectively_smooth()) {
                s.wi = -wo;
                s.f = base_color_ * (SampledSpectrum(1.f) - dielectric_reflectance(o.z)) *
                      (specular_bsdf_weight_ / o.z);
                s.pdf = p;
                s.flags = BxDFSpecularTransmission;
                return s;
            }
            i = mirror_z(reflect(o, thin_transmission_.sample_wm(o, u)));
            s.flags = BxDFGlossyTransmission;
            break;
        case Clearcoat: {
            // GTR1 normals by inverting the cdf of cos^2 theta_m, 1 - cos^2 = (a^2^(1-u) - a^2) /
            // (1 - a^2), written for sin^2 directly so that tiny angles keep their precision.
            float a2 = sqr(clearcoat_alpha_);
            float sin2_m = (std::pow(a2, 1 - u.x) - a2) / (1 - a2);
            Vec3f wm = spherical_direction(safe_sqrt(sin2_m), safe_sqrt(1 - sin2_m), 2 * Pi * u.y);
            i = reflect(o, wm);
            s.flags = BxDFGlossyReflection;
            break;
        }
        }
        // Reflections off a facet can leave below the horizon (and mirrored thin transmissions
        // above it): the masking term gives those zero value, so no sample.
        if (is_transmissive(s.flags) ? i.z >= 0 : i.z <= 0) return {};
        s.wi = mirrored ? mirror_z(i) : i;
    }

    // Non-delta samples carry the whole BSDF's value and density for wi.
    s.f = f(wo, s.wi, mode);
    s.pdf = pdf(wo, s.wi, mode, flags);
    if (s.dispersive)
        for (int i = 1; i < NumWavelengths; ++i) s.f[i] = 0;
    if (lane >= 0 && lobes.p[SpecularBSDF] > 0) {
        // Only the specular BSDF's density differs between lanes.
        const SampledSpectrum lanes = specular_bsdf_.lane_pdfs(wo, s.wi, flags) * lobes.p[SpecularBSDF];
        const float others = std::max(0.f, s.pdf - lanes.average());
        s.lane_pdf = lanes + SampledSpectrum(others);
        s.pdf = (*s.lane_pdf)[lane];
    }
    if (s.pdf == 0) return {};
    return s;
}

float DisneySubsurfaceExitBxDF::exit_value(float cos_i) const { return InvPi * (1 - schlick_weight(cos_i) / 2); }

} // namespace caustica
