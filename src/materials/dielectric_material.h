// pbrt-v4's "dielectric" material (smooth or rough glass, with a constant or spectral index of
// refraction) and "thindielectric", plus Beer-Lambert absorption inside dielectrics.
#pragma once

#include "materials/material.h"
#include "materials/microfacet_roughness.h"
#include "materials/thin_film.h"
#include "spectral/spectrum.h"

namespace caustica {

// The absorption coefficient that leaves transmittance T after distance d: sigma_a = -ln(T) / d
// (Burley 2015, "Extending the Disney BRDF to a BSDF with Integrated Subsurface Scattering",
// section 2.2: colour by "transmittance at a distance" is easier to art-direct than sigma_a).
// T is clamped to [1e-6, 1]: a black transmittance means an interior that absorbs all but a
// millionth of the light over d, rather than an infinite coefficient.
class TransmittanceAbsorptionSpectrum final : public Spectrum {
  public:
    TransmittanceAbsorptionSpectrum(SpectrumPtr transmittance, float distance)
        : transmittance_(std::move(transmittance)), distance_(distance) {}
    float operator()(float lambda) const override {
        return -std::log(clamp((*transmittance_)(lambda), 1e-6f, 1.f)) / distance_;
    }
    float max_value() const override { return -std::log(1e-6f) / distance_; }

  private:
    SpectrumPtr transmittance_;
    float distance_;
};

class DielectricMaterial final : public Material {
  public:
    // eta: index of the inside relative to the outside (a constant or a dispersion curve).
    // sigma_a: interior absorption per unit length, or null for a clear interior.
    // film: an interference film on the surface (thin_film.h), or none.
    DielectricMaterial(SpectrumPtr eta, MicrofacetRoughness roughness, SpectrumPtr sigma_a, FilmLayer film = {});
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool is_dispersive() const override { return dispersive_; }
    bool has_specular_lobe() const override { return specular_; }
    bool forms_caustics() const override { return specular_ || roughness_.may_focus_light(); }
    bool has_non_specular_lobe() const override { return roughness_.may_be_rough(); }
    SampledSpectrum interior_sigma_a(const SampledWavelengths &lambda) const override {
        return sigma_a_ ? sigma_a_->sample(lambda) : SampledSpectrum();
    }
    bool has_interior_absorption() const override { return sigma_a_ != nullptr; }
    bool is_wavelength_independent() const override {
        return is_flat(*eta_) && (!sigma_a_ || is_flat(*sigma_a_)) && !film_.may_be_present();
    }

  private:
    SpectrumPtr eta_;
    MicrofacetRoughness roughness_;
    SpectrumPtr sigma_a_;
    FilmLayer film_;
    bool dispersive_ = false, specular_ = false;
};

// A thin slab (see thin_dielectric_bxdf.h). Its exit directions do not depend on wavelength,
// so it is never dispersive even with a spectral eta; both lobes are always specular. With a
// film thickness (nm, a texture; 0 is none) the slab is a coherent film of index eta: a soap
// bubble's wall.
class ThinDielectricMaterial final : public Material {
  public:
    ThinDielectricMaterial(SpectrumPtr eta, FloatTexturePtr film_thickness)
        : eta_(std::move(eta)), film_thickness_(std::move(film_thickness)) {}
    BSDF get_bsdf(const SurfaceInteraction &si, const SampledWavelengths &lambda,
                  ScratchBuffer &scratch) const override;
    bool has_specular_lobe() const override { return true; }
    bool has_non_specular_lobe() const override { return false; }
    bool is_wavelength_independent() const override;

  private:
    SpectrumPtr eta_;
    FloatTexturePtr film_thickness_;
};

// Smallest and largest value of a spectrum at the integer wavelengths of [LambdaMin, LambdaMax]
// (NaN propagates to both).
void spectrum_range(const Spectrum &s, float *min_value, float *max_value);

} // namespace caustica
