#include "film/splat_buffer.h"

#include <algorithm>
#include <cmath>

namespace caustica {

namespace {

// The pixels whose centres lie within the filter's radius r of p: [lo, hi) on one axis.
std::pair<int, int> footprint(float p, float r, int min, int max) {
    const float discrete = p + 0.5f;
    return {std::max(min, int(std::floor(discrete - r))), std::min(max, int(std::floor(discrete + r)) + 1)};
}

} // namespace

SplatBuffer::SplatBuffer(Vec2i bounds_min, Vec2i bounds_max, const Filter &filter, int channels)
    : min_(bounds_min), max_(bounds_max), filter_(&filter), channels_(channels),
      rows_per_band_(std::max(kMinRowsPerBand, (bounds_max.y - bounds_min.y + kBands - 1) / kBands)) {}

void SplatBuffer::allocate_sums() {
    std::call_once(sums_allocated_, [this] {
        if (sums_.empty()) sums_.assign(size_t(max_.x - min_.x) * (max_.y - min_.y) * channels_, 0);
    });
}

void SplatBuffer::add(Vec2f p, RGB v) {
    SplatValues values;
    for (int c = 0; c < 3; ++c) values.add(c, v[c]);
    add(p, values);
}

void SplatBuffer::add(Vec2f p, const SplatValues &v) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    const Vec2f r = filter_->radius();
    const auto [x0, x1] = footprint(p.x, r.x, min_.x, max_.x);
    const auto [y0, y1] = footprint(p.y, r.y, min_.y, max_.y);
    if (x0 >= x1 || y0 >= y1) return;
    allocate_sums();
    Queues &queues = queues_.local();
    for (int band = band_of_row(y0); band <= band_of_row(y1 - 1); ++band) {
        std::vector<Pending> &queue = queues[band];
        if (queue.capacity() == 0) queue.reserve(kQueueCapacity);
        queue.push_back({p, v});
        if (queue.size() == kQueueCapacity) {
            std::lock_guard lock(band_locks_[band]);
            apply(band, queue);
        }
    }
}

// Adds a band's queued splats to the sums, each clipped to the band's rows; the caller holds the
// band's lock (or no thread is adding).
void SplatBuffer::apply(int band, std::vector<Pending> &queue) {
    const int band_y0 = min_.y + band * rows_per_band_, band_y1 = std::min(max_.y, band_y0 + rows_per_band_);
    const Vec2f r = filter_->radius();
    const size_t width = size_t(max_.x - min_.x);
    // The filter is separable: one weight per column and one per row (at most 2 r + 2 each).
    constexpr int MaxFootprint = 2 * int(MaxFilterRadius) + 2;
    float weight_x[MaxFootprint], weight_y[MaxFootprint];
    bool overflow = false;
    for (const Pending &s : queue) {
        const auto [x0, x1] = footprint(s.p.x, r.x, min_.x, max_.x);
        auto [y0, y1] = footprint(s.p.y, r.y, min_.y, max_.y);
        y0 = std::max(y0, band_y0);
        y1 = std::min(y1, band_y1);
        for (int x = x0; x < x1; ++x) weight_x[x - x0] = filter_->evaluate_x(s.p.x - x - 0.5f);
        for (int y = y0; y < y1; ++y) weight_y[y - y0] = filter_->evaluate_y(s.p.y - y - 0.5f);
        for (int y = y0; y < y1; ++y) {
            if (weight_y[y - y0] == 0) continue;
            int64_t *row = &sums_[(size_t(y - min_.y) * width) * channels_];
            for (int x = x0; x < x1; ++x) {
                const float w = weight_x[x - x0] * weight_y[y - y0];
                if (w == 0) continue;
                int64_t *sum = &row[size_t(x - min_.x) * channels_];
                for (int i = 0; i < s.v.count; ++i)
                    if (!fixed_point::add(sum[s.v.channel[i]], double(w) * double(s.v.value[i]))) overflow = true;
            }
        }
    }
    queue.clear();
    if (overflow) overflow_ = true;
}

void SplatBuffer::flush() {
    for (Queues &queues : queues_)
        for (int band = 0; band < kBands; ++band)
            if (!queues[band].empty()) apply(band, queues[band]);
}

void SplatBuffer::restore(std::vector<int64_t> sums) {
    queues_.clear();
    if (sums.empty() && !sums_.empty()) sums.assign(sums_.size(), 0);
    sums_ = std::move(sums);
}

} // namespace caustica
