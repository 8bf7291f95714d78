#include "spatial/hash_grid.h"

#include "core/rng.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace caustica {

namespace {

// Cell coordinates are packed into 21 bits each for hashing. Capping the grid at 2^20 cells per
// axis (by enlarging cells when max_radius is tiny against the scene) keeps them in range and
// keeps cell coordinates small enough for double arithmetic to place query bounds within a
// billionth of a cell, which is what bounds a query to 3 cells per axis (see find_within).
constexpr double MaxCellsPerAxis = 1 << 20;

} // namespace

int64_t HashGrid::cell_coordinate(double x, int axis) const {
    return int64_t(std::floor((x - bounds_.lo[axis]) * inverse_cell_size_));
}

uint32_t HashGrid::bucket_of(const CellCoords &cell) const {
    // The packed key is unique per cell and mix_bits is a bijection, so distinct cells only share
    // a bucket through the final reduction. That maps the top 32 hash bits to [0, bucket count)
    // by multiply-shift (Lemire 2019, "Fast random integer generation in an interval"): each
    // bucket receives the floor or the ceiling of 2^32 / bucket count hash values, without a
    // division.
    uint64_t key = uint64_t(cell[0]) | uint64_t(cell[1]) << 21 | uint64_t(cell[2]) << 42;
    uint64_t hash = mix_bits(key) >> 32;
    return uint32_t((hash * bucket_ends_.size()) >> 32);
}

void HashGrid::build(std::span<const Vec3f> points, float max_radius) {
    if (points.size() >= std::numeric_limits<uint32_t>::max())
        throw std::invalid_argument("HashGrid: more than 2^32 - 1 points");
    if (!(max_radius >= 0)) throw std::invalid_argument("HashGrid: negative max_radius");
    size_t n = points.size();
    max_radius_ = max_radius;
    bounds_ = Bounds3f{};
    for (Vec3f p : points) bounds_.expand(p);
    // As many buckets as points, as in the paper: occupied cells are at most that many, so the
    // table stays sparse enough for collisions to be rare.
    bucket_ends_.assign(n, 0);
    sorted_points_.resize(n);
    sorted_indices_.resize(n);
    if (n == 0) return;

    double extent = max_component(bounds_.diagonal());
    double cell_size = std::max(2.0 * max_radius, extent / MaxCellsPerAxis);
    // Radius 0 with all points identical: any cell size puts them in one cell.
    if (!(cell_size > 0)) cell_size = 1;
    inverse_cell_size_ = 1 / cell_size;
    for (int axis = 0; axis < 3; ++axis) max_cell_[axis] = cell_coordinate(bounds_.hi[axis], axis);

    // Counting sort by bucket: count, turn counts into bucket starts, then place each point at
    // its bucket's cursor. Each cursor ends one past its bucket's last point, i.e. at its end.
    std::vector<uint32_t> point_bucket(n);
    for (size_t i = 0; i < n; ++i) {
        CellCoords cell;
        for (int axis = 0; axis < 3; ++axis) cell[axis] = cell_coordinate(points[i][axis], axis);
        point_bucket[i] = bucket_of(cell);
        ++bucket_ends_[point_bucket[i]];
    }
    uint32_t start = 0;
    for (uint32_t &end : bucket_ends_) {
        uint32_t count = end;
        end = start;
        start += count;
    }
    for (size_t i = 0; i < n; ++i) {
        uint32_t slot = bucket_ends_[point_bucket[i]]++;
        sorted_points_[slot] = points[i];
        sorted_indices_[slot] = uint32_t(i);
    }
}

void HashGrid::find_within(Vec3f center, float radius, std::vector<uint32_t> &indices) const {
    if (!(radius >= 0 && radius <= max_radius_))
        throw std::invalid_argument("HashGrid: query radius outside [0, max_radius]");
    indices.clear();
    if (sorted_points_.empty()) return;

    // A point passes the float test below only if |p - center| < radius exactly on each axis
    // (rounding is monotone and radius is a float), so p lies in [lo, hi] even after lo and hi
    // are rounded, and monotone cell_coordinate puts it in the cell range [lo_cell, hi_cell].
    // The range spans hi - lo <= 2 radius <= one cell plus rounding, hence at most 3 cells per
    // axis (2 unless lo falls within rounding of a cell boundary).
    CellCoords lo_cell, hi_cell;
    for (int axis = 0; axis < 3; ++axis) {
        double lo = double(center[axis]) - radius, hi = double(center[axis]) + radius;
        // Outside the points' bounds there is nothing to find; returning here also keeps far
        // away queries from producing huge cell coordinates.
        if (lo > bounds_.hi[axis] || hi < bounds_.lo[axis]) return;
        lo_cell[axis] = std::max<int64_t>(0, cell_coordinate(lo, axis));
        hi_cell[axis] = std::min(max_cell_[axis], cell_coordinate(hi, axis));
        assert(hi_cell[axis] - lo_cell[axis] <= 2);
    }

    float radius2 = radius * radius;
    // Two cells of the range may hash to the same bucket; visiting it once avoids duplicates.
    std::array<uint32_t, 27> visited;
    int visited_count = 0;
    CellCoords cell;
    for (cell[2] = lo_cell[2]; cell[2] <= hi_cell[2]; ++cell[2])
        for (cell[1] = lo_cell[1]; cell[1] <= hi_cell[1]; ++cell[1])
            for (cell[0] = lo_cell[0]; cell[0] <= hi_cell[0]; ++cell[0]) {
                uint32_t bucket = bucket_of(cell);
                auto visited_end = visited.begin() + visited_count;
                if (std::find(visited.begin(), visited_end, bucket) != visited_end) continue;
                visited[visited_count++] = bucket;
                uint32_t begin = bucket == 0 ? 0 : bucket_ends_[bucket - 1];
                for (uint32_t i = begin; i < bucket_ends_[bucket]; ++i)
                    if (distance_squared(sorted_points_[i], center) < radius2)
                        indices.push_back(sorted_indices_[i]);
            }
}

size_t HashGrid::memory_bytes() const {
    return bucket_ends_.capacity() * sizeof(uint32_t) + sorted_points_.capacity() * sizeof(Vec3f) +
           sorted_indices_.capacity() * sizeof(uint32_t);
}

} // namespace caustica
