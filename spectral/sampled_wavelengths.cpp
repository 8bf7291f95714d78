#include "spectral/sampled_wavelengths.h"

#include "core/vecmath.h"
#include "spectral/wavelength_density.h"

namespace caustica {

// pbrt-v4's visible-wavelength density: p(l) proportional to sech^2(0.0072 (l - 538)), a
// smooth lobe close to the sum of the CIE matching functions, normalised over [360, 830] nm.
float visible_wavelengths_pdf(float lambda) {
    if (lambda < LambdaMin || lambda > LambdaMax) return 0;
    return 0.0039398042f / sqr(std::cosh(0.0072f * (lambda - 538)));
}

float sample_visible_wavelengths(float u) {
    return 538 - 138.888889f * std::atanh(0.85691062f - 1.82750197f * u);
}

template <typename InverseCdf, typename Pdf>
SampledWavelengths SampledWavelengths::rotations(float u, const InverseCdf &inverse_cdf, const Pdf &pdf) {
    SampledWavelengths s;
    // Rotations of the primary sample u (see header): member i is the density's inverse CDF at
    // u + i/n, so each member has the density itself as its combined pdf.
    for (int i = 0; i < NumWavelengths; ++i) {
        float rotated = u + float(i) / NumWavelengths;
        if (rotated >= 1) rotated -= 1;
        s.lambda_[i] = inverse_cdf(rotated);
        s.pdf_[i] = pdf(s.lambda_[i]);
    }
    s.hero_pdf_ = s.pdf_[0];
    return s;
}

SampledWavelengths SampledWavelengths::sample_visible(float u) {
    return rotations(
        u, [](float v) { return clamp(sample_visible_wavelengths(v), LambdaMin, LambdaMax); }, visible_wavelengths_pdf);
}

SampledWavelengths SampledWavelengths::sample(const WavelengthDensity &density, float u) {
    return rotations(
        u, [&](float v) { return density.sample(v); }, [&](float lambda) { return density.pdf(lambda); });
}

SampledWavelengths SampledWavelengths::sample_uniform(float u, float lambda_min, float lambda_max) {
    SampledWavelengths s;
    const float range = lambda_max - lambda_min;
    s.lambda_[0] = lerp(u, lambda_min, lambda_max);
    const float delta = range / NumWavelengths;
    for (int i = 1; i < NumWavelengths; ++i) {
        float lambda = s.lambda_[0] + i * delta;
        s.lambda_[i] = lambda > lambda_max ? lambda - range : lambda;
    }
    s.pdf_ = SampledSpectrum(1 / range);
    s.hero_pdf_ = 1 / range;
    return s;
}

SampledWavelengths SampledWavelengths::sample_single(float u) {
    SampledWavelengths s = sample_visible(u);
    s.terminate_secondary();
    return s;
}

SampledWavelengths SampledWavelengths::sample_single(const WavelengthDensity &density, float u) {
    SampledWavelengths s = sample(density, u);
    s.terminate_secondary();
    return s;
}

SampledWavelengths SampledWavelengths::fixed(float lambda) {
    SampledWavelengths s;
    s.lambda_ = SampledSpectrum(lambda);
    s.pdf_ = SampledSpectrum(1);
    s.hero_pdf_ = 1;
    return s;
}

void SampledWavelengths::terminate_secondary() {
    if (secondary_terminated()) return;
    // The hero alone is an unbiased estimate with its own density; the film averages over
    // NumWavelengths lanes, so the surviving lane carries NumWavelengths times the weight.
    for (int i = 1; i < NumWavelengths; ++i) pdf_[i] = 0;
    pdf_[0] = hero_pdf_ / NumWavelengths;
}

bool SampledWavelengths::secondary_terminated() const {
    for (int i = 1; i < NumWavelengths; ++i)
        if (pdf_[i] != 0) return false;
    return true;
}

} // namespace caustica
