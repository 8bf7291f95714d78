#include "materials/dielectric_bxdf.h"

#include "materials/fresnel.h"
#include "materials/radiance_scaling.h"

namespace caustica {

namespace {

// Probabilities of choosing reflection and transmission given the hero's Fresnel reflectance,
// restricted to the lobes the caller allows.
struct LobeChoice {
    float pr, pt;
    bool empty() const { return pr == 0 && pt == 0; }
    float reflection_probability() const { return pr / (pr + pt); }
    float transmission_probability() const { return pt / (pr + pt); }
};
LobeChoice choose_lobes(float reflectance, SampleFlags flags) {
    return {allows(flags, SampleFlags::Reflection) ? reflectance : 0.f,
            allows(flags, SampleFlags::Transmission) ? 1 - reflectance : 0.f};
}

// eta' of the side wi is on over the side wo is on, for a transmission with wo on the given side.
float relative_eta(float cos_o, float eta) { return cos_o > 0 ? eta : 1 / eta; }

// The microfacet normal that refracts wo into wi: the generalised half vector eta' wi + wo of
// Walter et al. 2007 (eq. 16), oriented to the outside; empty unless both directions see the
// facet from their own side.
std::optional<Vec3f> transmission_half_vector(Vec3f wo, Vec3f wi, float etap) {
    Vec3f h = wi * etap + wo;
    if (length_squared(h) == 0) return {};
    Vec3f wm = face_forward(normalize(h), Vec3f(0, 0, 1));
    if (dot(wo, wm) * wo.z <= 0 || dot(wi, wm) * wi.z <= 0) return {};
    return wm;
}

} // namespace

DielectricBxDF::DielectricBxDF(const SampledSpectrum &eta,
                               const TrowbridgeReitzDistribution &distribution, const ThinFilm &film)
    : eta_(eta), film_(film), distribution_(distribution) {
    index_matched_ = true;
    bool any_matched = false;
    for (int i = 0; i < NumWavelengths; ++i) {
        if (eta_[i] != eta_[0]) dispersive_ = true;
        if (is_matched_lane(i))
            any_matched = true;
        else
            index_matched_ = false;
    }
    partly_matched_ = any_matched && !index_matched_;
    lane_lobes_ = dispersive_ && !any_matched && !distribution_.effectively_smooth();
}

float DielectricBxDF::lane_reflectance(float cos_d, int lane) const {
    if (is_matched_lane(lane)) return 0;
    return film_.present() ? film_.over_dielectric(cos_d, eta_[lane], lane) : fresnel_dielectric(cos_d, eta_[lane]);
}

float DielectricBxDF::choice_reflectance(float cos_d, int lane) const {
    return lane_lobes_ ? lane_reflectance(cos_d, lane) : selection_reflectance(cos_d);
}

float DielectricBxDF::selection_reflectance(float cos_d) const {
    if (!dispersive_ && !film_.present()) return fresnel_dielectric(cos_d, eta_[0]);
    float sum = 0;
    for (int i = 0; i < NumWavelengths; ++i) sum += lane_reflectance(cos_d, i);
    return sum / NumWavelengths;
}

BxDFFlags DielectricBxDF::flags() const {
    if (index_matched_) return BxDFSpecularTransmission;
    BxDFFlags lobe = distribution_.effectively_smooth() ? BxDFSpecular : BxDFGlossy;
    BxDFFlags all = BxDFReflection | BxDFTransmission | lobe;
    // A hero in the index-matched band passes straight through, even on a rough interface.
    return partly_matched_ ? all | BxDFSpecular : all;
}

std::optional<BSDFSample> DielectricBxDF::sample_f(Vec3f wo, float uc, Vec2f u,
                                                   TransportMode mode, SampleFlags flags) const {
    if (wo.z == 0) return {};
    if (index_matched_ || is_matched_lane(0)) {
        // The hero sees no interface: the delta transmission continues the ray unchanged, with
        // unit throughput in either transport mode (eta' = 1). Lanes outside the band have
        // their lobes elsewhere, so a partly matched interface terminates the secondaries.
        if (!allows(flags, SampleFlags::Transmission)) return {};
        BSDFSample s;
        s.wi = -wo;
        s.f[0] = 1 / std::abs(wo.z);
        if (index_matched_) s.f = SampledSpectrum(s.f[0]);
        s.pdf = 1;
        s.flags = BxDFSpecularTransmission;
        s.dispersive = !index_matched_;
        return s;
    }
    if (distribution_.effectively_smooth()) return sample_specular(wo, uc, mode, flags);
    if (!lane_lobes_) return sample_rough(wo, uc, u, mode, flags, 0);
    // The lane is uniform, from uc; the rest of uc chooses the lobe. The density is the lanes'
    // mean, pdf()'s.
    const float scaled = uc * NumWavelengths;
    const int lane = std::min(int(scaled), NumWavelengths - 1);
    std::optional<BSDFSample> s = sample_rough(wo, std::min(scaled - lane, OneMinusEpsilon), u, mode, flags, lane);
    if (s && s->lane_pdf) {
        s->pdf = s->lane_pdf->average();
        s->lane_pdf.reset();
    }
    return s;
}

std::optional<BSDFSample> DielectricBxDF::sample_f_as(int lane, Vec3f wo, float uc, Vec2f u, TransportMode mode) const {
    if (!lane_lobes_) return sample_f(wo, uc, u, mode);
    if (wo.z == 0) return {};
    return sample_rough(wo, uc, u, mode, SampleFlags::All, lane);
}

std::optional<BSDFSample> DielectricBxDF::sample_specular(Vec3f wo, float uc, TransportMode mode,
                                                          SampleFlags flags) const {
    float cos_o = wo.z;
    LobeChoice lobes = choose_lobes(selection_reflectance(cos_o), flags);
    if (lobes.empty()) return {};
    BSDFSample s;
    if (uc < lobes.reflection_probability()) {
        // Mirror reflection; every wavelength reflects the same way with its own Fresnel weight.
        s.wi = Vec3f(-wo.x, -wo.y, wo.z);
        for (int i = 0; i < NumWavelengths; ++i)
            s.f[i] = lane_reflectance(cos_o, i) / std::abs(cos_o);
        s.pdf = lobes.reflection_probability();
        s.flags = BxDFSpecularReflection;
        return s;
    }
    float etap;
    if (!refract(wo, Vec3f(0, 0, 1), eta_[0], &etap, &s.wi)) return {};
    float cos_i = std::abs(s.wi.z);
    if (cos_i == 0) return {};
    int lanes = dispersive_ ? 1 : NumWavelengths;
    for (int i = 0; i < lanes; ++i) {
        float t = 1 - lane_reflectance(cos_o, i);
        t *= radiance_scaling(mode, relative_eta(cos_o, eta_[i]));
        s.f[i] = t / cos_i;
    }
    s.pdf = lobes.transmission_probability();
    s.flags = BxDFSpecularTransmission;
    s.eta = etap;
    s.dispersive = dispersive_;
    return s;
}

std::optional<BSDFSample> DielectricBxDF::sample_rough(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                                       SampleFlags flags, int lane) const {
    Vec3f wm = distribution_.sample_wm(wo, u);
    float wo_dot_m = dot(wo, wm);
    LobeChoice lobes = choose_lobes(choice_reflectance(wo_dot_m, lane), flags);
    if (lobes.empty()) return {};
    float cos_o = std::abs(wo.z);
    BSDFSample s;
    if (uc < lobes.reflection_probability()) {
        s.wi = reflect(wo, wm);
        if (!same_hemisphere(wo, s.wi) || s.wi.z == 0) return {};
        float cos_i = std::abs(s.wi.z);
        float common = distribution_.D(wm) * distribution_.G(wo, s.wi) / (4 * cos_i * cos_o);
        for (int i = 0; i < NumWavelengths; ++i)
            s.f[i] = lane_reflectance(wo_dot_m, i) * common;
        s.pdf = distribution_.reflection_pdf(wo, wm) * lobes.reflection_probability();
        s.flags = BxDFGlossyReflection;
        if (lane_lobes_) {
            s.lane_pdf = reflection_lane_pdfs(wo, wm, flags);
            s.pdf = (*s.lane_pdf)[lane];
        }
        return s;
    }
    float etap;
    if (!refract(wo, wm, eta_[lane], &etap, &s.wi)) return {};
    if (same_hemisphere(wo, s.wi) || s.wi.z == 0) return {};
    // The sample is evaluated where f() and pdf() evaluate it: at the half vector recovered
    // from (wo, wi), not at the sampled facet. Near eta = 1 the recovered vector is a difference
    // of nearly opposite vectors, with a direction error of about 1e-7 / |eta' wi + wo| (up to
    // 1e-3): for facets within that of vertical its orientation can flip, and for facets nearly
    // edge-on to wo the Fresnel transmittance 1 - F can round to zero there. Either makes pdf()
    // zero, and the sample is rejected too, so that sample_f, f and pdf describe the same
    // distribution. The weight f |cos| / pdf is G / G1 at whichever facet it is evaluated.
    std::optional<Vec3f> recovered = transmission_half_vector(wo, s.wi, etap);
    if (!recovered) return {};
    wm = *recovered;
    wo_dot_m = dot(wo, wm);
    lobes = choose_lobes(choice_reflectance(wo_dot_m, lane), flags);
    if (lobes.pt == 0) return {};
    float wi_dot_m = dot(s.wi, wm);
    // Jacobian of the refraction half-vector map (Walter et al. 2007, eq. 17).
    float denom = sqr(wi_dot_m + wo_dot_m / etap);
    if (denom == 0) return {};
    s.pdf = distribution_.pdf(wo, wm) * std::abs(wi_dot_m) / denom * lobes.transmission_probability();
    s.flags = BxDFGlossyTransmission;
    s.eta = etap;
    if (!dispersive_) {
        s.f = rough_transmission_shared_index(wo, s.wi, mode);
    } else if (partly_matched_) {
        s.f[0] = rough_transmission(wo, s.wi, 0, mode);
        s.dispersive = true;
    } else {
        for (int i = 0; i < NumWavelengths; ++i) s.f[i] = rough_transmission(wo, s.wi, i, mode);
        s.lane_pdf = lane_pdfs(wo, s.wi, flags);
        s.pdf = (*s.lane_pdf)[lane];
        if (s.pdf == 0) return {};
    }
    return s;
}

SampledSpectrum DielectricBxDF::rough_transmission_shared_index(Vec3f wo, Vec3f wi, TransportMode mode) const {
    if (!film_.present()) return SampledSpectrum(rough_transmission(wo, wi, 0, mode));
    SampledSpectrum t;
    for (int i = 0; i < NumWavelengths; ++i) t[i] = rough_transmission(wo, wi, i, mode);
    return t;
}

float DielectricBxDF::rough_transmission(Vec3f wo, Vec3f wi, int lane, TransportMode mode) const {
    float cos_o = wo.z, cos_i = wi.z;
    float etap = relative_eta(cos_o, eta_[lane]);
    std::optional<Vec3f> wm = transmission_half_vector(wo, wi, etap);
    if (!wm) return 0;
    float wo_dot_m = dot(wo, *wm), wi_dot_m = dot(wi, *wm);
    float denom = sqr(wi_dot_m + wo_dot_m / etap);
    if (denom == 0) return 0;
    float t = (1 - lane_reflectance(wo_dot_m, lane)) * distribution_.D(*wm) * distribution_.G(wo, wi) *
              std::abs(wi_dot_m * wo_dot_m / (cos_i * cos_o * denom));
    t *= radiance_scaling(mode, etap);
    return t;
}

SampledSpectrum DielectricBxDF::f(Vec3f wo, Vec3f wi, TransportMode mode) const {
    if (specular()) return {};
    float cos_o = wo.z, cos_i = wi.z;
    if (cos_o == 0 || cos_i == 0) return {};
    SampledSpectrum result;
    if (cos_o * cos_i > 0) {
        // The half vector of two directions on one side is visible from both (see
        // TrowbridgeReitzDistribution::reflection_pdf), so there is no visibility test: at
        // grazing angles it would only test rounding, and pdf() has none either.
        Vec3f wm = wi + wo;
        if (length_squared(wm) == 0) return {};
        wm = face_forward(normalize(wm), Vec3f(0, 0, 1));
        float wo_dot_m = dot(wo, wm);
        float common = distribution_.D(wm) * distribution_.G(wo, wi) / std::abs(4 * cos_i * cos_o);
        for (int i = 0; i < NumWavelengths; ++i)
            result[i] = lane_reflectance(wo_dot_m, i) * common;
        return result;
    }
    if (!dispersive_) return rough_transmission_shared_index(wo, wi, mode);
    for (int i = 0; i < NumWavelengths; ++i)
        if (!is_matched_lane(i)) result[i] = rough_transmission(wo, wi, i, mode);
    return result;
}

float DielectricBxDF::pdf(Vec3f wo, Vec3f wi, TransportMode, SampleFlags flags) const {
    // A hero in the index-matched band samples only its straight-through delta.
    if (specular() || is_matched_lane(0)) return 0;
    if (!lane_lobes_) return lane_pdf(wo, wi, 0, flags);
    return lane_pdfs(wo, wi, flags).average();
}

SampledSpectrum DielectricBxDF::lane_pdfs(Vec3f wo, Vec3f wi, SampleFlags flags) const {
    if (wo.z * wi.z > 0) {
        // One half vector for every lane.
        Vec3f wm = wi + wo;
        if (length_squared(wm) == 0) return {};
        return reflection_lane_pdfs(wo, face_forward(normalize(wm), Vec3f(0, 0, 1)), flags);
    }
    SampledSpectrum p;
    for (int i = 0; i < NumWavelengths; ++i) p[i] = lane_pdf(wo, wi, i, flags);
    return p;
}

SampledSpectrum DielectricBxDF::reflection_lane_pdfs(Vec3f wo, Vec3f wm, SampleFlags flags) const {
    const float facet = distribution_.reflection_pdf(wo, wm), wo_dot_m = dot(wo, wm);
    SampledSpectrum p;
    for (int i = 0; i < NumWavelengths; ++i) {
        const LobeChoice lobes = choose_lobes(choice_reflectance(wo_dot_m, i), flags);
        if (lobes.pr > 0) p[i] = facet * lobes.reflection_probability();
    }
    return p;
}

float DielectricBxDF::lane_pdf(Vec3f wo, Vec3f wi, int lane, SampleFlags flags) const {
    float cos_o = wo.z, cos_i = wi.z;
    if (cos_o == 0 || cos_i == 0) return 0;
    bool reflection = cos_o * cos_i > 0;
    Vec3f wm;
    if (reflection) {
        wm = wi + wo;
        if (length_squared(wm) == 0) return 0;
        wm = face_forward(normalize(wm), Vec3f(0, 0, 1));
    } else {
        std::optional<Vec3f> m = transmission_half_vector(wo, wi, relative_eta(cos_o, eta_[lane]));
        if (!m) return 0;
        wm = *m;
    }
    float wo_dot_m = dot(wo, wm), wi_dot_m = dot(wi, wm);
    LobeChoice lobes = choose_lobes(choice_reflectance(wo_dot_m, lane), flags);
    if (lobes.empty()) return 0;
    if (reflection) {
        if (lobes.pr == 0) return 0;
        return distribution_.reflection_pdf(wo, wm) * lobes.reflection_probability();
    }
    if (lobes.pt == 0) return 0;
    float denom = sqr(wi_dot_m + wo_dot_m / relative_eta(cos_o, eta_[lane]));
    if (denom == 0) return 0;
    return distribution_.pdf(wo, wm) * std::abs(wi_dot_m) / denom * lobes.transmission_probability();
}

} // namespace caustica
