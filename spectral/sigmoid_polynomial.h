// The spectral model of Jakob and Hanika 2019, "A Low-Dimensional Function Space for Efficient
// Spectral Upsampling": s(lambda) = sigmoid(c0 lambda^2 + c1 lambda + c2), lambda in nm.
// Three coefficients give smooth spectra bounded to [0, 1] that can reach every RGB colour
// inside the spectral locus: an RGB value maps to the coefficients through a precomputed table.
#pragma once

#include "spectral/sampled_wavelengths.h"

#include <algorithm>
#include <cmath>

namespace caustica {

// sigmoid(x) = 1/2 + x / (2 sqrt(1 + x^2)): algebraic, so cheap, and exactly 0 or 1 at -inf, +inf.
inline float sigmoid(float x) {
    if (std::isinf(x)) return x > 0 ? 1 : 0;
    return 0.5f + x / (2 * std::sqrt(1 + x * x));
}

class SigmoidPolynomial {
  public:
    SigmoidPolynomial() = default;
    SigmoidPolynomial(float c0, float c1, float c2) : c0_(c0), c1_(c1), c2_(c2) {}

    float operator()(float lambda) const { return sigmoid((c0_ * lambda + c1_) * lambda + c2_); }
    SampledSpectrum sample(const SampledWavelengths &lambda) const {
        SampledSpectrum s;
        for (int i = 0; i < NumWavelengths; ++i) s[i] = (*this)(lambda[i]);
        return s;
    }
    // The maximum over [LambdaMin, LambdaMax]: at an end, or at the polynomial's vertex.
    float max_value() const {
        float result = std::max((*this)(LambdaMin), (*this)(LambdaMax));
        float vertex = -c1_ / (2 * c0_);
        if (vertex >= LambdaMin && vertex <= LambdaMax) result = std::max(result, (*this)(vertex));
        return result;
    }
    float c0() const { return c0_; }
    float c1() const { return c1_; }
    float c2() const { return c2_; }

  private:
    float c0_ = 0, c1_ = 0, c2_ = 0;
};

} // namespace caustica
