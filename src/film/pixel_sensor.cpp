#include "film/pixel_sensor.h"

#include "spectral/cie.h"

#include <stdexcept>
#include <string>

namespace caustica {

Matrix3 white_balance(Chromaticity source_white, Chromaticity target_white) {
    const Matrix3 lms_from_xyz{{{{0.8951f, 0.2664f, -0.1614f},
                                 {-0.7502f, 1.7135f, 0.0367f},
                                 {0.0389f, -0.0685f, 1.0296f}}}};
    const Matrix3 xyz_from_lms = lms_from_xyz.inverse();
    XYZ src = lms_from_xyz * XYZ::from_xy(source_white);
    XYZ dst = lms_from_xyz * XYZ::from_xy(target_white);
    return xyz_from_lms * Matrix3::diagonal(dst.x / src.x, dst.y / src.y, dst.z / src.z) *
           lms_from_xyz;
}

namespace {

// The chromaticity of pbrt-v4's white-balance illuminant for a temperature: the nominal
// temperature is converted to a correlated colour temperature with the revised radiation
// constant c2, then CIE daylight is used (a blackbody below 4000 K, where daylight is undefined).
Chromaticity illuminant_white(float temperature) {
    float cct = temperature * 1.4388f / 1.4380f;
    if (cct < 4000) return spectrum_to_xyz(BlackbodySpectrum(cct)).xy();
    if (cct > 25000)
        throw std::domain_error("white balance temperature " + std::to_string(temperature) +
                                " K is above the 25000 K that CIE daylight is defined for");
    return spectrum_to_xyz(*daylight_illuminant(cct)).xy();
}

} // namespace

PixelSensor::PixelSensor(const RGBColorSpace &output, float white_balance_temperature,
                         float imaging_ratio)
    : imaging_ratio_(imaging_ratio) {
    if (white_balance_temperature != 0)
        xyz_from_sensor_rgb_ =
            white_balance(illuminant_white(white_balance_temperature), output.whitepoint().xy());
}

RGB PixelSensor::to_sensor_rgb(const Spectrum &s) const {
    return RGB{inner_product(cie_x(), s), inner_product(cie_y(), s), inner_product(cie_z(), s)} * imaging_ratio_;
}

RGB PixelSensor::to_sensor_rgb(const SampledSpectrum &L, const SampledWavelengths &lambda) const {
    SampledSpectrum radiance = safe_div(L, lambda.pdf());
    return RGB{(cie_x().sample(lambda) * radiance).average(),
               (cie_y().sample(lambda) * radiance).average(),
               (cie_z().sample(lambda) * radiance).average()} *
           imaging_ratio_;
}

} // namespace caustica
