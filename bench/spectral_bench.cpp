// Cost of the spectral conversions made at every path vertex or camera sample: sampling the
// hero-wavelength set, a Sellmeier glass's index at its four wavelengths, turning an RGB value
// into a spectrum (the coefficient-table lookup, done per texture evaluation of an RGB texture,
// and the sigmoid polynomial's evaluation at four wavelengths), and the film's conversion of a
// sampled spectrum into sensor RGB. Inputs are generated once and cycled through, so the
// timings hold the conversion, not the RNG.
//   caustica_bench --benchmark_filter='Wavelength|Sellmeier|RGB|Sigmoid|Sensor'
#include "core/rng.h"
#include "film/pixel_sensor.h"
#include "spectral/color_space.h"
#include "spectral/ior.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace caustica {
namespace {

constexpr size_t InputCount = 4096;

const std::vector<float> &uniforms() {
    static const std::vector<float> u = [] {
        std::vector<float> v(InputCount);
        Rng rng(21, 1);
        for (float &x : v) x = rng.uniform();
        return v;
    }();
    return u;
}

const std::vector<SampledWavelengths> &wavelength_sets() {
    static const std::vector<SampledWavelengths> sets = [] {
        std::vector<SampledWavelengths> s;
        for (float u : uniforms()) s.push_back(SampledWavelengths::sample_visible(u));
        return s;
    }();
    return sets;
}

// Reflectance-like RGB values (in [0, 1]) and radiance-like spectra (in [0, 2)).
const std::vector<RGB> &rgb_values() {
    static const std::vector<RGB> values = [] {
        std::vector<RGB> v(InputCount);
        Rng rng(21, 2);
        for (RGB &c : v) c = {rng.uniform(), rng.uniform(), rng.uniform()};
        return v;
    }();
    return values;
}

const std::vector<SampledSpectrum> &radiance_values() {
    static const std::vector<SampledSpectrum> values = [] {
        std::vector<SampledSpectrum> v(InputCount);
        Rng rng(21, 3);
        for (SampledSpectrum &s : v)
            for (int i = 0; i < NumWavelengths; ++i) s[i] = 2 * rng.uniform();
        return v;
    }();
    return values;
}

void BM_SampleVisibleWavelengths(benchmark::State &state) {
    const std::vector<float> &u = uniforms();
    size_t i = 0;
    for (auto _ : state) {
        SampledWavelengths lambda = SampledWavelengths::sample_visible(u[i++ % u.size()]);
        benchmark::DoNotOptimize(lambda);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SampleVisibleWavelengths);

// Through the Spectrum interface, as a material samples its "spectrum eta".
void BM_SellmeierIndex(benchmark::State &state) {
    SpectrumPtr glass = named_ior("glass-BK7");
    const std::vector<SampledWavelengths> &lambdas = wavelength_sets();
    size_t i = 0;
    for (auto _ : state) {
        SampledSpectrum eta = glass->sample(lambdas[i++ % lambdas.size()]);
        benchmark::DoNotOptimize(eta);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SellmeierIndex);

void BM_RGBToCoefficients(benchmark::State &state) {
    const RGBColorSpace &srgb = RGBColorSpace::srgb();
    const std::vector<RGB> &rgb = rgb_values();
    size_t i = 0;
    for (auto _ : state) {
        SigmoidPolynomial polynomial = srgb.to_coefficients(rgb[i++ % rgb.size()]);
        benchmark::DoNotOptimize(polynomial);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RGBToCoefficients);

void BM_SigmoidPolynomialSample(benchmark::State &state) {
    const RGBColorSpace &srgb = RGBColorSpace::srgb();
    std::vector<SigmoidPolynomial> polynomials;
    for (const RGB &rgb : rgb_values()) polynomials.push_back(srgb.to_coefficients(rgb));
    const std::vector<SampledWavelengths> &lambdas = wavelength_sets();
    size_t i = 0;
    for (auto _ : state) {
        size_t k = i++ % InputCount;
        SampledSpectrum s = polynomials[k].sample(lambdas[k]);
        benchmark::DoNotOptimize(s);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SigmoidPolynomialSample);

void BM_SensorRGB(benchmark::State &state) {
    PixelSensor sensor(RGBColorSpace::srgb(), 0, 1);
    const std::vector<SampledSpectrum> &radiance = radiance_values();
    const std::vector<SampledWavelengths> &lambdas = wavelength_sets();
    size_t i = 0;
    for (auto _ : state) {
        size_t k = i++ % InputCount;
        RGB rgb = sensor.to_sensor_rgb(radiance[k], lambdas[k]);
        benchmark::DoNotOptimize(rgb);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SensorRGB);

} // namespace
} // namespace caustica
