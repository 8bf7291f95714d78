#include "spatial/hash_grid.h"

#include <algorithm>
#include <cassert>

namespace caustica {

namespace {

// Cell coordinates are packed into 21 bits each for hashing. Capping the grid at 2^20 cells per
// axis (by enlarging cells when max_radius is tiny against the scene) keeps them in range and
// keeps cell coordinates small enough for double arithmetic to place query bounds within a
// billionth of a cell, which is what bounds a query to 3 cells per axis (see
// overlapping_buckets).
constexpr double MaxCellsPerAxis = 1 << 20;

} // namespace

uint32_t HashGrid::bucket_of(const CellCoords &cell) const {
    // The packed key is unique per cell and mix_bits is a bijection, so distinct cells only share
    // a bucket through the final reduction. That maps the top 32 hash bits to [0, bucket count)
    // by multiply-shift (Lemire 2019, "Fast random integer generation in an interval"): each
    // bucket receives the floor or the ceiling of 2^32 / bucket count hash values, without a
    // division.
    uint64_t key = uint64_t(cell[0]) | uint64_t(cell[1]) << 21 | uint64_t(cell[2]) << 42;
    uint64_t hash = mix_bits(key) >> 32;
    return uint32_t((hash * bucket_count()) >> 32);
}

void HashGrid::set_cells(const Bounds3f &bounds, size_t point_count, float max_radius) {
    bounds_ = bounds;
    max_radius_ = max_radius;
    bucket_starts_.assign(point_count == 0 ? 0 : std::max<size_t>(1, point_count / 4) + 1, 0);
    if (point_count == 0) return;
    double extent = max_component(bounds_.diagonal());
    double cell_size = std::max(2.0 * max_radius, extent / MaxCellsPerAxis);
    // Radius 0 with all points identical: any cell size puts them in one cell.
    if (!(cell_size > 0)) cell_size = 1;
    inverse_cell_size_ = 1 / cell_size;
    for (int axis = 0; axis < 3; ++axis) max_cell_[axis] = cell_coordinate(bounds_.hi[axis], axis);
}

int HashGrid::overlapping_buckets(Vec3f center, float radius, std::array<uint32_t, 27> &buckets) const {
    if (bucket_starts_.empty()) return 0;
    // A point passes the caller's float test (squared distance below radius^2) only if
    // |p - center| < radius exactly on each axis (rounding is monotone and radius is a float), so
    // p lies in [lo, hi] even after lo and hi are rounded, and monotone cell_coordinate puts it
    // in the cell range [lo_cell, hi_cell]. The range spans hi - lo <= 2 radius <= one cell plus
    // rounding, hence at most 3 cells per axis (2 unless lo falls within rounding of a cell
    // boundary).
    CellCoords lo_cell, hi_cell;
    for (int axis = 0; axis < 3; ++axis) {
        double lo = double(center[axis]) - radius, hi = double(center[axis]) + radius;
        // Outside the points' bounds there is nothing to find; returning here also keeps far
        // away queries from producing huge cell coordinates.
        if (lo > bounds_.hi[axis] || hi < bounds_.lo[axis]) return 0;
        lo_cell[axis] = std::max<int64_t>(0, cell_coordinate(lo, axis));
        hi_cell[axis] = std::min(max_cell_[axis], cell_coordinate(hi, axis));
        assert(hi_cell[axis] - lo_cell[axis] <= 2);
    }
    // Two cells of the range may hash to the same bucket; listing it once avoids duplicates.
    int count = 0;
    CellCoords cell;
    for (cell[2] = lo_cell[2]; cell[2] <= hi_cell[2]; ++cell[2])
        for (cell[1] = lo_cell[1]; cell[1] <= hi_cell[1]; ++cell[1])
            for (cell[0] = lo_cell[0]; cell[0] <= hi_cell[0]; ++cell[0]) {
                const uint32_t bucket = bucket_of(cell);
                if (std::find(buckets.begin(), buckets.begin() + count, bucket) == buckets.begin() + count)
                    buckets[count++] = bucket;
            }
    return count;
}

} // namespace caustica
