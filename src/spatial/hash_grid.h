// Hashed uniform grid for fixed-radius queries (Georgiev et al. 2012, "Light transport simulation
// with vertex connection and merging", section 6).
//
// Cells are cubes of side 2 * max_radius, so a query ball of radius r <= max_radius, whose
// extent along each axis is at most one cell, overlaps at most 2x2x2 cells. (Cells of side
// max_radius would be smaller but a query would then visit up to 3x3x3 = 27 cells instead of 8;
// the larger cells trade a few more distance tests for far fewer cell lookups.) Only occupied
// cells matter, so integer cell coordinates are hashed into a table of buckets.
//
// The grid does not copy the points: build() sorts the caller's items (photons with their
// records) into bucket order in place, so that a query reads each bucket's items sequentially
// and the grid itself holds only its bucket table. That table has one bucket for every four
// points (4 bytes each, so 1 byte a point). Occupied cells are far fewer than points where
// photons are dense enough to matter, as a cell holds tens of them, so collisions stay rare:
// twice as many buckets queried no faster on bench/photon_map_bench.cpp's data (878 and 2889 ns
// at 10^5 and 10^6 photons, against 921 and 2719). Where photons are sparse, a query tests the
// few photons of up to four cells per bucket.
//
// Measured on bench/photon_map_bench.cpp's data (1M photons, ~30 neighbours per query): cells of
// side max_radius made queries 1.5x slower, and reading the points through an index array
// instead of in bucket order made them 2x slower.
#pragma once

#include "core/rng.h"
#include "core/vecmath.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace caustica {

class HashGrid {
  public:
    // Reorders [first, last) in place so that the items of each bucket are contiguous and ordered
    // by `less` among themselves, and indexes them for queries of radius at most max_radius.
    // position(item) is the item's point (finite). The order within a bucket depends only on the
    // set of items and `less`, not on the order they came in, if `less` is a total order.
    template <class Iterator, class Position, class Less>
    void build(Iterator first, Iterator last, float max_radius, Position position, Less less);

    // The index ranges [begin, end), into the built sequence, of the non-empty buckets that may
    // hold an item within radius of center, at most 27: every such item is in one of the ranges
    // (items outside the ball are too: the caller tests distances), and no range is listed twice.
    // Returns their number. Requires 0 <= radius <= max_radius (std::invalid_argument otherwise).
    struct Range {
        uint32_t begin, end;
    };
    int candidate_ranges(Vec3f center, float radius, std::array<Range, 27> &ranges) const;

    // The bucket table's bytes.
    size_t memory_bytes() const { return bucket_starts_.size() * sizeof(uint32_t); }

  private:
    using CellCoords = std::array<int64_t, 3>;
    // Fixes the cells for points within bounds and sizes the bucket table (all zero).
    void set_cells(const Bounds3f &bounds, size_t point_count, float max_radius);
    // Cell index of coordinate x along an axis, unclamped. Evaluated in double and monotone in x,
    // which is what makes queries exact (see overlapping_buckets).
    int64_t cell_coordinate(double x, int axis) const {
        // floor(), without the library call it compiles to on baseline x86-64 (the sort
        // evaluates this several times for every point).
        const double v = (x - bounds_.lo[axis]) * inverse_cell_size_;
        const int64_t truncated = int64_t(v);
        return truncated - int64_t(v < double(truncated));
    }
    uint32_t bucket_of(const CellCoords &cell) const;
    uint32_t bucket_of(Vec3f p) const {
        return bucket_of(CellCoords{cell_coordinate(p.x, 0), cell_coordinate(p.y, 1), cell_coordinate(p.z, 2)});
    }
    uint32_t bucket_count() const { return uint32_t(bucket_starts_.size() - 1); }
    // The distinct buckets of the cells a query ball overlaps, at most 27; 0 if it misses the
    // points' bounds.
    int overlapping_buckets(Vec3f center, float radius, std::array<uint32_t, 27> &buckets) const;

    Bounds3f bounds_;
    float max_radius_ = 0;
    double inverse_cell_size_ = 1;
    CellCoords max_cell_{};
    // Bucket b holds the items [bucket_starts_[b], bucket_starts_[b + 1]); one entry more than
    // there are buckets (none before the first build).
    std::vector<uint32_t> bucket_starts_;
};

