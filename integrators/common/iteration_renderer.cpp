#include "integrators/common/iteration_renderer.h"

#include "film/film.h"
#include "scene/scene.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace caustica {

namespace {

constexpr int kTileSize = 16;

struct Tile {
    Vec2i lo, hi;
};

} // namespace

struct IterationRenderer::ThreadState {
    std::unique_ptr<Sampler> sampler;
    std::unique_ptr<ScratchBuffer> sample_scratch = std::make_unique<ScratchBuffer>();
    std::unique_ptr<ScratchBuffer> iteration_scratch = std::make_unique<ScratchBuffer>(1 << 20);
    uint64_t rays = 0, non_finite = 0;
};

struct IterationRenderer::Threads {
    tbb::enumerable_thread_specific<ThreadState> states;
    std::vector<Tile> tiles;
    explicit Threads(const Scene &scene)
        : states([&scene] {
              ThreadState s;
              s.sampler = scene.sampler->clone();
              return s;
          }) {}
};

IterationRenderer::IterationRenderer(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                                     const ProgressCallback &progress, Sharing sharing)
    : scene_(scene), budget_(budget), stats_(stats), progress_(progress), share_(budget.sharing()),
      share_pixels_(sharing == Sharing::PixelsAndPaths && share_.ranks() > 1),
      start_(std::chrono::steady_clock::now()), seconds_before_(stats.seconds),
      threads_(std::make_unique<Threads>(scene)) {
    const PixelBounds &bounds = scene.film->pixel_bounds();
    pixel_count_ = size_t(bounds.width()) * bounds.height();
    owned_pixel_count_ = 0;
    for (int y = bounds.min.y; y < bounds.max.y; ++y)
        for (int x = bounds.min.x; x < bounds.max.x; ++x) owned_pixel_count_ += owns({x, y}) ? 1 : 0;
    for (int y = bounds.min.y; y < bounds.max.y; y += kTileSize)
        for (int x = bounds.min.x; x < bounds.max.x; x += kTileSize)
            threads_->tiles.push_back(
                {{x, y}, {std::min(x + kTileSize, bounds.max.x), std::min(y + kTileSize, bounds.max.y)}});
}

IterationRenderer::~IterationRenderer() { flush_counters(); }

namespace {

// The tile (kTileSize square, row by row over the bounds) a pixel lies in.
size_t tile_of(const PixelBounds &bounds, Vec2i pixel) {
    const size_t tiles_per_row = size_t((bounds.width() + kTileSize - 1) / kTileSize);
    return size_t((pixel.y - bounds.min.y) / kTileSize) * tiles_per_row + size_t((pixel.x - bounds.min.x) / kTileSize);
}

} // namespace

bool IterationRenderer::owns(Vec2i pixel) const {
    return !share_pixels_ || tile_of(scene_.film->pixel_bounds(), pixel) % share_.ranks() == size_t(share_.rank());
}

float IterationRenderer::time(int iteration) const {
    const Shutter *shutter = scene_.motion_shutter();
    if (!shutter) return 0;
    constexpr int kCameraTimeDimension = 5; // sampler.h
    std::unique_ptr<Sampler> sampler = scene_.sampler->clone();
    sampler->start_pixel_sample(Vec2i{0, 0}, iteration, kCameraTimeDimension);
    return shutter->time(sampler->get_1d());
}

void IterationRenderer::flush_counters() {
    for (ThreadState &ts : threads_->states) {
        stats_.rays += std::exchange(ts.rays, 0);
        stats_.non_finite_samples += std::exchange(ts.non_finite, 0);
    }
    stats_.seconds = elapsed();
}

bool IterationRenderer::cancelled() const {
    return budget_.cancel && budget_.cancel->load(std::memory_order_relaxed);
}

