#include "spatial/flann_kd_tree.h"

#include <flann/algorithms/dist.h>
#include <flann/algorithms/kdtree_single_index.h>

#include <limits>
#include <stdexcept>

namespace caustica {

namespace {

// Points per leaf. FLANN's default is 10; with 10-50 neighbours per query a larger leaf trades a
// few extra distance tests for a shallower tree: 16 answered queries about 10% faster than 10
// and built a smaller tree (bench/photon_map_bench.cpp).
constexpr int LeafSize = 16;

// Appends the index of every point FLANN offers whose squared distance is below the squared
// radius. Reporting the squared radius as the worst distance makes FLANN prune every subtree
// whose bounding box lies at least that far away, so the search is exact and unlimited.
class AppendWithinRadius final : public flann::ResultSet<float> {
  public:
    AppendWithinRadius(float radius2, std::vector<uint32_t> &indices)
        : radius2_(radius2), indices_(indices) {}
    bool full() const override { return true; }
    void addPoint(float distance2, size_t index) override {
        if (distance2 < radius2_) indices_.push_back(uint32_t(index));
    }
    float worstDist() const override { return radius2_; }

  private:
    float radius2_;
    std::vector<uint32_t> &indices_;
};

} // namespace

// L2_3D sums (dx*dx + dy*dy) + dz*dz in float, the same expression as distance_squared.
struct FlannKdTree::Tree : flann::KDTreeSingleIndex<flann::L2_3D<float>> {
    using KDTreeSingleIndex::KDTreeSingleIndex;
};

FlannKdTree::FlannKdTree() = default;
FlannKdTree::~FlannKdTree() = default;

void FlannKdTree::build(std::span<const Vec3f> points, float max_radius) {
    static_assert(sizeof(Vec3f) == 3 * sizeof(float), "FLANN reads points as rows of 3 floats");
    if (points.size() >= std::numeric_limits<uint32_t>::max())
        throw std::invalid_argument("FlannKdTree: more than 2^32 - 1 points");
    if (!(max_radius >= 0)) throw std::invalid_argument("FlannKdTree: negative max_radius");
    tree_.reset();
    point_count_ = points.size();
    max_radius_ = max_radius;
    // FLANN cannot build a tree over no points.
    if (points.empty()) return;
    // flann::Matrix takes a mutable pointer but the tree only reads the points; with reordering
    // (the default) it copies them into leaf order, so queries do not touch the span.
    flann::Matrix<float> matrix(const_cast<float *>(&points[0].x), points.size(), 3);
    tree_ = std::make_unique<Tree>(matrix, flann::KDTreeSingleIndexParams(LeafSize));
    tree_->buildIndex();
}

void FlannKdTree::find_within(Vec3f center, float radius, std::vector<uint32_t> &indices) const {
    if (!(radius >= 0 && radius <= max_radius_))
        throw std::invalid_argument("FlannKdTree: query radius outside [0, max_radius]");
    indices.clear();
    if (!tree_) return;
    AppendWithinRadius result(radius * radius, indices);
    // eps = 0: exact search; checks is ignored by the single kd-tree, which visits every leaf
    // the bound above cannot prune.
    flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, 0.f);
    tree_->findNeighbors(result, &center.x, params);
}

size_t FlannKdTree::memory_bytes() const {
    if (!tree_) return 0;
    // usedMemory counts the node pool and the index permutation; beyond it FLANN keeps the
    // reordered copy of the points and one row pointer per point.
    return size_t(tree_->usedMemory()) + point_count_ * (sizeof(Vec3f) + sizeof(float *));
}

} // namespace caustica
