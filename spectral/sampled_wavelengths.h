// Hero-wavelength sampling (Wilkie et al. 2014, "Hero Wavelength Spectral Sampling").
//
// A path carries NumWavelengths wavelengths: a hero lambda_0 drawn from a smooth density close
// to the eye's response, and the others at equal offsets of (range / NumWavelengths), wrapped
// around [LambdaMin, LambdaMax]. Each wavelength's estimate is combined with the balance
// heuristic over the NumWavelengths rotations that could have produced it. Because the rotations
// of any one member generate the same set, every member's combined density is the same: the
// average of the hero density over the set. pdf() stores that average, so the film's estimate
// (1/n) sum_j f(lambda_j) / pdf_j is the hero-wavelength MIS estimator.
//
// A wavelength-dependent delta event (refraction in a dispersive dielectric) sends each
// wavelength in a different direction: terminate_secondary() keeps only the hero, whose estimate
// alone is unbiased with the plain hero density, scaled so the film's average stays correct.
#pragma once

#include "spectral/sampled_spectrum.h"

#include <optional>

namespace caustica {

inline constexpr float LambdaMin = 360.f, LambdaMax = 830.f;

// Density used for hero wavelengths (pbrt-v4's visible-wavelength pdf, a sech^2 lobe at 538 nm).
float visible_wavelengths_pdf(float lambda);
float sample_visible_wavelengths(float u);

class SampledWavelengths {
  public:
    // Hero from the visible density, the rest rotated; the default for rendering.
    static SampledWavelengths sample_visible(float u);
    // Hero uniform over [LambdaMin, LambdaMax].
    static SampledWavelengths sample_uniform(float u);
    // Single-wavelength sampling (one wavelength per path, for comparisons with hero sampling).
    static SampledWavelengths sample_single(float u);
    // Every lane at one fixed wavelength with pdf 1: the `--wavelength NM` monochromatic mode.
    static SampledWavelengths fixed(float lambda);

    float operator[](int i) const { return lambda_[i]; }
    float lambda(int i) const { return lambda_[i]; }
    SampledSpectrum pdf() const { return pdf_; }

    // Keeps the hero only; no-op if already terminated.
    void terminate_secondary();
    bool secondary_terminated() const;

  private:
    SampledSpectrum lambda_, pdf_;
    float hero_pdf_ = 0;  // density of the hero alone, used once secondaries are terminated
};

} // namespace caustica
