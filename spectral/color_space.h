// RGB colour spaces: primaries, a white illuminant, the RGB <-> XYZ matrices, and the
// RGB-to-spectrum table that turns the space's RGB values into spectra (rgb_spectrum.h).
#pragma once

#include "spectral/color.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "spectral/spectrum.h"
#include "spectral/standard_color_spaces.h"

#include <string>

namespace caustica {

class RGBColorSpace {
  public:
    // The white point is the XYZ of `illuminant` (luminance-normalised), so RGB (1, 1, 1) is
    // the colour of that light.
    RGBColorSpace(std::string name, Chromaticity red, Chromaticity green, Chromaticity blue,
                  const Spectrum &illuminant, const RGBToSpectrumTable &table);

    RGB rgb_from_xyz(const XYZ &xyz) const { return rgb_from_xyz_ * RGB{xyz.x, xyz.y, xyz.z}; }
    XYZ xyz_from_rgb(const RGB &rgb) const {
        RGB v = xyz_from_rgb_ * rgb;
        return {v.r, v.g, v.b};
    }
    const Matrix3 &xyz_from_rgb_matrix() const { return xyz_from_rgb_; }
    const Matrix3 &rgb_from_xyz_matrix() const { return rgb_from_xyz_; }

    const std::string &name() const { return name_; }
    Chromaticity red() const { return red_; }
    Chromaticity green() const { return green_; }
    Chromaticity blue() const { return blue_; }
    XYZ whitepoint() const { return whitepoint_; }
    // The white illuminant, tabulated at 1 nm; RGBIlluminantSpectrum multiplies by it.
    const DenselySampledSpectrum &illuminant() const { return illuminant_; }
    const RGBToSpectrumTable &table() const { return *table_; }
    // Sigmoid-polynomial coefficients for a reflectance of colour rgb (clamped to [0, 1]).
    SigmoidPolynomial to_coefficients(const RGB &rgb) const;

    // The standard spaces (standard_color_spaces.h), built on first use.
    static const RGBColorSpace &srgb();
    static const RGBColorSpace &aces2065_1();
    static const RGBColorSpace &rec2020();
    static const RGBColorSpace &dci_p3();
    // "srgb", "aces2065-1", "rec2020" or "dci-p3"; null for any other name.
    static const RGBColorSpace *by_name(std::string_view name);

  private:
    std::string name_;
    Chromaticity red_, green_, blue_;
    DenselySampledSpectrum illuminant_;
    XYZ whitepoint_;
    Matrix3 xyz_from_rgb_, rgb_from_xyz_;
    const RGBToSpectrumTable *table_;
};

// Matrix taking linear RGB in `from` to linear RGB in `to` (through XYZ, no chromatic adaptation).
Matrix3 rgb_conversion_matrix(const RGBColorSpace &from, const RGBColorSpace &to);

// XYZ of a spectrum: integrals against the matching functions (sums over integer nm from
// LambdaMin to LambdaMax) divided by CIE_Y_integral, so a normalised illuminant has Y = 1.
XYZ spectrum_to_xyz(const Spectrum &s);
// Monte Carlo estimate of the same from a path's wavelengths: the average over the wavelengths
// of cmf(l) s(l) / pdf(l), zero for wavelengths of zero pdf (terminated secondaries). This is
// what the film accumulates.
XYZ sampled_spectrum_to_xyz(const SampledSpectrum &s, const SampledWavelengths &lambda);
// Its Y alone (luminance), cheaper when only brightness matters.
float sampled_spectrum_to_y(const SampledSpectrum &s, const SampledWavelengths &lambda);

} // namespace caustica
