// Refractive index of transparent media as a function of wavelength: dispersion formulas
// (Sellmeier, Cauchy), the Abbe number, and named glasses, gems and water.
#pragma once

#include "spectral/spectrum.h"

#include <algorithm>
#include <span>
#include <string_view>
#include <vector>

namespace caustica {

// Sellmeier's formula n^2 = 1 + sum_i B_i l^2 / (l^2 - C_i), l in micrometres, C_i in um^2
// (the form of glass catalogues). lambda_nm is in nm.
float sellmeier_ior(std::span<const float> b, std::span<const float> c, float lambda_nm);
inline float sellmeier_ior(const float b[3], const float c[3], float lambda_nm) {
    return sellmeier_ior(std::span<const float>(b, 3), std::span<const float>(c, 3), lambda_nm);
}

class SellmeierSpectrum final : public Spectrum {
  public:
    // As many B as C terms (three for glass catalogues); throws std::invalid_argument otherwise.
    SellmeierSpectrum(std::span<const float> b, std::span<const float> c);
    float operator()(float lambda) const override { return sellmeier_ior(b_, c_, lambda); }
    float max_value() const override { return max_; }

  private:
    std::vector<float> b_, c_;
    float max_;
};

// Cauchy's formula n = A + B / l^2 + C / l^4, l in micrometres (B in um^2, C in um^4).
class CauchySpectrum final : public Spectrum {
  public:
    CauchySpectrum(float a, float b, float c = 0) : a_(a), b_(b), c_(c) {}
    float operator()(float lambda) const override {
        float l2 = (lambda * 1e-3f) * (lambda * 1e-3f);
        return a_ + b_ / l2 + c_ / (l2 * l2);
    }
    // With B, C >= 0 (normal dispersion) the index falls with wavelength.
    float max_value() const override { return std::max((*this)(LambdaMin), (*this)(LambdaMax)); }

  private:
    float a_, b_, c_;
};

// Fraunhofer lines used to characterise glass dispersion (nm): helium d, hydrogen F and C.
inline constexpr float FraunhoferD = 587.5618f, FraunhoferF = 486.1327f, FraunhoferC = 656.2725f;

// Abbe number V_d = (n_d - 1) / (n_F - n_C): low for strongly dispersive media.
float abbe_number(const Spectrum &ior);

// Refractive index of a named dielectric: pbrt-v4's glass names ("glass-BK7", "glass-BAF10",
// "glass-FK51A", "glass-LASF9", "glass-F5", "glass-F10", "glass-F11") and ours
// ("glass-fused-silica", "glass-SF11", "gem-sapphire", "gem-diamond", "water"). Null if unknown.
SpectrumPtr named_ior(std::string_view name);
std::vector<std::string_view> named_ior_names();

} // namespace caustica
