// Fixed-radius neighbour search over a point set: the photon (light vertex) lookup of photon
// mapping and vertex merging. The point set is rebuilt once per iteration and then queried from
// many threads, so build() is single-shot and find_within() is const and thread-safe.
//
// Two implementations sit behind this interface (create_range_search): a kd-tree radius search
// from FLANN, and the hashed uniform grid of the VCM paper (Georgiev et al. 2012, section 6),
// whose cells are twice as wide as the largest query radius so that a query ball (diameter at
// most one cell) overlaps at most 2x2x2 cells.
//
// Conventions shared by both: a point is found when its float squared distance to the center,
// (dx*dx + dy*dy) + dz*dz, is strictly less than radius*radius, so radius 0 finds nothing and
// points exactly at the radius are excluded. Points, centers and radii are assumed finite (no
// NaN or infinity); at most 2^32 - 1 points.
#pragma once

#include "core/vecmath.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace caustica {

class RangeSearch {
  public:
    virtual ~RangeSearch() = default;
    // Indexes points (copied or referenced as the implementation needs; the span must stay
    // valid until the next build) for queries of radius at most max_radius.
    virtual void build(std::span<const Vec3f> points, float max_radius) = 0;
    // Replaces the contents of indices with the indices (into the built span) of every point
    // whose distance to center is less than radius, in no fixed order. Requires
    // 0 <= radius <= max_radius (std::invalid_argument otherwise).
    virtual void find_within(Vec3f center, float radius, std::vector<uint32_t> &indices) const = 0;
    // Bytes the structure holds beyond the points themselves, for memory reports.
    virtual size_t memory_bytes() const = 0;
};

// "hashgrid" or "flann"; throws std::invalid_argument for anything else.
std::unique_ptr<RangeSearch> create_range_search(const std::string &name);

} // namespace caustica
