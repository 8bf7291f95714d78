// A medium whose absorption, scattering and phase function are the same everywhere: transmittance
// is Beer-Lambert's exp(-sigma_t d) in closed form, and free-flight distances are exponential.
#pragma once

#include "media/medium.h"
#include "spectral/spectrum.h"

namespace caustica {

class HomogeneousMedium final : public Medium {
  public:
    // sigma_a and sigma_s per unit length of the scene, already multiplied by "scale"; Le (null:
    // none) times Le_scale, the emitted radiance (pbrt-v4's "Le" and "Lescale").
    HomogeneousMedium(SpectrumPtr sigma_a, SpectrumPtr sigma_s, float scale, float g, SpectrumPtr Le = nullptr,
                      float Le_scale = 0);

    SampledSpectrum sigma_a(const SampledWavelengths &lambda) const;
    SampledSpectrum sigma_s(const SampledWavelengths &lambda) const;
    MediumProperties properties(Vec3f, const SampledWavelengths &lambda) const override {
        return {sigma_a(lambda), sigma_s(lambda)};
    }
    SampledSpectrum max_sigma_t(const SampledWavelengths &lambda) const override {
        return sigma_a(lambda) + sigma_s(lambda);
    }
    const HenyeyGreenstein &phase() const override { return phase_; }
    bool is_emissive() const override { return Le_ && Le_scale_ > 0; }
    SampledSpectrum Le(Vec3f, const SampledWavelengths &lambda) const override;
    SampledSpectrum transmittance(const Ray &ray, float distance, const SampledWavelengths &lambda) const override;
    bool is_wavelength_independent() const override { return is_flat(*sigma_a_) && is_flat(*sigma_s_); }
    MediumEvent sample_distance(const Ray &ray, float t_max, const SampledWavelengths &lambda, int lane,
                                float u_distance) const override;

  private:
    SpectrumPtr sigma_a_, sigma_s_;
    float scale_;
    HenyeyGreenstein phase_;
    SpectrumPtr Le_;
    float Le_scale_;
};

// A homogeneous medium known only at one path's wavelengths: the interior a material makes for
// the point where a path enters it, when the interior's coefficients come from textures there
// (the Disney material's random walk with a textured baseColor). It lives in the path's scratch
// memory, and every lambda it is asked about must be the wavelengths it was made for (the
// secondary ones may have been terminated since). interior_of() names the material, so that a
// path leaving through any point of that material's surface leaves this medium.
class SampledHomogeneousMedium final : public Medium {
  public:
    SampledHomogeneousMedium(const SampledSpectrum &sigma_a, const SampledSpectrum &sigma_s, float g,
                             const Material *owner)
        : sigma_a_(sigma_a), sigma_s_(sigma_s), phase_(g), owner_(owner) {}

    SampledSpectrum sigma_a(const SampledWavelengths &) const { return sigma_a_; }
    SampledSpectrum sigma_s(const SampledWavelengths &) const { return sigma_s_; }
    MediumProperties properties(Vec3f, const SampledWavelengths &) const override { return {sigma_a_, sigma_s_}; }
    SampledSpectrum max_sigma_t(const SampledWavelengths &) const override { return sigma_a_ + sigma_s_; }
    const HenyeyGreenstein &phase() const override { return phase_; }
    SampledSpectrum transmittance(const Ray &ray, float distance, const SampledWavelengths &lambda) const override;
    MediumEvent sample_distance(const Ray &ray, float t_max, const SampledWavelengths &lambda, int lane,
                                float u_distance) const override;
    const Material *interior_of() const override { return owner_; }

  private:
    SampledSpectrum sigma_a_, sigma_s_;
    HenyeyGreenstein phase_;
    const Material *owner_;
};

} // namespace caustica
