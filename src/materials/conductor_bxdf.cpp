#include "materials/conductor_bxdf.h"

#include "materials/fresnel.h"

namespace caustica {

SampledSpectrum ConductorBxDF::fresnel(float cos_i) const {
    return film_.present() ? film_.over_conductor(cos_i, eta_, k_) : fresnel_conductor(cos_i, eta_, k_);
}

SampledSpectrum ConductorBxDF::f(Vec3f wo, Vec3f wi, TransportMode) const {
    if (!same_hemisphere(wo, wi) || distribution_.effectively_smooth()) return {};
    float cos_o = std::abs(wo.z), cos_i = std::abs(wi.z);
    if (cos_o == 0 || cos_i == 0) return {};
    Vec3f wm = wi + wo;
    if (length_squared(wm) == 0) return {};
    wm = face_forward(normalize(wm), Vec3f(0, 0, 1));
    return fresnel(abs_dot(wo, wm)) * (distribution_.D(wm) * distribution_.G(wo, wi) / (4 * cos_o * cos_i));
}

std::optional<BSDFSample> ConductorBxDF::sample_f(Vec3f wo, float, Vec2f u, TransportMode,
                                                  SampleFlags flags) const {
    if (!allows(flags, SampleFlags::Reflection)) return {};
    if (distribution_.effectively_smooth()) {
        // Mirror reflection: the delta distribution's f / pdf is F / |cos|.
        Vec3f wi(-wo.x, -wo.y, wo.z);
        float cos_i = std::abs(wi.z);
        if (cos_i == 0) return {};
        BSDFSample s;
        s.f = fresnel(cos_i) / cos_i;
        s.wi = wi;
        s.pdf = 1;
        s.flags = BxDFSpecularReflection;
        return s;
    }
    if (wo.z == 0) return {};
    Vec3f wm = distribution_.sample_wm(wo, u);
    Vec3f wi = reflect(wo, wm);
    // Reflections off visible facets can still leave below the horizon: those are masked by
    // the shadowing term, which the pdf of the surviving directions does not renormalise.
    if (!same_hemisphere(wo, wi)) return {};
    float pdf = distribution_.reflection_pdf(wo, wm);
    float cos_o = std::abs(wo.z), cos_i = std::abs(wi.z);
    if (cos_i == 0 || pdf == 0) return {};
    BSDFSample s;
    s.f = fresnel(abs_dot(wo, wm)) *
          (distribution_.D(wm) * distribution_.G(wo, wi) / (4 * cos_o * cos_i));
    s.wi = wi;
    s.pdf = pdf;
    s.flags = BxDFGlossyReflection;
    return s;
}

float ConductorBxDF::pdf(Vec3f wo, Vec3f wi, TransportMode, SampleFlags flags) const {
    if (!allows(flags, SampleFlags::Reflection) || !same_hemisphere(wo, wi) ||
        distribution_.effectively_smooth())
        return 0;
    Vec3f wm = wo + wi;
    if (length_squared(wm) == 0) return 0;
    wm = face_forward(normalize(wm), Vec3f(0, 0, 1));
    // The visible-normal density times the reflection map's Jacobian d(wm)/d(wi) = 1 / (4 |wo.wm|),
    // in the form that stays exact at grazing angles (see reflection_pdf).
    return distribution_.reflection_pdf(wo, wm);
}

} // namespace caustica
