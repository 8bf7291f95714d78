#include "spectral/spectrum.h"

#include "spectral/cie.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace caustica {

PiecewiseLinearSpectrum::PiecewiseLinearSpectrum(std::span<const float> lambdas,
                                                 std::span<const float> values)
    : lambdas_(lambdas.begin(), lambdas.end()), values_(values.begin(), values.end()) {
    if (lambdas_.size() != values_.size())
        throw std::invalid_argument(
            "piecewise-linear spectrum: " + std::to_string(lambdas_.size()) + " wavelengths but " +
            std::to_string(values_.size()) + " values");
    for (size_t i = 1; i < lambdas_.size(); ++i)
        if (!(lambdas_[i - 1] < lambdas_[i]))
            throw std::invalid_argument("piecewise-linear spectrum: wavelengths must increase (" +
                                        std::to_string(lambdas_[i - 1]) + " then " +
                                        std::to_string(lambdas_[i]) + ")");
}

std::shared_ptr<PiecewiseLinearSpectrum> PiecewiseLinearSpectrum::from_interleaved(
    std::span<const float> pairs, bool normalize) {
    if (pairs.size() % 2 != 0)
        throw std::invalid_argument("interleaved spectrum: odd number of values (" +
                                    std::to_string(pairs.size()) + ")");
    std::vector<float> lambdas, values;
    for (size_t i = 0; i < pairs.size(); i += 2) {
        lambdas.push_back(pairs[i]);
        values.push_back(pairs[i + 1]);
    }
    auto spectrum = std::make_shared<PiecewiseLinearSpectrum>(lambdas, values);
    // Illuminants are normalised to luminance Y = 1 (pbrt's convention), so that a light's
    // "scale"/"power" alone sets its brightness whatever tabulated data it uses.
    if (normalize) spectrum->scale(CIE_Y_integral / inner_product_y(*spectrum));
    return spectrum;
}

float PiecewiseLinearSpectrum::operator()(float lambda) const {
    if (lambdas_.empty() || lambda < lambdas_.front() || lambda > lambdas_.back()) return 0;
    if (lambdas_.size() == 1) return values_[0];
    // First knot strictly above lambda, clamped so that lambda == back() uses the last segment.
    size_t hi = std::upper_bound(lambdas_.begin(), lambdas_.end(), lambda) - lambdas_.begin();
    hi = std::clamp<size_t>(hi, 1, lambdas_.size() - 1);
    size_t lo = hi - 1;
    float t = (lambda - lambdas_[lo]) / (lambdas_[hi] - lambdas_[lo]);
    return (1 - t) * values_[lo] + t * values_[hi];
}

float PiecewiseLinearSpectrum::max_value() const {
    if (values_.empty()) return 0;
    return *std::max_element(values_.begin(), values_.end());
}

void PiecewiseLinearSpectrum::scale(float s) {
    for (float &v : values_) v *= s;
}

DenselySampledSpectrum::DenselySampledSpectrum(const Spectrum &s) {
    values_.resize(size_t(LambdaMax - LambdaMin) + 1);
    for (size_t i = 0; i < values_.size(); ++i) values_[i] = s(LambdaMin + float(i));
}

float DenselySampledSpectrum::max_value() const {
    return *std::max_element(values_.begin(), values_.end());
}

void DenselySampledSpectrum::scale(float s) {
    for (float &v : values_) v *= s;
}

float blackbody(float lambda_nm, float temperature_k) {
    if (temperature_k <= 0) return 0;
    // Physical constants as pbrt-v4 uses them (CODATA 2010), so radiances agree with it.
    constexpr double c = 299792458.;      // speed of light, m/s
    constexpr double h = 6.62606957e-34;  // Planck constant, J s
    constexpr double kb = 1.3806488e-23;  // Boltzmann constant, J/K
    double l = double(lambda_nm) * 1e-9;  // metres
    double l5 = (l * l) * (l * l) * l;
    return float((2 * h * c * c) / (l5 * std::expm1((h * c) / (l * kb * temperature_k))));
}

BlackbodySpectrum::BlackbodySpectrum(float temperature_k) : t_(temperature_k), normalization_(0) {
    if (temperature_k <= 0) return;  // no emission
    // Wien's displacement law gives the peak, lambda_max = b / T with b = 2.8977721e-3 m K.
    float lambda_max_nm = 2.8977721e-3f / temperature_k * 1e9f;
    normalization_ = 1 / blackbody(lambda_max_nm, temperature_k);
}

float BlackbodySpectrum::operator()(float lambda) const {
    return blackbody(lambda, t_) * normalization_;
}

float inner_product(const Spectrum &a, const Spectrum &b) {
    float sum = 0;
    for (float lambda = LambdaMin; lambda <= LambdaMax; ++lambda) sum += a(lambda) * b(lambda);
    return sum;
}

float inner_product_y(const Spectrum &s) { return inner_product(s, cie_y()); }

float peak_wavelength(const Spectrum &s) {
    float peak = LambdaMin;
    for (float lambda = LambdaMin; lambda <= LambdaMax; ++lambda)
        if (s(lambda) > s(peak)) peak = lambda;
    return peak;
}

float visible_integral(const Spectrum &s) { return inner_product(s, ConstantSpectrum(1)); }

bool is_flat(const Spectrum &s) { return s.is_constant() || is_multiple_of(s, ConstantSpectrum(1)); }

bool is_multiple_of(const Spectrum &b, const Spectrum &a) {
    // The factor from the wavelength where a is largest, then every wavelength checked against it.
    float a_max = 0, b_at_a_max = 0;
    for (float lambda = LambdaMin; lambda <= LambdaMax; ++lambda)
        if (a(lambda) > a_max) {
            a_max = a(lambda);
            b_at_a_max = b(lambda);
        }
    if (!(a_max > 0)) return false;
    const float k = b_at_a_max / a_max;
    if (!(k >= 0)) return false;
    constexpr float tolerance = 1e-4f;
    for (float lambda = LambdaMin; lambda <= LambdaMax; ++lambda)
        if (std::abs(b(lambda) - k * a(lambda)) > tolerance * std::max(std::abs(b(lambda)), k * a_max)) return false;
    return true;
}

} // namespace caustica
