// The film's sensor: how spectral radiance becomes the film's colour values (pbrt-v4's
// PixelSensor, "cie1931" sensor). Its response is the CIE 1931 observer, so sensor "RGB" is
// XYZ; an optional white balance (von Kries adaptation in the Bradford cone space) maps the
// white of a daylight illuminant to the output colour space's white.
#pragma once

#include "spectral/color.h"
#include "spectral/color_space.h"
#include "spectral/sampled_wavelengths.h"
#include "spectral/spectrum.h"

namespace caustica {

class PixelSensor {
  public:
    // imaging_ratio = exposure time * ISO / 100 (pbrt-v4). white_balance_temperature 0 leaves
    // colours unbalanced; otherwise the CIE daylight illuminant of that temperature (K) becomes
    // the output space's white. Throws std::domain_error for temperatures it cannot model.
    PixelSensor(const RGBColorSpace &output, float white_balance_temperature, float imaging_ratio);

    // The hero-wavelength estimate of XYZ: the average over the path's wavelengths of
    // cmf(l) L(l) / pdf(l), times the imaging ratio. No division by CIE_Y_integral: lights are
    // normalised photometrically (radiance of "L" [1 1 1] has Y = 1), as in pbrt-v4.
    RGB to_sensor_rgb(const SampledSpectrum &L, const SampledWavelengths &lambda) const;
    // What that estimate converges to for the spectrum s: the integrals of cmf(l) s(l), times
    // the imaging ratio.
    RGB to_sensor_rgb(const Spectrum &s) const;

    // Sensor values to XYZ: the white balance, or the identity.
    const Matrix3 &xyz_from_sensor_rgb() const { return xyz_from_sensor_rgb_; }
    float imaging_ratio() const { return imaging_ratio_; }

  private:
    Matrix3 xyz_from_sensor_rgb_ = Matrix3::identity();
    float imaging_ratio_;
};

// Chromatic adaptation of XYZ from one white to another by scaling the Bradford cone responses
// (Lam 1985; the matrix as used by ICC and CIECAM97s).
Matrix3 white_balance(Chromaticity source_white, Chromaticity target_white);

} // namespace caustica
