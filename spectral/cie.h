// CIE colorimetry: the CIE 1931 2-degree standard observer and the CIE standard illuminants.
//
// Data: CIE 015:2018 "Colorimetry", 4th edition (the 1 nm colour-matching-function tables of
// CIE 1931 / ISO/CIE 11664-1, the daylight basis functions, illuminants D65 and F1..F12).
#pragma once

#include "spectral/spectrum.h"

namespace caustica {

// Sum of ybar over every integer nm from 360 to 830 (pbrt-v4's value): the Y of an equal-energy
// spectrum of value 1. Dividing by it makes the film's Y of a normalised illuminant equal 1.
inline constexpr float CIE_Y_integral = 106.856895f;

// Colour matching functions xbar, ybar, zbar (ybar peaks at 1 at 555 nm), tabulated at 1 nm.
const DenselySampledSpectrum &cie_x();
const DenselySampledSpectrum &cie_y();
const DenselySampledSpectrum &cie_z();

// Standard illuminants as CIE tabulates them: relative spectral power, 100 at 560 nm (not
// normalised to luminance; get_named_spectrum("stdillum-...") returns normalised versions).
// Illuminant A, a Planckian radiator at 2856 K, from its defining formula.
const Spectrum &cie_illuminant_a();
// Illuminant D65, from the CIE's 5 nm table (300 to 830 nm), linearly interpolated.
const PiecewiseLinearSpectrum &cie_illuminant_d65();
// Fluorescent illuminants F1..F12 from the CIE's 5 nm tables (380 to 780 nm; zero outside).
// Throws std::out_of_range for a number outside 1..12.
const PiecewiseLinearSpectrum &cie_illuminant_f(int number);

// CIE daylight (D-series) illuminant of correlated colour temperature cct (K), defined by the
// CIE for 4000 K <= cct <= 25000 K (throws std::domain_error outside). As the CIE specifies for
// its tabulated D illuminants, M1 and M2 are rounded to three decimals, so
// daylight_illuminant(6504) reproduces the D65 table and daylight_illuminant(6000) the ACES
// white. Note that D50 and D65 are named after nominal temperatures: their CCTs are
// 5000 * 1.4388 / 1.4380 and 6500 * 1.4388 / 1.4380 (c2 was revised after they were defined).
std::shared_ptr<PiecewiseLinearSpectrum> daylight_illuminant(float cct);

} // namespace caustica
