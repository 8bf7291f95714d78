// The iteration loop of the photon-mapping integrators (sppm, bpm, vcm). Unlike camera-only
// rendering, an iteration is a sequence of passes over all pixels that depend on each other
// (trace every light path, build the photon index, then trace every camera path), so the budget
// is counted in whole iterations: `--spp N` means N iterations, as in SmallVCM and pbrt-v4.
//
// A pass visits the film's pixels in tiles over oneTBB. Every pixel's random numbers depend only
// on (pixel, iteration, first sampler dimension, seed), so results do not depend on threads, nor
// on whether the render was resumed from a checkpoint taken between iterations.
//
// A distributed render (RenderShare) shares the work in one of two ways:
//  - whole iterations (bpm, vcm: iterations are independent): rank r renders iterations
//    n + r, n + N + r, ... Nothing is exchanged until the film is reduced at the end;
//  - each iteration's pixels and paths (sppm, whose pixels carry statistics from one iteration
//    to the next): every rank runs every iteration, but its passes visit only its own tiles and
//    light paths; the integrator exchanges what the passes share (the photons).
#pragma once

#include "core/scratch_buffer.h"
#include "integrators/integrator.h"
#include "sampler/sampler.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>

namespace caustica {

class Scene;

// What a pass's work for one pixel may use. sample_scratch is reset after every pixel;
// iteration_scratch lives until the iteration ends (for objects the next pass still reads,
// such as the BSDFs of stored light vertices).
struct IterationPixelContext {
    Sampler &sampler;
    ScratchBuffer &sample_scratch;
    ScratchBuffer &iteration_scratch;
    uint64_t &rays;
    uint64_t &non_finite;
};

// pixel_index numbers the film's pixel bounds row by row from 0.
using IterationPixelFunction = std::function<void(Vec2i pixel, size_t pixel_index, IterationPixelContext &ctx)>;

class IterationRenderer {
  public:
    enum class Sharing { Iterations, PixelsAndPaths };
    IterationRenderer(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                      const ProgressCallback &progress, Sharing sharing = Sharing::Iterations);
    ~IterationRenderer();

    // Calls iteration(i) for i = n, n + 1, ... from the n iterations the stats count as done
    // (0, or those of a resumed render) until the budget's iteration count or time is used up
    // or the render is cancelled; iteration() returns false when it was cancelled part-way.
    // Sharing iterations, each rank is given only its own i.
    // Fills in stats.samples_per_pixel (completed iterations), pixel_samples, seconds and
    // interrupted, and calls the budget's at_boundary after every completed iteration.
    void run(const std::function<bool(int iteration)> &iteration);

    // One parallel pass: work(pixel, index, ctx) for every pixel of the film's bounds (of this
    // rank's tiles, when pixels are shared), with the thread's sampler started at (pixel,
    // iteration, dimension). Returns false if cancelled.
    bool for_each_pixel(int iteration, int dimension, const IterationPixelFunction &work);

    // The same pass over the pixels in the given order of pixel indices (each index once; not
    // with shared pixels): work that reads data kept per group of pixels visits one group's
    // pixels together, while its data stay in cache.
    bool for_each_pixel_in_order(int iteration, int dimension, std::span<const uint32_t> order,
                                 const IterationPixelFunction &work);

    // A parallel pass over path_count paths that belong to no pixel (photons): work(index, ctx),
    // with the sampler started at a pixel and sample index derived from (iteration, index); when
    // paths are shared, only this rank's chunks of them.
    bool for_each_path(int iteration, size_t path_count, int dimension,
                       const std::function<void(size_t index, IterationPixelContext &ctx)> &work);

    size_t pixel_count() const { return pixel_count_; }
    // Whether this rank's passes visit the pixel (every pixel unless pixels are shared).
    bool owns(Vec2i pixel) const;
    const RenderShare &share() const { return share_; }

    // The time within the shutter (geometry/ray.h) of every path of the iteration, camera and
    // light alike, so that connections and merges join paths of one time: the scene's sampler at
    // pixel (0, 0), sample index `iteration`, in the camera's time dimension, so that successive
    // iterations stratify the shutter. 0 when nothing moves.
    float time(int iteration) const;

  private:
    struct ThreadState;
    bool cancelled() const;
    // visit(i, sampler, ctx) for i in [0, count) in parallel chunks (this rank's chunks only, if
    // `shared`), each with the thread's sampler and a fresh sample scratch; false if cancelled.
    template <class Visit> bool for_each_in_chunks(size_t count, bool shared, const Visit &visit);
    double elapsed() const;
    // Adds the threads' counters to the stats and brings their time up to date.
    void flush_counters();

    const Scene &scene_;
    const RenderBudget &budget_;
    RenderStats &stats_;
    const ProgressCallback &progress_;
    const RenderShare &share_;
    const bool share_pixels_;
    size_t pixel_count_, owned_pixel_count_;
    std::chrono::steady_clock::time_point start_;
    double seconds_before_; // of the render this one resumes
    struct Threads;
    std::unique_ptr<Threads> threads_;
};

} // namespace caustica
