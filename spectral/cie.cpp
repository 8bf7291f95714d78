#include "spectral/cie.h"

#include "spectral/cie_data.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace caustica {

namespace {

DenselySampledSpectrum tabulated_cmf(const float (&values)[cie_data::CmfSamples]) {
    std::vector<float> lambdas(cie_data::CmfSamples);
    for (int i = 0; i < cie_data::CmfSamples; ++i) lambdas[i] = float(cie_data::CmfLambdaMin + i);
    return DenselySampledSpectrum(PiecewiseLinearSpectrum(lambdas, values));
}

PiecewiseLinearSpectrum regularly_sampled(std::span<const float> values, float lambda_min,
                                          float lambda_step) {
    std::vector<float> lambdas(values.size());
    for (size_t i = 0; i < values.size(); ++i) lambdas[i] = lambda_min + float(i) * lambda_step;
    return PiecewiseLinearSpectrum(lambdas, values);
}

// Illuminant A by CIE 015's formula, which keeps the original definition (T = 2848 K with
// c2 = 1.435e-2 m K; the same curve as 2856 K with today's c2 = 1.4388e-2 m K), so that it
// reproduces the CIE's tabulated values exactly.
class IlluminantA final : public Spectrum {
  public:
    float operator()(float lambda) const override {
        constexpr double c2_over_t = 1.435e7 / 2848;  // nm
        double l = lambda;
        return float(100 * std::pow(560 / l, 5) * std::expm1(c2_over_t / 560) /
                     std::expm1(c2_over_t / l));
    }
    float max_value() const override { return (*this)(LambdaMax); }  // increasing over the range
};

} // namespace

const DenselySampledSpectrum &cie_x() {
    static const DenselySampledSpectrum x = tabulated_cmf(cie_data::x_bar);
    return x;
}

const DenselySampledSpectrum &cie_y() {
    static const DenselySampledSpectrum y = tabulated_cmf(cie_data::y_bar);
    return y;
}

const DenselySampledSpectrum &cie_z() {
    static const DenselySampledSpectrum z = tabulated_cmf(cie_data::z_bar);
    return z;
}

const Spectrum &cie_illuminant_a() {
    static const IlluminantA a;
    return a;
}

const PiecewiseLinearSpectrum &cie_illuminant_d65() {
    static const PiecewiseLinearSpectrum d65 = regularly_sampled(
        cie_data::illuminant_d65, cie_data::DaylightLambdaMin, cie_data::DaylightLambdaStep);
    return d65;
}

const PiecewiseLinearSpectrum &cie_illuminant_f(int number) {
    static const std::vector<PiecewiseLinearSpectrum> f = [] {
        std::vector<PiecewiseLinearSpectrum> all;
        for (const auto &table : cie_data::illuminant_f)
            all.push_back(regularly_sampled(table, cie_data::FluorescentLambdaMin,
                                            cie_data::FluorescentLambdaStep));
        return all;
    }();
    if (number < 1 || number > 12)
        throw std::out_of_range("CIE fluorescent illuminant F" + std::to_string(number) +
                                " does not exist (F1..F12)");
    return f[number - 1];
}

std::shared_ptr<PiecewiseLinearSpectrum> daylight_illuminant(float cct) {
    if (!(cct >= 4000 && cct <= 25000))
        throw std::domain_error("CIE daylight illuminants are defined for 4000 K to 25000 K, not " +
                                std::to_string(cct) + " K");
    // Chromaticity of daylight at this CCT, then the weights of the basis functions
    // (CIE 015:2018, equations 4.7 to 4.10).
    double t = cct;
    double x = t <= 7000 ? -4.6070e9 / (t * t * t) + 2.9678e6 / (t * t) + 0.09911e3 / t + 0.244063
                         : -2.0064e9 / (t * t * t) + 1.9018e6 / (t * t) + 0.24748e3 / t + 0.237040;
    double y = -3.000 * x * x + 2.870 * x - 0.275;
    double m = 0.0241 + 0.2562 * x - 0.7341 * y;
    double m1 = std::round((-1.3515 - 1.7703 * x + 5.9114 * y) / m * 1000) / 1000;
    double m2 = std::round((0.0300 - 31.4424 * x + 30.0717 * y) / m * 1000) / 1000;
    std::vector<float> values(cie_data::DaylightSamples);
    for (int i = 0; i < cie_data::DaylightSamples; ++i)
        values[i] = float(cie_data::daylight_s0[i] + m1 * cie_data::daylight_s1[i] +
                          m2 * cie_data::daylight_s2[i]);
    return std::make_shared<PiecewiseLinearSpectrum>(
        regularly_sampled(values, cie_data::DaylightLambdaMin, cie_data::DaylightLambdaStep));
}

} // namespace caustica
