// Continuous spectral distributions, evaluated at a path's wavelengths.
#pragma once

#include "spectral/sampled_wavelengths.h"

#include <memory>
#include <span>
#include <vector>

namespace caustica {

class Spectrum {
  public:
    virtual ~Spectrum() = default;
    // Value at one wavelength in nm.
    virtual float operator()(float lambda) const = 0;
    virtual SampledSpectrum sample(const SampledWavelengths &lambda) const {
        SampledSpectrum s;
        for (int i = 0; i < NumWavelengths; ++i) s[i] = (*this)(lambda[i]);
        return s;
    }
    // An upper bound of the values over [LambdaMin, LambdaMax].
    virtual float max_value() const = 0;
    // True when the value does not depend on wavelength; lets the renderer skip dispersion work.
    virtual bool is_constant() const { return false; }
};

using SpectrumPtr = std::shared_ptr<const Spectrum>;

class ConstantSpectrum final : public Spectrum {
  public:
    explicit ConstantSpectrum(float c) : c_(c) {}
    float operator()(float) const override { return c_; }
    SampledSpectrum sample(const SampledWavelengths &) const override {
        return SampledSpectrum(c_);
    }
    float max_value() const override { return c_; }
    bool is_constant() const override { return true; }

  private:
    float c_;
};

// Linear interpolation between (lambda, value) pairs, zero outside their range.
class PiecewiseLinearSpectrum final : public Spectrum {
  public:
    // lambdas strictly increasing, as many as values; throws std::invalid_argument otherwise.
    PiecewiseLinearSpectrum(std::span<const float> lambdas, std::span<const float> values);
    // From interleaved pairs; if normalize, scaled so that its CIE Y integral equals CIE_Y_integral
    // (how pbrt normalises illuminant spectra).
    static std::shared_ptr<PiecewiseLinearSpectrum> from_interleaved(std::span<const float> pairs,
                                                                     bool normalize);
    float operator()(float lambda) const override;
    float max_value() const override;
    void scale(float s);

  private:
    std::vector<float> lambdas_, values_;
};

// Tabulated at every integer nm in [LambdaMin, LambdaMax]: fast lookups for CMFs and illuminants.
// A wavelength reads the sample at the nearest integer nm (as pbrt-v4 does), zero outside.
class DenselySampledSpectrum final : public Spectrum {
  public:
    explicit DenselySampledSpectrum(const Spectrum &s);
    float operator()(float lambda) const override { return lookup(lambda); }
    SampledSpectrum sample(const SampledWavelengths &lambda) const override {
        SampledSpectrum s;
        for (int i = 0; i < NumWavelengths; ++i) s[i] = lookup(lambda[i]);
        return s;
    }
    float max_value() const override;
    void scale(float s);

  private:
    float lookup(float lambda) const {
        // Rounds to the nearest nm without a libm call; the range test also rejects NaN.
        if (!(lambda >= LambdaMin - 0.5f && lambda < LambdaMax + 0.5f)) return 0;
        return values_[size_t(lambda - LambdaMin + 0.5f)];
    }
    std::vector<float> values_;
};

// Planck's law: spectral radiance of a blackbody at temperature T (K), in W / (m^2 sr m);
// zero for T <= 0. BlackbodySpectrum divides by the value at the peak, so its maximum is 1.
float blackbody(float lambda_nm, float temperature_k);
class BlackbodySpectrum final : public Spectrum {
  public:
    explicit BlackbodySpectrum(float temperature_k);
    float operator()(float lambda) const override;
    float max_value() const override { return 1; }

  private:
    float t_, normalization_;
};

// True if b is a constant multiple of a (k >= 0) at every integer nm of [LambdaMin, LambdaMax],
// to a relative tolerance of 1e-4: the two have the same colour. a must not be zero everywhere.
bool is_multiple_of(const Spectrum &b, const Spectrum &a);

// True if s does not depend on wavelength (at every integer nm, to the same tolerance).
bool is_flat(const Spectrum &s);

// Sum of a(l) b(l) over every integer nm l in [LambdaMin, LambdaMax] (pbrt's InnerProduct).
float inner_product(const Spectrum &a, const Spectrum &b);
// Integral of a spectrum against CIE Y (nm units): inner_product(s, cie_y()). Lights divide by
// it to give a spectrum a prescribed photometric power (pbrt-v4's SpectrumToPhotometric).
float inner_product_y(const Spectrum &s);
// The wavelength (an integer nm) where a spectrum is largest.
float peak_wavelength(const Spectrum &s);
// The spectrum integrated over [LambdaMin, LambdaMax] (1 nm steps, nm units).
float visible_integral(const Spectrum &s);

} // namespace caustica
