#include "spectral/color_space.h"

#include "spectral/cie.h"
#include "spectral/named_spectra.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace caustica {

RGBColorSpace::RGBColorSpace(std::string name, Chromaticity red, Chromaticity green,
                             Chromaticity blue, const Spectrum &illuminant,
                             const RGBToSpectrumTable &table)
    : name_(std::move(name)),
      red_(red),
      green_(green),
      blue_(blue),
      illuminant_(illuminant),
      whitepoint_(spectrum_to_xyz(illuminant)),
      xyz_from_rgb_(rgb_to_xyz_matrix(red, green, blue, whitepoint_)),
      rgb_from_xyz_(xyz_from_rgb_.inverse()),
      table_(&table) {}

SigmoidPolynomial RGBColorSpace::to_coefficients(const RGB &rgb) const {
    RGB clamped{std::clamp(rgb.r, 0.f, 1.f), std::clamp(rgb.g, 0.f, 1.f),
                std::clamp(rgb.b, 0.f, 1.f)};
    return (*table_)(clamped);
}

namespace {

// A standard space and the table it refers to, allocated together and never freed or moved.
struct StandardColorSpace {
    StandardColorSpace(const ColorSpaceDefinition &def, const RGBToSpectrumTableData &data,
                       const Spectrum &illuminant)
        : table(data),
          space(std::string(def.name), def.red, def.green, def.blue, illuminant, table) {}
    RGBToSpectrumTable table;
    RGBColorSpace space;
};

std::unique_ptr<StandardColorSpace> make_standard_color_space(const ColorSpaceDefinition &def) {
    const RGBToSpectrumTableData *data = rgb_to_spectrum_table_data(def.name);
    SpectrumPtr illuminant = get_named_spectrum(std::string(def.illuminant));
    if (!data || !illuminant)
        throw std::logic_error("colour space " + std::string(def.name) +
                               " has no generated RGB-to-spectrum table or no illuminant");
    return std::make_unique<StandardColorSpace>(def, *data, *illuminant);
}

} // namespace

const RGBColorSpace &RGBColorSpace::srgb() {
    static const auto cs = make_standard_color_space(StandardColorSpaces[0]);
    return cs->space;
}

const RGBColorSpace &RGBColorSpace::aces2065_1() {
    static const auto cs = make_standard_color_space(StandardColorSpaces[1]);
    return cs->space;
}

const RGBColorSpace &RGBColorSpace::rec2020() {
    static const auto cs = make_standard_color_space(StandardColorSpaces[2]);
    return cs->space;
}

const RGBColorSpace &RGBColorSpace::dci_p3() {
    static const auto cs = make_standard_color_space(StandardColorSpaces[3]);
    return cs->space;
}

const RGBColorSpace *RGBColorSpace::by_name(std::string_view name) {
    if (name == "srgb") return &srgb();
    if (name == "aces2065-1") return &aces2065_1();
    if (name == "rec2020") return &rec2020();
    if (name == "dci-p3") return &dci_p3();
    return nullptr;
}

Matrix3 rgb_conversion_matrix(const RGBColorSpace &from, const RGBColorSpace &to) {
    return to.rgb_from_xyz_matrix() * from.xyz_from_rgb_matrix();
}

XYZ spectrum_to_xyz(const Spectrum &s) {
    return XYZ{inner_product(cie_x(), s), inner_product(cie_y(), s), inner_product(cie_z(), s)} /
           CIE_Y_integral;
}

XYZ sampled_spectrum_to_xyz(const SampledSpectrum &s, const SampledWavelengths &lambda) {
    SampledSpectrum pdf = lambda.pdf();
    return XYZ{safe_div(cie_x().sample(lambda) * s, pdf).average(),
               safe_div(cie_y().sample(lambda) * s, pdf).average(),
               safe_div(cie_z().sample(lambda) * s, pdf).average()} /
           CIE_Y_integral;
}

float sampled_spectrum_to_y(const SampledSpectrum &s, const SampledWavelengths &lambda) {
    return safe_div(cie_y().sample(lambda) * s, lambda.pdf()).average() / CIE_Y_integral;
}

float srgb_to_linear(float v) {
    if (v <= 0.04045f) return v / 12.92f;
    return std::pow((v + 0.055f) / 1.055f, 2.4f);
}

} // namespace caustica
