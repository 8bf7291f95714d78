// Spectra given as RGB in a colour space, through the sigmoid-polynomial upsampling of Jakob
// and Hanika 2019 (rgb_to_spectrum_table.h), in pbrt-v4's three flavours.
#pragma once

#include "spectral/color_space.h"

namespace caustica {

// A reflectance in [0, 1]: rgb is clamped to [0, 1]. Under the colour space's illuminant its
// colour is rgb.
class RGBAlbedoSpectrum final : public Spectrum {
  public:
    RGBAlbedoSpectrum(const RGBColorSpace &cs, const RGB &rgb) : rsp_(cs.to_coefficients(rgb)) {}
    float operator()(float lambda) const override { return rsp_(lambda); }
    SampledSpectrum sample(const SampledWavelengths &lambda) const override {
        return rsp_.sample(lambda);
    }
    float max_value() const override { return rsp_.max_value(); }
    // Grey: the table's polynomial for r = g = b is a constant.
    bool is_constant() const override { return rsp_.c0() == 0 && rsp_.c1() == 0; }

  private:
    SigmoidPolynomial rsp_;
};

// Any non-negative rgb (negative components are clamped to zero): the spectrum of rgb / (2 m),
// m the largest component, scaled by 2 m (pbrt-v4's RGBUnboundedSpectrum). Halving keeps the
// table lookup away from fully saturated values, whose spectra would be near-boxes.
class RGBUnboundedSpectrum final : public Spectrum {
  public:
    RGBUnboundedSpectrum(const RGBColorSpace &cs, const RGB &rgb);
    float operator()(float lambda) const override { return scale_ * rsp_(lambda); }
    SampledSpectrum sample(const SampledWavelengths &lambda) const override {
        return rsp_.sample(lambda) * scale_;
    }
    float max_value() const override { return scale_ * rsp_.max_value(); }
    bool is_constant() const override { return rsp_.c0() == 0 && rsp_.c1() == 0; }

  private:
    float scale_;
    SigmoidPolynomial rsp_;
};

// An emission spectrum of colour rgb: the unbounded spectrum of rgb times the colour space's
// illuminant, so that rgb (1, 1, 1) is exactly that illuminant (pbrt-v4's RGBIlluminantSpectrum).
class RGBIlluminantSpectrum final : public Spectrum {
  public:
    RGBIlluminantSpectrum(const RGBColorSpace &cs, const RGB &rgb);
    float operator()(float lambda) const override {
        return scale_ * rsp_(lambda) * (*illuminant_)(lambda);
    }
    SampledSpectrum sample(const SampledWavelengths &lambda) const override {
        return rsp_.sample(lambda) * illuminant_->sample(lambda) * scale_;
    }
    float max_value() const override {
        return scale_ * rsp_.max_value() * illuminant_->max_value();
    }
    // The colour space's illuminant alone. Lights normalise photometric power with it rather
    // than with the whole spectrum, as pbrt-v4 does, so an RGB light's colour does not change
    // its brightness setting.
    const DenselySampledSpectrum &illuminant_spectrum() const { return *illuminant_; }

  private:
    float scale_;
    SigmoidPolynomial rsp_;
    const DenselySampledSpectrum *illuminant_;
};

} // namespace caustica
