// The film's sensor: how spectral radiance becomes the film's colour values (pbrt-v4's
// PixelSensor). Two kinds, as pbrt-v4's film "sensor" parameter:
//  - "cie1931": the CIE 1931 observer, so sensor "RGB" is XYZ; an optional white balance (von
//    Kries adaptation in the Bradford cone space) maps the white of a daylight illuminant to the
//    output colour space's white;
//  - a camera's sensor ("canon_eos_5d_mkiv", ...; spectral/camera_sensor_data.h): sensor RGB is
//    the camera's raw response, and XYZ is a 3x3 matrix of it, fitted by least squares so that
//    a chart of reflectances under the white-balance illuminant gives their XYZ under the output
//    space's white, scaled to keep luminance (pbrt-v4's method; Langlands and Fascione 2020,
//    "PhysLight"). The chart is the 24 patches of the ColorChecker, as pbrt-v4, but each patch's
//    reflectance is the smooth spectrum of its published sRGB value (Jakob and Hanika 2019),
//    where pbrt-v4 uses measured ones (see training_chart in pixel_sensor.cpp).
#pragma once

#include "spectral/color.h"
#include "spectral/color_space.h"
#include "spectral/sampled_wavelengths.h"
#include "spectral/spectrum.h"

#include <memory>

namespace caustica {

class PixelSensor {
  public:
    // The CIE 1931 observer. imaging_ratio = exposure time * ISO / 100 (pbrt-v4).
    // white_balance_temperature 0 leaves colours unbalanced; otherwise the CIE daylight
    // illuminant of that temperature (K) becomes the output space's white. Throws
    // std::domain_error for temperatures it cannot model.
    PixelSensor(const RGBColorSpace &output, float white_balance_temperature, float imaging_ratio);
    // A camera sensor with spectral responses r, g and b, white-balanced for the daylight
    // illuminant of white_balance_temperature (K, not 0).
    PixelSensor(const RGBColorSpace &output, const Spectrum &r, const Spectrum &g, const Spectrum &b,
                float white_balance_temperature, float imaging_ratio);

    // The hero-wavelength estimate of the sensor's values: the average over the path's
    // wavelengths of response(l) L(l) / pdf(l), times the imaging ratio. No division by
    // CIE_Y_integral: lights are normalised photometrically (radiance of "L" [1 1 1] has Y = 1),
    // as in pbrt-v4.
    RGB to_sensor_rgb(const SampledSpectrum &L, const SampledWavelengths &lambda) const;
    // What that estimate converges to for the spectrum s: the integrals of response(l) s(l),
    // times the imaging ratio.
    RGB to_sensor_rgb(const Spectrum &s) const;

    // Sensor values to XYZ: the white balance or the fitted matrix, or the identity.
    const Matrix3 &xyz_from_sensor_rgb() const { return xyz_from_sensor_rgb_; }
    float imaging_ratio() const { return imaging_ratio_; }

  private:
    // The responses, tabulated at 1 nm (shared: films copy their sensor).
    std::shared_ptr<const DenselySampledSpectrum> r_bar_, g_bar_, b_bar_;
    Matrix3 xyz_from_sensor_rgb_ = Matrix3::identity();
    float imaging_ratio_;
};

// Chromatic adaptation of XYZ from one white to another by scaling the Bradford cone responses
// (Lam 1985; the matrix as used by ICC and CIECAM97s).
Matrix3 white_balance(Chromaticity source_white, Chromaticity target_white);

} // namespace caustica
