#include "integrators/common/tile_renderer.h"

#include "camera/camera.h"
#include "film/film.h"
#include "scene/scene.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <utility>
#include <vector>

namespace caustica {

SampledWavelengths sample_wavelengths(const Scene &scene, float u, WavelengthsFor use) {
    if (scene.overrides.wavelength > 0) return SampledWavelengths::fixed(scene.overrides.wavelength);
    if (scene.achromatic_wavelength > 0) return SampledWavelengths::fixed(scene.achromatic_wavelength);
    if (const SpectralBuckets *buckets = scene.film->spectral()) {
        // pbrt-v4's spectral film samples its own range uniformly, so every bucket gets samples.
        SampledWavelengths lambda = SampledWavelengths::sample_uniform(u, buckets->lambda_min(), buckets->lambda_max());
        if (scene.overrides.single_wavelength) lambda.terminate_secondary();
        return lambda;
    }
    const std::optional<WavelengthDensity> &density =
        use == WavelengthsFor::LightPath && scene.light_path_wavelength_density ? scene.light_path_wavelength_density
                                                                                : scene.wavelength_density;
    if (density)
        return scene.overrides.single_wavelength ? SampledWavelengths::sample_single(*density, u)
                                                 : SampledWavelengths::sample(*density, u);
    if (scene.overrides.single_wavelength) return SampledWavelengths::sample_single(u);
    return SampledWavelengths::sample_visible(u);
}

namespace {

constexpr int kTileSize = 16;

struct Tile {
    Vec2i lo, hi;
};

struct ThreadState {
    std::unique_ptr<Sampler> sampler;
    std::unique_ptr<ScratchBuffer> scratch = std::make_unique<ScratchBuffer>();
    uint64_t rays = 0;
    uint64_t non_finite = 0;
    uint64_t pixel_samples = 0;
};

std::vector<Tile> make_tiles(const PixelBounds &bounds) {
    std::vector<Tile> tiles;
    for (int y = bounds.min.y; y < bounds.max.y; y += kTileSize)
        for (int x = bounds.min.x; x < bounds.max.x; x += kTileSize)
            tiles.push_back({{x, y}, {std::min(x + kTileSize, bounds.max.x), std::min(y + kTileSize, bounds.max.y)}});
    return tiles;
}

} // namespace

void for_each_pixel_sample(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                           const ProgressCallback &progress, const PixelSampleFunction &work) {
    const Film &film = *scene.film;
    const PixelBounds &bounds = film.pixel_bounds();
    const std::vector<Tile> tiles = make_tiles(bounds);
    const uint64_t pixel_count = uint64_t(bounds.width()) * bounds.height();
    const bool timed = budget.seconds > 0;
    const int spp_cap = budget.spp > 0 ? budget.spp : (timed ? INT_MAX : 1);
    const auto start = std::chrono::steady_clock::now();
    const double seconds_before = stats.seconds; // of the render this one resumes
    auto elapsed = [&] {
        return seconds_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };

    // The samples each pixel has taken. A pixel's value only depends on its own samples, and the
    // film sums in order-independent fixed point, so the sweeps below may be cut anywhere: a
    // render resumed from per-pixel counts (an interrupted sweep) gives the same image as one
    // that was never stopped.
    std::vector<int> taken = std::move(stats.pixel_sample_counts);
    stats.pixel_sample_counts.clear();
    if (taken.size() != pixel_count) taken.assign(pixel_count, stats.samples_per_pixel);

    tbb::enumerable_thread_specific<ThreadState> states([&] {
        ThreadState s;
        s.sampler = scene.sampler->clone();
        return s;
    });
    // Brings the stats up to date (for RenderBudget::at_boundary and at the end).
    auto flush_counters = [&] {
        for (ThreadState &ts : states) {
            stats.rays += std::exchange(ts.rays, 0);
            stats.non_finite_samples += std::exchange(ts.non_finite, 0);
            stats.pixel_samples += std::exchange(ts.pixel_samples, 0);
        }
        stats.seconds = elapsed();
    };

    auto cancelled = [&] { return budget.cancel && budget.cancel->load(std::memory_order_relaxed); };
    // A distributed render deals each wave's (tile, sample index) pairs out to the ranks in turn,
    // so that even a one-sample wave is shared; rank 0's clock decides the waves' sizes.
    const RenderShare &share = budget.sharing();
    const int rank = share.rank(), ranks = share.ranks();
    std::atomic<uint64_t> tiles_done{0};
    int done = stats.samples_per_pixel;
    while (done < spp_cap && !share.agree(timed && elapsed() >= budget.seconds)) {
        // Sweeps over the image in waves of doubling size (1, 1, 2, 4, ... 64 samples per
        // pixel), so that an interrupted render holds the whole image at a lower sample count;
        // a time budget sizes its waves from the measured cost per sample instead, so the
        // deadline is not overshot.
        int wave = std::min({spp_cap - done, std::max(done, 1), 64});
        if (timed) {
            double per_spp = done > 0 ? elapsed() / done : 0;
            double remaining = budget.seconds - elapsed();
            wave = done == 0 ? 1 : int(std::clamp(remaining / std::max(per_spp, 1e-9), 1.0, 64.0));
            wave = std::min(wave, spp_cap - done);
        }
        wave = int(share.agree(wave));
        const int first = done, end = done + wave;
        tiles_done = 0;
        tbb::parallel_for(size_t(0), tiles.size(), [&](size_t t) {
            ThreadState &ts = states.local();
            PixelSampleContext ctx{*ts.sampler, *ts.scratch, ts.rays, ts.non_finite};
            const Tile &tile = tiles[t];
            for (int y = tile.lo.y; y < tile.hi.y; ++y)
                for (int x = tile.lo.x; x < tile.hi.x; ++x) {
                    Vec2i pixel{x, y};
                    int &pixel_taken = taken[size_t(y - bounds.min.y) * bounds.width() + (x - bounds.min.x)];
                    for (int s = std::max(first, pixel_taken); s < end; ++s) {
                        if (ranks > 1 && (uint64_t(s - first) * tiles.size() + t) % ranks != uint64_t(rank)) {
                            pixel_taken = s + 1; // another rank's
                            continue;
                        }
                        // Checked per sample so an interruption is honoured within one sample's
                        // time; the film normalises each pixel by its own weight, so pixels with
                        // fewer samples are still correct.
                        if (cancelled()) return;
                        ts.sampler->start_pixel_sample(pixel, s);
                        work(pixel, s, ctx);
                        ts.scratch->reset();
                        ++ts.pixel_samples;
                        pixel_taken = s + 1;
                    }
                }
            uint64_t n = ++tiles_done;
            if (progress)
                progress(timed ? std::min(1.0, elapsed() / budget.seconds)
                               : (double(first) + double(wave) * n / tiles.size()) / spp_cap,
                         uint64_t(double(pixel_count) * (first + double(wave) * n / tiles.size())));
        });
        // Cancellation is only checked before a sample, so a wave may be complete even when
        // the render was cancelled.
        const bool stopped = share.any(cancelled());
        const bool complete =
            !share.any(stopped && !std::all_of(taken.begin(), taken.end(), [end](int n) { return n >= end; }));
        if (complete) done = end;
        flush_counters();
        stats.samples_per_pixel = done;
        if (stopped) {
            stats.interrupted = true;
            if (!complete && ranks == 1) stats.pixel_sample_counts = taken;
            // The ranks' shares of a wave cut short are not each pixel's first samples: their
            // state cannot be continued, so it is not offered for a checkpoint.
            if (budget.at_boundary && (complete || ranks == 1)) budget.at_boundary();
            break;
        }
        if (budget.at_boundary) budget.at_boundary();
    }
    flush_counters();
    stats.samples_per_pixel = done;
}

void render_tiles(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                  const ProgressCallback &progress, const RadianceFunction &radiance) {
    Film &film = *scene.film;
    for_each_pixel_sample(scene, budget, stats, progress, [&](Vec2i pixel, int, PixelSampleContext &ctx) {
        Sampler &sampler = ctx.sampler;
        SampledWavelengths lambda = sample_wavelengths(scene, sampler.get_1d());
        CameraSample cs = get_camera_sample(sampler, pixel, film.filter(), scene.motion_shutter());
        SampledSpectrum L;
        if (auto ray = scene.generate_camera_ray(cs, lambda, sampler.samples_per_pixel())) {
            L = radiance(*ray, lambda, sampler, ctx.scratch, ctx.rays) * ray->weight;
            // A non-finite value is a bug to fix at its source; it is counted (reported in the
            // stats) and never reaches the film.
            if (L.has_non_finite()) {
                ++ctx.non_finite;
                L = SampledSpectrum(0.f);
            }
        }
        film.add_sample(pixel, L, lambda, cs.filter_weight);
    });
}

} // namespace caustica
