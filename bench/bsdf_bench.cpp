// Cost of one call of each BxDF's f, sample_f and pdf (src/materials), the three queries an
// integrator makes at every surface vertex. The directions and random numbers are generated once
// and cycled through, so the timings hold the BxDF alone, not the RNG; the BxDFs are called
// through the BxDF interface, as BSDF calls them in the renderer. Each BxDF holds spectra sampled
// at one hero-wavelength set from SampledWavelengths::sample_visible. Specular BxDFs have only
// sample_f: their f and pdf are zero by definition and return at once.
//   caustica_bench --benchmark_filter=BxDF
#include "core/rng.h"
#include "core/sampling.h"
#include "core/scratch_buffer.h"
#include "materials/conductor_bxdf.h"
#include "materials/dielectric_bxdf.h"
#include "materials/diffuse_bxdf.h"
#include "materials/disney_bxdf.h"
#include "materials/thin_dielectric_bxdf.h"
#include "spectral/color_space.h"
#include "spectral/ior.h"
#include "spectral/named_spectra.h"
#include "spectral/rgb_spectrum.h"

#include <benchmark/benchmark.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace caustica {
namespace {

// One query's inputs: wo on the outside (upper) hemisphere, wi anywhere on the sphere so that
// transmission lobes are evaluated as often as reflection ones.
struct Query {
    Vec3f wo, wi;
    float uc;
    Vec2f u;
};

const std::vector<Query> &queries() {
    static const std::vector<Query> set = [] {
        std::vector<Query> q(4096);
        Rng rng(11, 5);
        for (Query &query : q) {
            query.wo = sample_uniform_hemisphere(rng.uniform2());
            query.wi = sample_uniform_sphere(rng.uniform2());
            query.uc = rng.uniform();
            query.u = rng.uniform2();
        }
        return q;
    }();
    return set;
}

const SampledWavelengths &wavelengths() {
    static const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.37f);
    return lambda;
}

SampledSpectrum rgb_albedo(RGB rgb) {
    return RGBAlbedoSpectrum(RGBColorSpace::srgb(), rgb).sample(wavelengths());
}

SampledSpectrum named(const std::string &name) { return get_named_spectrum(name)->sample(wavelengths()); }

// The Disney parameter sets: a rough plastic, an anisotropic metal, a glass, a thin
// translucent sheet, and a coated cloth-like base with clearcoat and sheen.
DisneyParameters disney_parameters(const std::string &name) {
    DisneyParameters p;
    RGB base{0.8f, 0.3f, 0.2f};
    p.base_color = rgb_albedo(base);
    p.base_luminance = 0.2126f * base.r + 0.7152f * base.g + 0.0722f * base.b;
    if (name == "disney_plastic") {
        p.roughness = 0.3f;
    } else if (name == "disney_metal") {
        p.metallic = 1;
        p.roughness = 0.25f;
        p.anisotropic = 0.5f;
    } else if (name == "disney_glass") {
        p.spec_trans = 1;
        p.roughness = 0.1f;
    } else if (name == "disney_thin") {
        p.thin = true;
        p.spec_trans = 0.5f;
        p.diff_trans = 1;
        p.flatness = 0.5f;
        p.roughness = 0.4f;
    } else if (name == "disney_clearcoat_sheen") {
        p.roughness = 0.5f;
        p.clearcoat = 1;
        p.clearcoat_gloss = 0.8f;
        p.sheen = 1;
    } else {
        throw std::invalid_argument("no Disney parameter set \"" + name + "\"");
    }
    return p;
}

