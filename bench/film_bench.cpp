// Cost of recording one sample in the film (src/film), single-threaded: add_sample, which every
// camera sample makes (sensor RGB plus the pixel's weighted sum), and add_splat, which light
// tracing and the bidirectional integrators make for every light-path vertex that reaches the
// camera (sensor RGB, then the filter evaluated at each pixel within its radius and added with
// an atomic). add_splat is measured with pbrt's default Gaussian filter (radius 1.5: 9 to 16
// pixels per splat) and with the box filter (1 to 4), since its cost grows with the footprint.
// Samples visit pixels in raster order, as a tile does; splats land at random film positions.
//   caustica_bench --benchmark_filter=Film
#include "core/rng.h"
#include "film/film.h"

#include <benchmark/benchmark.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace caustica {
namespace {

constexpr int FilmSize = 512;
constexpr size_t InputCount = 4096;

struct SampleInput {
    Vec2f p_raster;
    SampledSpectrum L;
    SampledWavelengths lambda;
};

const std::vector<SampleInput> &sample_inputs() {
    static const std::vector<SampleInput> inputs = [] {
        std::vector<SampleInput> v(InputCount);
        Rng rng(31, 1);
        for (SampleInput &s : v) {
            s.p_raster = {FilmSize * rng.uniform(), FilmSize * rng.uniform()};
            for (int i = 0; i < NumWavelengths; ++i) s.L[i] = 2 * rng.uniform();
            s.lambda = SampledWavelengths::sample_visible(rng.uniform());
        }
        return v;
    }();
    return inputs;
}

std::unique_ptr<Film> make_film(const std::string &filter) {
    std::unique_ptr<Filter> f;
    if (filter == "gaussian") f = std::make_unique<GaussianFilter>();
    else if (filter == "box") f = std::make_unique<BoxFilter>();
    else throw std::invalid_argument("no filter \"" + filter + "\"");
    const RGBColorSpace &srgb = RGBColorSpace::srgb();
    return std::make_unique<Film>(Vec2i{FilmSize, FilmSize}, PixelBounds{{0, 0}, {FilmSize, FilmSize}},
                                  std::move(f), srgb, PixelSensor(srgb, 0, 1), Infinity, "bench.exr",
                                  false);
}

void BM_FilmAddSample(benchmark::State &state) {
    std::unique_ptr<Film> film = make_film("gaussian");
    const std::vector<SampleInput> &inputs = sample_inputs();
    size_t i = 0;
    int pixel = 0;
    for (auto _ : state) {
        const SampleInput &s = inputs[i++ % inputs.size()];
        film->add_sample({pixel % FilmSize, pixel / FilmSize}, s.L, s.lambda, 1);
        pixel = (pixel + 1) % (FilmSize * FilmSize);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FilmAddSample);

void BM_FilmAddSplat(benchmark::State &state, const char *filter) {
    std::unique_ptr<Film> film = make_film(filter);
    const std::vector<SampleInput> &inputs = sample_inputs();
    size_t i = 0;
    for (auto _ : state) {
        const SampleInput &s = inputs[i++ % inputs.size()];
        film->add_splat(s.p_raster, s.L, s.lambda);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_FilmAddSplat, gaussian, "gaussian");
BENCHMARK_CAPTURE(BM_FilmAddSplat, box, "box");

} // namespace
} // namespace caustica
