#include "film/pixel_sensor.h"

#include "spectral/cie.h"
#include "spectral/rgb_spectrum.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

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

// pbrt-v4's white-balance illuminant for a temperature: the nominal temperature is converted to
// a correlated colour temperature with the revised radiation constant c2, then CIE daylight is
// used (a blackbody below 4000 K, where daylight is undefined).
std::shared_ptr<const Spectrum> white_balance_illuminant(float temperature) {
    float cct = temperature * 1.4388f / 1.4380f;
    if (cct < 4000) return std::make_shared<BlackbodySpectrum>(cct);
    if (cct > 25000)
        throw std::domain_error("white balance temperature " + std::to_string(temperature) +
                                " K is above the 25000 K that CIE daylight is defined for");
    return daylight_illuminant(cct);
}

std::shared_ptr<const DenselySampledSpectrum> dense(const Spectrum &s) {
    return std::make_shared<DenselySampledSpectrum>(s);
}

// The training chart of camera sensors' colour matrices: the 24 patches of the ColorChecker
// Classic by their sRGB values as X-Rite publishes them (8-bit, sRGB-encoded), each turned into
// the smooth reflectance spectrum of that colour. pbrt-v4 fits to BabelColor's measured spectra
// of the same patches, which it may redistribute by permission. Colours then differ from
// pbrt-v4's by a few percent (docs/pbrt-v4-coverage.md has the figures).
std::vector<RGBAlbedoSpectrum> training_chart() {
    static const int srgb8[24][3] = {
        {115, 82, 68},   {194, 150, 130}, {98, 122, 157},  {87, 108, 67},   {133, 128, 177}, {103, 189, 170},
        {214, 126, 44},  {80, 91, 166},   {193, 90, 99},   {94, 60, 108},   {157, 188, 64},  {224, 163, 46},
        {56, 61, 150},   {70, 148, 73},   {175, 54, 60},   {231, 199, 31},  {187, 86, 149},  {8, 133, 161},
        {243, 243, 242}, {200, 200, 200}, {160, 160, 160}, {122, 122, 121}, {85, 85, 85},    {52, 52, 52}};
    auto decode = [](int v) {
        const float c = v / 255.f;
        return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    };
    std::vector<RGBAlbedoSpectrum> chart;
    for (const auto &p : srgb8)
        chart.emplace_back(RGBColorSpace::srgb(), RGB{decode(p[0]), decode(p[1]), decode(p[2])});
    return chart;
}

// The responses b1, b2, b3 to reflectance refl under illum, over b2's response to illum itself
// (pbrt-v4's PixelSensor::ProjectReflectance), summed at every nm.
std::array<double, 3> project_reflectance(const Spectrum &refl, const Spectrum &illum, const Spectrum &b1,
                                          const Spectrum &b2, const Spectrum &b3) {
    std::array<double, 3> result{};
    double b2_white = 0;
    for (int lambda = int(LambdaMin); lambda <= int(LambdaMax); ++lambda) {
        const double l = illum(float(lambda)), r = refl(float(lambda)) * l;
        b2_white += b2(float(lambda)) * l;
        result[0] += b1(float(lambda)) * r;
        result[1] += b2(float(lambda)) * r;
        result[2] += b3(float(lambda)) * r;
    }
    for (double &v : result) v /= b2_white;
    return result;
}

// The matrix M that minimises sum_i |M a_i - b_i|^2: M = (B^T A) (A^T A)^-1.
Matrix3 least_squares(const std::vector<std::array<double, 3>> &a, const std::vector<std::array<double, 3>> &b) {
    double ata[3][3] = {}, bta[3][3] = {};
    for (size_t i = 0; i < a.size(); ++i)
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                ata[r][c] += a[i][r] * a[i][c];
                bta[r][c] += b[i][r] * a[i][c];
            }
    // Invert A^T A in double (Cramer's rule); it is positive definite for a chart that spans
    // the sensor's three responses.
    const double det = ata[0][0] * (ata[1][1] * ata[2][2] - ata[1][2] * ata[2][1]) -
                       ata[0][1] * (ata[1][0] * ata[2][2] - ata[1][2] * ata[2][0]) +
                       ata[0][2] * (ata[1][0] * ata[2][1] - ata[1][1] * ata[2][0]);
    if (!(std::abs(det) > 0)) throw std::domain_error("the sensor's colour matrix cannot be fitted");
    double inv[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
            inv[r][c] = (ata[r1][c1] * ata[r2][c2] - ata[r1][c2] * ata[r2][c1]) / det;
        }
    Matrix3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m.m[r][c] = float(bta[r][0] * inv[0][c] + bta[r][1] * inv[1][c] + bta[r][2] * inv[2][c]);
    return m;
}

} // namespace

PixelSensor::PixelSensor(const RGBColorSpace &output, float white_balance_temperature, float imaging_ratio)
    : r_bar_(dense(cie_x())), g_bar_(dense(cie_y())), b_bar_(dense(cie_z())), imaging_ratio_(imaging_ratio) {
    if (white_balance_temperature != 0)
        xyz_from_sensor_rgb_ = white_balance(spectrum_to_xyz(*white_balance_illuminant(white_balance_temperature)).xy(),
                                             output.whitepoint().xy());
}

PixelSensor::PixelSensor(const RGBColorSpace &output, const Spectrum &r, const Spectrum &g, const Spectrum &b,
                         float white_balance_temperature, float imaging_ratio)
    : r_bar_(dense(r)), g_bar_(dense(g)), b_bar_(dense(b)), imaging_ratio_(imaging_ratio) {
    const std::shared_ptr<const Spectrum> illuminant = white_balance_illuminant(white_balance_temperature);
    // The chart's XYZ under the output's white, scaled so that the sensor's green and Y agree
    // on the white-balance illuminant.
    const double white_y = inner_product(*illuminant, cie_y()), white_g = inner_product(*illuminant, *g_bar_);
    std::vector<std::array<double, 3>> camera, xyz;
    for (const RGBAlbedoSpectrum &patch : training_chart()) {
        camera.push_back(project_reflectance(patch, *illuminant, *r_bar_, *g_bar_, *b_bar_));
        std::array<double, 3> v = project_reflectance(patch, output.illuminant(), cie_x(), cie_y(), cie_z());
        for (double &c : v) c *= white_y / white_g;
        xyz.push_back(v);
    }
    xyz_from_sensor_rgb_ = least_squares(camera, xyz);
}

RGB PixelSensor::to_sensor_rgb(const Spectrum &s) const {
    return RGB{inner_product(*r_bar_, s), inner_product(*g_bar_, s), inner_product(*b_bar_, s)} * imaging_ratio_;
}

RGB PixelSensor::to_sensor_rgb(const SampledSpectrum &L, const SampledWavelengths &lambda) const {
    SampledSpectrum radiance = safe_div(L, lambda.pdf());
    return RGB{(r_bar_->sample(lambda) * radiance).average(), (g_bar_->sample(lambda) * radiance).average(),
               (b_bar_->sample(lambda) * radiance).average()} *
           imaging_ratio_;
}

} // namespace caustica