const BxDF &bxdf_named(const std::string &name) {
    static ScratchBuffer storage;
    static std::map<std::string, const BxDF *> made;
    auto [it, inserted] = made.try_emplace(name, nullptr);
    if (!inserted) return *it->second;
    const TrowbridgeReitzDistribution smooth(0, 0), rough(0.3f, 0.3f);
    const SampledSpectrum glass(1.5f), flint = named_ior("glass-F11")->sample(wavelengths());
    if (name == "diffuse")
        it->second = storage.make<DiffuseBxDF>(rgb_albedo({0.8f, 0.3f, 0.2f}));
    else if (name == "dielectric_smooth")
        it->second = storage.make<DielectricBxDF>(glass, smooth);
    else if (name == "dielectric_smooth_dispersive")
        it->second = storage.make<DielectricBxDF>(flint, smooth);
    else if (name == "dielectric_rough")
        it->second = storage.make<DielectricBxDF>(glass, rough);
    else if (name == "dielectric_rough_dispersive")
        it->second = storage.make<DielectricBxDF>(flint, rough);
    else if (name == "conductor_smooth")
        it->second = storage.make<ConductorBxDF>(smooth, named("metal-Cu-eta"), named("metal-Cu-k"));
    else if (name == "conductor_rough")
        it->second = storage.make<ConductorBxDF>(rough, named("metal-Cu-eta"), named("metal-Cu-k"));
    else if (name == "thin_dielectric")
        it->second = storage.make<ThinDielectricBxDF>(glass);
    else
        it->second = storage.make<DisneyBxDF>(disney_parameters(name));
    return *it->second;
}

void BM_BxDFEval(benchmark::State &state, const char *name) {
    const BxDF &bxdf = bxdf_named(name);
    const std::vector<Query> &q = queries();
    size_t i = 0;
    for (auto _ : state) {
        const Query &query = q[i++ % q.size()];
        SampledSpectrum f = bxdf.f(query.wo, query.wi, TransportMode::Radiance);
        benchmark::DoNotOptimize(f);
    }
    state.SetItemsProcessed(state.iterations());
}

void BM_BxDFSample(benchmark::State &state, const char *name) {
    const BxDF &bxdf = bxdf_named(name);
    const std::vector<Query> &q = queries();
    size_t i = 0;
    for (auto _ : state) {
        const Query &query = q[i++ % q.size()];
        std::optional<BSDFSample> sample = bxdf.sample_f(query.wo, query.uc, query.u, TransportMode::Radiance);
        benchmark::DoNotOptimize(sample);
    }
    state.SetItemsProcessed(state.iterations());
}

void BM_BxDFPdf(benchmark::State &state, const char *name) {
    const BxDF &bxdf = bxdf_named(name);
    const std::vector<Query> &q = queries();
    size_t i = 0;
    for (auto _ : state) {
        const Query &query = q[i++ % q.size()];
        float pdf = bxdf.pdf(query.wo, query.wi, TransportMode::Radiance);
        benchmark::DoNotOptimize(pdf);
    }
    state.SetItemsProcessed(state.iterations());
}

// Non-specular BxDFs: all three queries.
#define CAUSTICA_BXDF_BENCHMARKS(name)                     \
    BENCHMARK_CAPTURE(BM_BxDFEval, name, #name);           \
    BENCHMARK_CAPTURE(BM_BxDFSample, name, #name);         \
    BENCHMARK_CAPTURE(BM_BxDFPdf, name, #name)

CAUSTICA_BXDF_BENCHMARKS(diffuse);
CAUSTICA_BXDF_BENCHMARKS(dielectric_rough);
CAUSTICA_BXDF_BENCHMARKS(dielectric_rough_dispersive);
CAUSTICA_BXDF_BENCHMARKS(conductor_rough);
CAUSTICA_BXDF_BENCHMARKS(disney_plastic);
CAUSTICA_BXDF_BENCHMARKS(disney_metal);
CAUSTICA_BXDF_BENCHMARKS(disney_glass);
CAUSTICA_BXDF_BENCHMARKS(disney_thin);
CAUSTICA_BXDF_BENCHMARKS(disney_clearcoat_sheen);
BENCHMARK_CAPTURE(BM_BxDFSample, dielectric_smooth, "dielectric_smooth");
BENCHMARK_CAPTURE(BM_BxDFSample, dielectric_smooth_dispersive, "dielectric_smooth_dispersive");
BENCHMARK_CAPTURE(BM_BxDFSample, conductor_smooth, "conductor_smooth");
BENCHMARK_CAPTURE(BM_BxDFSample, thin_dielectric, "thin_dielectric");

} // namespace
} // namespace caustica
