// A thin dielectric slab (a window pane, a soap film without interference), as pbrt-v4's
// ThinDielectricBxDF: light reflects inside the slab any number of times between two parallel
// smooth interfaces, and leaves either mirrored or undeviated. Summing the geometric series of
// internal bounces with single-interface reflectance R gives total reflectance
// R' = R + T^2 R / (1 - R^2) and transmittance T' = 1 - R' (no absorption).
//
// A slab thinner than light's coherence length (a soap film, a few hundred nanometres) is a thin
// film instead (Caustica's "filmthickness" on `thindielectric`): its internal reflections add as
// amplitudes, not as intensities, and the Airy summation of thin_film.h, with air on both sides,
// gives R' per wavelength and angle; T' = 1 - R' again. This is what colours soap bubbles.
//
// Both exit directions are the same for every wavelength, so a dispersive eta only changes the
// per-wavelength weights and never sets BSDFSample::dispersive. The light leaves into the medium
// it came from, so there is no radiance compression and the two transport modes agree.
#pragma once

#include "materials/bxdf.h"
#include "materials/fresnel.h"
#include "materials/thin_film.h"

namespace caustica {

class ThinDielectricBxDF final : public BxDF {
  public:
    // film_thickness_nm > 0: the slab is a coherent film that thick, at the wavelengths lambda.
    explicit ThinDielectricBxDF(const SampledSpectrum &eta, float film_thickness_nm = 0,
                                const SampledSpectrum &lambda = {})
        : eta_(eta), lambda_(lambda), film_thickness_nm_(film_thickness_nm) {}

    SampledSpectrum f(Vec3f, Vec3f, TransportMode) const override { return {}; }
    float pdf(Vec3f, Vec3f, TransportMode, SampleFlags = SampleFlags::All) const override { return 0; }
    BxDFFlags flags() const override { return BxDFReflection | BxDFTransmission | BxDFSpecular; }

    // Total reflectance of the slab per wavelength for light with cosine cos_o.
    SampledSpectrum reflectance(float cos_o) const {
        SampledSpectrum r;
        if (film_thickness_nm_ > 0) {
            for (int i = 0; i < NumWavelengths; ++i)
                r[i] = thin_film_response(std::abs(cos_o), eta_[i], 1, film_thickness_nm_, lambda_[i]).reflectance;
            return r;
        }
        for (int i = 0; i < NumWavelengths; ++i) {
            float single = fresnel_dielectric(std::abs(cos_o), eta_[i]);
            float t = 1 - single;
            r[i] = single < 1 ? single + sqr(t) * single / (1 - sqr(single)) : 1;
        }
        return r;
    }

    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f, TransportMode,
                                       SampleFlags flags = SampleFlags::All) const override {
        float cos_o = std::abs(wo.z);
        if (cos_o == 0) return {};
        SampledSpectrum r = reflectance(cos_o);
        SampledSpectrum t = SampledSpectrum(1) - r;
        // Lobe choice by the average over wavelengths: every lane's weight f / pdf then stays
        // near 1, which keeps the secondary wavelengths' variance low.
        float pr = allows(flags, SampleFlags::Reflection) ? r.average() : 0;
        float pt = allows(flags, SampleFlags::Transmission) ? t.average() : 0;
        if (pr == 0 && pt == 0) return {};
        BSDFSample s;
        if (uc < pr / (pr + pt)) {
            s.wi = Vec3f(-wo.x, -wo.y, wo.z);
            s.f = r / cos_o;
            s.pdf = pr / (pr + pt);
            s.flags = BxDFSpecularReflection;
        } else {
            s.wi = -wo;
            s.f = t / cos_o;
            s.pdf = pt / (pr + pt);
            s.flags = BxDFSpecularTransmission;
        }
        return s;
    }

  private:
    SampledSpectrum eta_, lambda_;
    float film_thickness_nm_;
};

} // namespace caustica
