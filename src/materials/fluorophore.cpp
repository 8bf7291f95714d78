#include "materials/fluorophore.h"

#include "spectral/sampled_wavelengths.h"

#include <stdexcept>

namespace caustica {

namespace {

constexpr int Bins = int(LambdaMax - LambdaMin); // 1 nm each

float bin_centre(int i) { return LambdaMin + i + 0.5f; }

// Position of lambda in the bins, as a float index clamped to [0, Bins].
float bin_position(float lambda) { return clamp(lambda - LambdaMin, 0.f, float(Bins)); }

// Linear interpolation of a running sum tabulated at the bin edges.
float running_sum(const std::vector<float> &edges, float lambda) {
    const float x = bin_position(lambda);
    const int i = std::min(int(x), Bins - 1);
    return edges[i] + (edges[i + 1] - edges[i]) * (x - i);
}

} // namespace

Fluorophore::Fluorophore(SpectrumPtr absorption, SpectrumPtr emission, float quantum_yield)
    : absorption_(std::move(absorption)), emission_(std::move(emission)), quantum_yield_(clamp(quantum_yield, 0.f, 1.f)) {
    double total = 0;
    for (int i = 0; i < Bins; ++i) total += std::max((*emission_)(bin_centre(i)), 0.f);
    if (!(total > 0)) throw std::invalid_argument("the emission spectrum has no power between 360 and 830 nm");
    emission_scale_ = float(1 / total);
    std::vector<float> excite(Bins), emit(Bins);
    excitation_below_.assign(Bins + 1, 0.f);
    emission_above_.assign(Bins + 1, 0.f);
    for (int i = 0; i < Bins; ++i) {
        const float lambda = bin_centre(i);
        excite[i] = this->absorption(lambda) * lambda;
        emit[i] = this->emission(lambda) / lambda;
        excitation_below_[i + 1] = excitation_below_[i] + excite[i];
    }
    for (int i = Bins - 1; i >= 0; --i) emission_above_[i] = emission_above_[i + 1] + emit[i];
    excitation_ = PiecewiseConstant1D(excite);
    emission_density_ = PiecewiseConstant1D(emit);
}

float Fluorophore::reradiation(float lambda_in, float lambda_out) const {
    if (lambda_in > lambda_out) return 0;
    return absorption(lambda_in) * quantum_yield_ * emission(lambda_out) * (lambda_in / lambda_out);
}

Fluorophore::WavelengthSample Fluorophore::sample_excitation(float u) const {
    if (excitation_.integral() == 0) return {};
    WavelengthSample s;
    s.lambda = LambdaMin + excitation_.sample(u, &s.pdf) * Bins;
    s.pdf /= Bins; // from the unit interval to nm
    return s;
}

Fluorophore::WavelengthSample Fluorophore::sample_emission(float u) const {
    WavelengthSample s;
    s.lambda = LambdaMin + emission_density_.sample(u, &s.pdf) * Bins;
    s.pdf /= Bins;
    return s;
}

float Fluorophore::importance_albedo(float lambda_in) const {
    return absorption(lambda_in) * quantum_yield_ * lambda_in * running_sum(emission_above_, lambda_in);
}

float Fluorophore::radiance_albedo(float lambda_out) const {
    return quantum_yield_ * emission(lambda_out) / lambda_out * running_sum(excitation_below_, lambda_out);
}

std::vector<float> Fluorophore::reemitted(const std::function<float(float)> &incident) const {
    std::vector<float> absorbed(Bins + 1);
    for (int i = 0; i <= Bins; ++i) absorbed[i] = incident(LambdaMin + i);
    std::vector<float> out(Bins + 1, 0.f);
    for (int o = 0; o <= Bins; ++o)
        for (int i = 0; i <= o; ++i)
            if (absorbed[i] > 0) out[o] += absorbed[i] * reradiation(LambdaMin + i, LambdaMin + o);
    return out;
}

ReradiationShift sample_reradiation_shift(const Fluorophore &dye, TransportMode mode, const SampledWavelengths &lambda,
                                          float u) {
    const bool radiance = mode == TransportMode::Radiance;
    const Fluorophore::WavelengthSample w = radiance ? dye.sample_excitation(u) : dye.sample_emission(u);
    ReradiationShift shift;
    if (!(w.pdf > 0)) return shift;
    shift.lambda = w.lambda;
    for (int j = 0; j < NumWavelengths; ++j)
        shift.albedo[j] = (radiance ? dye.reradiation(w.lambda, lambda[j]) : dye.reradiation(lambda[j], w.lambda)) / w.pdf;
    return shift;
}

} // namespace caustica