double IterationRenderer::elapsed() const {
    return seconds_before_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void IterationRenderer::run(const std::function<bool(int)> &iteration) {
    const bool timed = budget_.seconds > 0;
    const int cap = budget_.spp > 0 ? budget_.spp : (timed ? INT_MAX : 1);
    // Sharing iterations, a round gives each rank one; otherwise a round is one iteration.
    const int per_round = share_pixels_ ? 1 : share_.ranks();
    const int rank_offset = share_pixels_ ? 0 : share_.rank();
    int done = stats_.samples_per_pixel;
    while (done < cap) {
        // With a time limit, a round is only started if it is expected to finish in time (its
        // cost estimated from the iterations so far, on rank 0's clock); the first one always
        // runs.
        if (share_.agree(timed && done > 0 && elapsed() + elapsed() / done * per_round > budget_.seconds)) break;
        const int mine = done + rank_offset;
        const bool completed = mine >= cap || iteration(mine);
        for (ThreadState &ts : threads_->states) ts.iteration_scratch->reset();
        const int completed_in_round = int(share_.sum(completed && mine < cap ? 1 : 0));
        const bool round_complete = !share_.any(!completed);
        // Iterations are counted as done only in whole rounds: an iteration another rank cut short
        // leaves its round unfinished, and its completed ones are in the film but not counted.
        if (!round_complete) {
            stats_.interrupted = true;
            break;
        }
        done += share_pixels_ ? 1 : completed_in_round;
        // This rank's pixel samples (the ranks' are added up when the render ends).
        if (mine < cap) stats_.pixel_samples += share_pixels_ ? owned_pixel_count_ : pixel_count_;
        stats_.samples_per_pixel = done;
        flush_counters();
        if (budget_.at_boundary) budget_.at_boundary();
        if (share_.any(cancelled())) {
            stats_.interrupted = true;
            break;
        }
        if (progress_)
            progress_(timed ? std::min(1.0, elapsed() / budget_.seconds) : double(done) / cap,
                      uint64_t(done) * pixel_count_);
    }
    stats_.samples_per_pixel = done;
    stats_.seconds = elapsed();
}

bool IterationRenderer::for_each_pixel(int iteration, int dimension, const IterationPixelFunction &work) {
    const PixelBounds &bounds = scene_.film->pixel_bounds();
    const size_t width = size_t(bounds.width());
    std::atomic<bool> stopped{false};
    tbb::parallel_for(size_t(0), threads_->tiles.size(), [&](size_t t) {
        if (share_pixels_ && t % share_.ranks() != size_t(share_.rank())) return;
        ThreadState &ts = threads_->states.local();
        IterationPixelContext ctx{*ts.sampler, *ts.sample_scratch, *ts.iteration_scratch, ts.rays,
                                  ts.non_finite};
        const Tile &tile = threads_->tiles[t];
        for (int y = tile.lo.y; y < tile.hi.y; ++y)
            for (int x = tile.lo.x; x < tile.hi.x; ++x) {
                // Checked per pixel, so an interruption is honoured within one path's time.
                if (cancelled()) {
                    stopped = true;
                    return;
                }
                Vec2i pixel{x, y};
                ts.sampler->start_pixel_sample(pixel, iteration, dimension);
                work(pixel, size_t(y - bounds.min.y) * width + size_t(x - bounds.min.x), ctx);
                ts.sample_scratch->reset();
            }
    });
    return !stopped;
}

template <class Visit> bool IterationRenderer::for_each_in_chunks(size_t count, bool shared, const Visit &visit) {
    constexpr size_t kChunk = 256;
    std::atomic<bool> stopped{false};
    tbb::parallel_for(size_t(0), (count + kChunk - 1) / kChunk, [&](size_t chunk) {
        if (shared && chunk % share_.ranks() != size_t(share_.rank())) return;
        ThreadState &ts = threads_->states.local();
        IterationPixelContext ctx{*ts.sampler, *ts.sample_scratch, *ts.iteration_scratch, ts.rays,
                                  ts.non_finite};
        for (size_t i = chunk * kChunk; i < std::min(count, (chunk + 1) * kChunk); ++i) {
            if (cancelled()) {
                stopped = true;
                return;
            }
            visit(i, *ts.sampler, ctx);
            ts.sample_scratch->reset();
        }
    });
    return !stopped;
}

bool IterationRenderer::for_each_pixel_in_order(int iteration, int dimension, std::span<const uint32_t> order,
                                                const IterationPixelFunction &work) {
    if (share_pixels_) throw std::logic_error("IterationRenderer: an ordered pass with shared pixels");
    const PixelBounds &bounds = scene_.film->pixel_bounds();
    const size_t width = size_t(bounds.width());
    return for_each_in_chunks(order.size(), false, [&](size_t i, Sampler &sampler, IterationPixelContext &ctx) {
        const size_t index = order[i];
        const Vec2i pixel{bounds.min.x + int(index % width), bounds.min.y + int(index / width)};
        sampler.start_pixel_sample(pixel, iteration, dimension);
        work(pixel, index, ctx);
    });
}

bool IterationRenderer::for_each_path(int iteration, size_t path_count, int dimension,
                                      const std::function<void(size_t, IterationPixelContext &)> &work) {
    // Path i uses the sample stream of pixel i mod P (P pixels) at sample index
    // iteration * rounds + i / P: every path of every iteration gets its own stream.
    const PixelBounds &bounds = scene_.film->pixel_bounds();
    const size_t width = size_t(bounds.width());
    const size_t rounds = (path_count + pixel_count_ - 1) / pixel_count_;
    return for_each_in_chunks(path_count, share_pixels_, [&](size_t i, Sampler &sampler, IterationPixelContext &ctx) {
        const size_t p = i % pixel_count_;
        const Vec2i pixel{bounds.min.x + int(p % width), bounds.min.y + int(p / width)};
        sampler.start_pixel_sample(pixel, int(size_t(iteration) * rounds + i / pixel_count_), dimension);
        work(i, ctx);
    });
}

} // namespace caustica
