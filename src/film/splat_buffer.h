// The film's store of light-tracing contributions ("splats"): values that land anywhere on the
// image, from any thread, each spread over the pixels within the filter's radius.
//
// Exact and order-independent: the sums are kept in 64-bit fixed point (fixed_point.h), so the
// image is bit-identical whatever order the splats arrive in, and so for any number of threads
// or processes. Exceeding the range is detected (overflowed()).
//
// Each pixel has a fixed number of channels (3 for RGB, or a spectral film's buckets), and a
// splat adds up to four values, each to one channel: an RGB value, or a spectral sample's four
// wavelengths, each to its bucket.
//
// Memory that does not grow with the thread count: one shared full-frame sum (8 bytes per
// pixel and channel), and per thread only a queue of pending splats per horizontal band of the image (at
// most kBands x kQueueCapacity records). A splat is queued in every band its footprint touches;
// when a thread's queue for a band is full, the thread locks that band and adds the queued
// splats, clipped to the band's rows, with plain integer adds. The alternatives cost more: a
// full-frame sum per thread is 200 MB per thread at 3840x2160, and atomic adds into the shared
// sum (three per pixel of each footprint) made the light tracer 1.2 (one thread) to 1.4 (two
// threads) times slower. Applying a band's queue at once also keeps the adds within a few rows.
#pragma once

#include "core/vecmath.h"
#include "film/filter.h"
#include "film/fixed_point.h"
#include "spectral/color.h"

#include <tbb/enumerable_thread_specific.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace caustica {

// What one splat adds to each pixel it reaches, before the filter weight: up to four values,
// each to one channel.
struct SplatValues {
    std::array<float, 4> value{};
    std::array<uint16_t, 4> channel{};
    int count = 0;

    void add(int c, float v) {
        value[count] = v;
        channel[count] = uint16_t(c);
        ++count;
    }
};

class SplatBuffer {
  public:
    // bounds: the pixels stored (the film's pixel bounds, not empty); filter: the film's, which
    // must outlive the buffer; channels: per pixel (at most 65536).
    SplatBuffer(Vec2i bounds_min, Vec2i bounds_max, const Filter &filter, int channels = 3);

    // Queues v at raster position p (thread-safe): an RGB value goes to channels 0, 1 and 2.
    void add(Vec2f p, RGB v);
    void add(Vec2f p, const SplatValues &v);
    // Adds every thread's queued splats to the sums. Call it while no thread is adding.
    void flush();

    // After flush(): the sums, channels() per pixel in raster order over the bounds, in fixed
    // point, or empty if nothing was ever splatted.
    const std::vector<int64_t> &sums() const { return sums_; }
    int channels() const { return channels_; }
    // Replaces the sums (a checkpoint's; empty or channels() per pixel) and drops what is queued.
    void restore(std::vector<int64_t> sums);
    // After flush(), the sums to change in place (a distributed render's reduction), allocated
    // first if `allocate`. Call it while no thread is adding.
    std::vector<int64_t> &sums(bool allocate) {
        if (allocate) allocate_sums();
        return sums_;
    }

    // Whether a sum left the fixed-point range since the flag was last taken; take_overflow()
    // also clears it.
    bool overflowed() const { return overflow_.load(); }
    bool take_overflow() { return overflow_.exchange(false); }
    void set_overflow(bool overflow) { overflow_ = overflow; }

  private:
    struct Pending {
        Vec2f p;
        SplatValues v;
    };
    static constexpr int kBands = 64;
    // A splat that straddles two bands is queued, and its filter weights computed, in each. Bands
    // of at least 32 rows keep that to about a tenth of the splats of a 1.5-pixel filter (a third
    // with the 8-row bands of a 512-row image split 64 ways).
    static constexpr int kMinRowsPerBand = 32;
    static constexpr size_t kQueueCapacity = 1024;
    using Queues = std::array<std::vector<Pending>, kBands>;

    int band_of_row(int y) const { return (y - min_.y) / rows_per_band_; }
    void apply(int band, std::vector<Pending> &queue);
    void allocate_sums();

    Vec2i min_, max_;
    const Filter *filter_;
    int channels_;
    int rows_per_band_;
    std::vector<int64_t> sums_;
    std::once_flag sums_allocated_;
    std::array<std::mutex, kBands> band_locks_;
    tbb::enumerable_thread_specific<Queues> queues_;
    std::atomic<bool> overflow_{false};
};

} // namespace caustica
