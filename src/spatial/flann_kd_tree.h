// Fixed-radius search with FLANN's single kd-tree (Muja and Lowe 2014, "Scalable nearest neighbor
// algorithms for high dimensional data"), searched exactly.
//
// The tree is FLANN's KDTreeSingleIndex with the 3D squared-Euclidean distance, queried through
// its findNeighbors with our own result set that appends indices straight into the caller's
// vector: flann::Index::radiusSearch would instead allocate a query matrix wrapper, two
// vectors of vectors and a 1024-entry result buffer on every call. findNeighbors is const and
// keeps its traversal state on the stack (plus one small local vector), so concurrent queries on
// a built tree are safe.
#pragma once

#include "core/vecmath.h"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace caustica {

class FlannKdTree {
  public:
    FlannKdTree();
    ~FlannKdTree();
    // Indexes points for queries of radius at most max_radius; the tree keeps its own copy.
    void build(std::span<const Vec3f> points, float max_radius);
    // Replaces the contents of indices with the indices of the points within radius of center
    // (the convention of photon_map.h), in an order fixed by the tree. Requires
    // 0 <= radius <= max_radius (std::invalid_argument otherwise).
    void find_within(Vec3f center, float radius, std::vector<uint32_t> &indices) const;
    // The tree's bytes, its copy of the points included.
    size_t memory_bytes() const;

  private:
    // The FLANN tree, kept out of this header because FLANN's headers are large.
    struct Tree;
    std::unique_ptr<Tree> tree_;
    size_t point_count_ = 0;
    float max_radius_ = 0;
};

} // namespace caustica
