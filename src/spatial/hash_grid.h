// Hashed uniform grid for fixed-radius queries (Georgiev et al. 2012, "Light transport simulation
// with vertex connection and merging", section 6).
//
// Cells are cubes of side 2 * max_radius, so a query ball of radius r <= max_radius, whose
// extent along each axis is at most one cell, overlaps at most 2x2x2 cells. (Cells of side
// max_radius would be smaller but a query would then visit up to 3x3x3 = 27 cells instead of 8;
// the larger cells trade a few more distance tests for far fewer cell lookups.) Only occupied
// cells matter, so integer cell coordinates are hashed into a table of as many buckets as there
// are points; a counting sort by bucket stores the points of each bucket contiguously, in a copy
// of the points kept in bucket order so that a query reads memory sequentially.
//
// Both choices were measured with bench/range_search_bench.cpp (1M photons, ~30 neighbours per
// query): cells of side max_radius made queries 1.5x slower, and reading the points through
// their indices instead of the bucket-ordered copy made them 2x slower.
#pragma once

#include "spatial/range_search.h"

#include <array>

namespace caustica {

class HashGrid final : public RangeSearch {
  public:
    void build(std::span<const Vec3f> points, float max_radius) override;
    void find_within(Vec3f center, float radius, std::vector<uint32_t> &indices) const override;
    size_t memory_bytes() const override;

  private:
    using CellCoords = std::array<int64_t, 3>;
    // Cell index of coordinate x along an axis, unclamped. Evaluated in double and monotone in x,
    // which is what makes queries exact (see find_within).
    int64_t cell_coordinate(double x, int axis) const;
    uint32_t bucket_of(const CellCoords &cell) const;

    Bounds3f bounds_;
    float max_radius_ = 0;
    double inverse_cell_size_ = 1;
    CellCoords max_cell_{};
    // bucket_ends_[b] is one past the last entry of bucket b in sorted_points_/sorted_indices_;
    // bucket b starts at bucket_ends_[b - 1] (0 for b = 0).
    std::vector<uint32_t> bucket_ends_;
    std::vector<Vec3f> sorted_points_;
    std::vector<uint32_t> sorted_indices_;
};

} // namespace caustica
