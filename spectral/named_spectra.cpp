#include "spectral/named_spectra.h"

#include "spectral/camera_sensor_data.h"
#include "spectral/cie.h"
#include "spectral/ior.h"
#include "spectral/metal_data.h"

#include <map>

namespace caustica {

namespace {

template <typename S>
std::shared_ptr<S> normalized(std::shared_ptr<S> illuminant) {
    illuminant->scale(CIE_Y_integral / inner_product_y(*illuminant));
    return illuminant;
}

// A measured table, held constant beyond its first and last samples so that the index never
// drops to zero inside [LambdaMin, LambdaMax] (a zero eta would make a metal a perfect mirror).
SpectrumPtr measured(std::span<const float> lambdas, std::span<const float> values) {
    std::vector<float> l(lambdas.begin(), lambdas.end()), v(values.begin(), values.end());
    if (l.front() > LambdaMin) {
        l.insert(l.begin(), LambdaMin);
        v.insert(v.begin(), v.front());
    }
    if (l.back() < LambdaMax) {
        l.push_back(LambdaMax);
        v.push_back(v.back());
    }
    return std::make_shared<PiecewiseLinearSpectrum>(l, v);
}

std::map<std::string, SpectrumPtr> build_named_spectra() {
    namespace md = metal_data;
    std::map<std::string, SpectrumPtr> spectra;
    for (std::string_view name : named_ior_names()) spectra[std::string(name)] = named_ior(name);

    spectra["metal-Ag-eta"] = measured(md::palik_lambda, md::silver_eta);
    spectra["metal-Ag-k"] = measured(md::palik_lambda, md::silver_k);
    spectra["metal-Al-eta"] = measured(md::palik_lambda, md::aluminium_eta);
    spectra["metal-Al-k"] = measured(md::palik_lambda, md::aluminium_k);
    spectra["metal-Au-eta"] = measured(md::palik_lambda, md::gold_eta);
    spectra["metal-Au-k"] = measured(md::palik_lambda, md::gold_k);
    spectra["metal-Cu-eta"] = measured(md::palik_lambda, md::copper_eta);
    spectra["metal-Cu-k"] = measured(md::palik_lambda, md::copper_k);
    spectra["metal-CuZn-eta"] = measured(md::brass_lambda, md::brass_eta);
    spectra["metal-CuZn-k"] = measured(md::brass_lambda, md::brass_k);
    spectra["metal-MgO-eta"] = measured(md::magnesium_oxide_lambda, md::magnesium_oxide_eta);
    spectra["metal-MgO-k"] = measured(md::magnesium_oxide_lambda, md::magnesium_oxide_k);
    spectra["metal-TiO2-eta"] = measured(md::titanium_dioxide_lambda, md::titanium_dioxide_eta);
    spectra["metal-TiO2-k"] = measured(md::titanium_dioxide_lambda, md::titanium_dioxide_k);

    spectra["stdillum-A"] =
        normalized(std::make_shared<DenselySampledSpectrum>(cie_illuminant_a()));
    // D50 and D65 are CIE daylight at 5000 K and 6500 K on the temperature scale of their
    // definition; the D65 table is used as published, D50 from the daylight formula (its table
    // is that formula's output).
    spectra["stdillum-D50"] = normalized(daylight_illuminant(5000 * 1.4388f / 1.4380f));
    spectra["stdillum-D65"] =
        normalized(std::make_shared<PiecewiseLinearSpectrum>(cie_illuminant_d65()));
    for (int i = 1; i <= 12; ++i)
        spectra["stdillum-F" + std::to_string(i)] =
            normalized(std::make_shared<PiecewiseLinearSpectrum>(cie_illuminant_f(i)));
    // The ACES white point: CIE daylight at exactly 6000 K (SMPTE ST 2065-1).
    spectra["illum-acesD60"] = normalized(daylight_illuminant(6000));
    for (const CameraSensorCurves &sensor : camera_sensor_curves()) {
        spectra[sensor.name + "_r"] = PiecewiseLinearSpectrum::from_interleaved(sensor.r, false);
        spectra[sensor.name + "_g"] = PiecewiseLinearSpectrum::from_interleaved(sensor.g, false);
        spectra[sensor.name + "_b"] = PiecewiseLinearSpectrum::from_interleaved(sensor.b, false);
    }
    return spectra;
}

const std::map<std::string, SpectrumPtr> &named_spectra() {
    static const std::map<std::string, SpectrumPtr> spectra = build_named_spectra();
    return spectra;
}

} // namespace

SpectrumPtr get_named_spectrum(const std::string &name) {
    auto it = named_spectra().find(name);
    return it == named_spectra().end() ? nullptr : it->second;
}

std::vector<std::string> named_spectrum_names() {
    std::vector<std::string> names;
    for (const auto &[name, spectrum] : named_spectra()) names.push_back(name);
    return names;
}

} // namespace caustica
