#include "materials/normalized_diffusion.h"

#include "core/vecmath.h"

#include <cmath>

namespace caustica {
namespace {

// R has a 1/r pole at the entry point. It is integrable (2 pi r R(r) <= A / (2 d)), but its value
// at r = 0 is infinite, and the probe sampler divides R by a sum of such densities at the same
// point. Below this fraction of d the profile is held at its value there; the energy of that disk
// is under 1e-6 A, so neither the integral nor the sampling changes measurably.
constexpr float MinRadiusFraction = 1e-6f;

// The radius beyond which a channel of scale d keeps the fraction `tail` of its energy.
//
// Integrating eq. 5 times 2 pi r gives the energy beyond r: e^{-r/d} / 4 + 3 e^{-r/(3d)} / 4.
// With x = e^{-r/(3d)} that is (x^3 + 3 x) / 4, so the radius solves the cubic
// x^3 + 3 x = 4 tail. Its one real root is x = 2 sinh(asinh(2 tail) / 3), since
// sinh(3t) = 3 sinh(t) + 4 sinh^3(t); unlike Cardano's difference of cube roots this form keeps
// full precision as tail -> 0. With tail = 1 - u this is the exact inverse of the radial CDF: the
// density of picking the lobe e^{-r/d} with probability 1/4 or e^{-r/(3d)} with 3/4 and
// sampling that exponential (Burley 2015, section 2.4), but from one uniform and monotone in it,
// so stratified samples stay stratified.
double radius_with_tail(double d, double tail) {
    double x = 2 * std::sinh(std::asinh(2 * tail) / 3);
    return std::max(0.0, -3 * d * std::log(x));
}

} // namespace

NormalizedDiffusionProfile::NormalizedDiffusionProfile(const SampledSpectrum &albedo,
                                                       const SampledSpectrum &scatter_distance)
    : albedo_(clamp_zero(albedo)), d_(clamp_zero(scatter_distance)) {}

float NormalizedDiffusionProfile::shape(int c, float r) const {
    float d = d_[c];
    if (d == 0) return 0;
    r = std::max(r, MinRadiusFraction * d);
    return (std::exp(-r / d) + std::exp(-r / (3 * d))) / (8 * Pi * d * r);
}

SampledSpectrum NormalizedDiffusionProfile::evaluate(float r) const {
    SampledSpectrum value;
    for (int c = 0; c < NumWavelengths; ++c) value[c] = albedo_[c] * shape(c, r);
    return value;
}

SampledSpectrum NormalizedDiffusionProfile::pdf_area(float r) const {
    SampledSpectrum pdf;
    for (int c = 0; c < NumWavelengths; ++c) pdf[c] = shape(c, r);
    return pdf;
}

float NormalizedDiffusionProfile::sample_radius(int c, float u) const {
    if (d_[c] == 0) return 0;
    return float(radius_with_tail(d_[c], 1 - double(u)));
}

SampledSpectrum NormalizedDiffusionProfile::albedo() const {
    SampledSpectrum a;
    for (int c = 0; c < NumWavelengths; ++c) a[c] = d_[c] > 0 ? albedo_[c] : 0.f;
    return a;
}

float NormalizedDiffusionProfile::max_radius(int c) const {
    if (d_[c] == 0 || albedo_[c] == 0) return 0;
    return float(radius_with_tail(d_[c], 1 - ProfileEnergyWithinMaxRadius));
}

} // namespace caustica
