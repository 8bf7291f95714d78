#include "spectral/ior.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace caustica {

float sellmeier_ior(std::span<const float> b, std::span<const float> c, float lambda_nm) {
    double l2 = double(lambda_nm) * 1e-3 * (double(lambda_nm) * 1e-3);
    double n2 = 1;
    for (size_t i = 0; i < b.size(); ++i) n2 += b[i] * l2 / (l2 - c[i]);
    return float(std::sqrt(n2));
}

SellmeierSpectrum::SellmeierSpectrum(std::span<const float> b, std::span<const float> c)
    : b_(b.begin(), b.end()), c_(c.begin(), c.end()), max_(0) {
    if (b_.size() != c_.size() || b_.empty())
        throw std::invalid_argument("Sellmeier formula: " + std::to_string(b_.size()) +
                                    " B terms but " + std::to_string(c_.size()) + " C terms");
    for (float lambda = LambdaMin; lambda <= LambdaMax; ++lambda)
        max_ = std::max(max_, (*this)(lambda));
}

float abbe_number(const Spectrum &ior) {
    return (ior(FraunhoferD) - 1) / (ior(FraunhoferF) - ior(FraunhoferC));
}

namespace {

struct SellmeierGlass {
    std::string_view name;
    std::array<float, 4> b, c;  // unused trailing terms are zero
    int terms;
};

// Catalogue data. Schott glasses: SCHOTT optical glass data sheets (the "Optical Glass"
// catalogue; C_i in um^2 as published). pbrt-v4 names SF5, SF10 and SF11 "glass-F5",
// "glass-F10" and "glass-F11"; its tables are sampled from these same formulas.
constexpr std::array<SellmeierGlass, 12> Glasses = {{
    // Schott N-BK7 (n_d = 1.5168, V_d = 64.17).
    {"glass-BK7",
     {1.03961212f, 0.231792344f, 1.01046945f},
     {0.00600069867f, 0.0200179144f, 103.560653f},
     3},
    // Schott N-BAF10 (n_d = 1.67003, V_d = 47.11).
    {"glass-BAF10",
     {1.5851495f, 0.143559385f, 1.08521269f},
     {0.00926681282f, 0.0424489805f, 105.613573f},
     3},
    // Schott N-FK51A (n_d = 1.48656, V_d = 84.47).
    {"glass-FK51A",
     {0.971247817f, 0.216901417f, 0.904651666f},
     {0.00472301995f, 0.0153575612f, 168.68133f},
     3},
    // Schott N-LASF9 (n_d = 1.85025, V_d = 32.17).
    {"glass-LASF9",
     {2.00029547f, 0.298926886f, 1.80691843f},
     {0.0121426017f, 0.0538736236f, 156.530829f},
     3},
    // Schott SF5 (n_d = 1.67270, V_d = 32.21).
    {"glass-F5",
     {1.52481889f, 0.187085527f, 1.42729015f},
     {0.011254756f, 0.0588995392f, 129.141675f},
     3},
    // Schott SF10 (n_d = 1.72825, V_d = 28.41).
    {"glass-F10",
     {1.62153902f, 0.256287842f, 1.64447552f},
     {0.0122241457f, 0.0595736775f, 147.468793f},
     3},
    // Schott SF11 (n_d = 1.78472, V_d = 25.68), under pbrt's name and under its own.
    {"glass-F11",
     {1.73759695f, 0.313747346f, 1.89878101f},
     {0.013188707f, 0.0623068142f, 155.23629f},
     3},
    {"glass-SF11",
     {1.73759695f, 0.313747346f, 1.89878101f},
     {0.013188707f, 0.0623068142f, 155.23629f},
     3},
    // Fused silica: I. H. Malitson, "Interspecimen comparison of the refractive index of fused
    // silica", J. Opt. Soc. Am. 55, 1205 (1965); resonances 0.0684043, 0.1162414, 9.896161 um.
    {"glass-fused-silica",
     {0.6961663f, 0.4079426f, 0.8974794f},
     {0.0684043f * 0.0684043f, 0.1162414f * 0.1162414f, 9.896161f * 9.896161f},
     3},
    // Sapphire (Al2O3), ordinary ray: I. H. Malitson and M. J. Dodge, "Refractive index and
    // birefringence of synthetic sapphire", J. Opt. Soc. Am. 62, 1405 (1972).
    {"gem-sapphire",
     {1.4313493f, 0.65054713f, 5.3414021f},
     {0.0726631f * 0.0726631f, 0.1193242f * 0.1193242f, 18.028251f * 18.028251f},
     3},
    // Diamond: F. Peter, "Uber Brechungsindizes und Absorptionskonstanten des Diamanten zwischen
    // 644 und 226 mu", Z. Phys. 15, 358 (1923); two terms, resonances 0.1750 and 0.1060 um.
    {"gem-diamond", {0.3306f, 4.3356f}, {0.1750f * 0.1750f, 0.1060f * 0.1060f}, 2},
    // Distilled water at 20 C: M. Daimon and A. Masumura, "Measurement of the refractive index of
    // distilled water from the near-infrared region to the ultraviolet region", Appl. Opt. 46,
    // 3811 (2007); their four-term fit.
    {"water",
     {5.684027565e-1f, 1.726177391e-1f, 2.086189578e-2f, 1.130748688e-1f},
     {5.101829712e-3f, 1.821153936e-2f, 2.620722293e-2f, 1.069792721e1f},
     4},
}};

} // namespace

SpectrumPtr named_ior(std::string_view name) {
    for (const SellmeierGlass &glass : Glasses)
        if (glass.name == name)
            return std::make_shared<SellmeierSpectrum>(std::span(glass.b).first(glass.terms),
                                                       std::span(glass.c).first(glass.terms));
    return nullptr;
}

std::vector<std::string_view> named_ior_names() {
    std::vector<std::string_view> names;
    for (const SellmeierGlass &glass : Glasses) names.push_back(glass.name);
    return names;
}

} // namespace caustica