// Sorts the n items at first in place by key(item), in [0, key_count), and sets starts[k] to
// where key k's items begin (American flag sort: McIlroy, Bostic and McIlroy 1993, "Engineering
// radix sort"). Each key's next free slot advances through its range: an item taken from there,
// if it belongs elsewhere, is swapped into its own key's next slot, and the item found there
// goes on in its place until one of the key being filled turns up.
namespace hash_grid_detail {
template <class Iterator, class Key>
void sort_by_key(Iterator first, uint32_t n, uint32_t key_count, Key key, uint32_t *starts) {
    std::fill(starts, starts + key_count, 0u);
    for (uint32_t i = 0; i < n; ++i) ++starts[key(first[i])];
    uint32_t start = 0;
    for (uint32_t k = 0; k < key_count; ++k) start += std::exchange(starts[k], start);
    std::vector<uint32_t> next(starts, starts + key_count);
    for (uint32_t k = 0; k < key_count; ++k) {
        const uint32_t end = k + 1 < key_count ? starts[k + 1] : n;
        while (next[k] < end) {
            typename std::iterator_traits<Iterator>::value_type held = first[next[k]];
            for (uint32_t other = key(held); other != k; other = key(held)) std::swap(held, first[next[other]++]);
            first[next[k]++] = held;
        }
    }
}
} // namespace hash_grid_detail

template <class Iterator, class Position, class Less>
void HashGrid::build(Iterator first, Iterator last, float max_radius, Position position, Less less) {
    const size_t n = size_t(last - first);
    if (n >= std::numeric_limits<uint32_t>::max()) throw std::invalid_argument("HashGrid: more than 2^32 - 1 points");
    if (!(max_radius >= 0)) throw std::invalid_argument("HashGrid: negative max_radius");
    Bounds3f bounds;
    for (Iterator it = first; it != last; ++it) bounds.expand(position(*it));
    set_cells(bounds, n, max_radius);
    if (n == 0) return;

    // Sorted by bucket in two passes. The moves of one pass over all buckets at once would land
    // at random places in memory, each waiting for the one before it (a million photons took
    // 0.4 s). So the first pass sorts by the top bits of the bucket index into at most 256
    // ranges of consecutive buckets, whose 256 insertion points stay in cache. The second then
    // sorts each range, small enough to stay in cache, by bucket, ranges in parallel.
    const uint32_t buckets = bucket_count();
    int shift = 0;
    while (((buckets - 1) >> shift) >= 256) ++shift;
    const uint32_t range_count = ((buckets - 1) >> shift) + 1;
    std::vector<uint32_t> range_starts(range_count + 1, uint32_t(n));
    hash_grid_detail::sort_by_key(first, uint32_t(n), range_count, [&](const auto &item) { return bucket_of(position(item)) >> shift; },
                range_starts.data());
    tbb::parallel_for(uint32_t(0), range_count, [&](uint32_t range) {
        const uint32_t begin = range_starts[range], count = range_starts[range + 1] - begin;
        const uint32_t first_bucket = range << shift, last_bucket = std::min(buckets, (range + 1) << shift);
        uint32_t *starts = &bucket_starts_[first_bucket];
        hash_grid_detail::sort_by_key(first + begin, count, last_bucket - first_bucket,
                    [&](const auto &item) { return bucket_of(position(item)) - first_bucket; }, starts);
        for (uint32_t b = first_bucket; b < last_bucket; ++b) bucket_starts_[b] += begin;
        for (uint32_t b = first_bucket; b < last_bucket; ++b) {
            const uint32_t end = b + 1 < last_bucket ? bucket_starts_[b + 1] : begin + count;
            std::sort(first + bucket_starts_[b], first + end, less);
        }
    });
    bucket_starts_.back() = uint32_t(n);
}

inline int HashGrid::candidate_ranges(Vec3f center, float radius, std::array<Range, 27> &ranges) const {
    if (!(radius >= 0 && radius <= max_radius_))
        throw std::invalid_argument("HashGrid: query radius outside [0, max_radius]");
    std::array<uint32_t, 27> buckets;
    const int count = overlapping_buckets(center, radius, buckets);
    // The buckets lie at unrelated places in a table too large for the cache: ask for all of
    // them before reading any, so that their misses overlap instead of following one another.
    for (int i = 0; i < count; ++i) __builtin_prefetch(&bucket_starts_[buckets[i]]);
    int ranges_count = 0;
    for (int i = 0; i < count; ++i) {
        const uint32_t begin = bucket_starts_[buckets[i]], end = bucket_starts_[buckets[i] + 1];
        if (begin < end) ranges[ranges_count++] = Range{begin, end};
    }
    return ranges_count;
}

} // namespace caustica
