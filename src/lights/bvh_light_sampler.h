// pbrt-v4's default light sampler, "bvh": a bounding volume hierarchy over the lights' bounds
// (Conty Estevez and Kulla 2018, "Importance Sampling of Many Lights with Adaptive Tree
// Splitting", without the splitting). A light is chosen by descending from the root, taking
// each child with probability proportional to its node's importance at the receiving point
// (LightBounds::importance), so the cost grows with the tree's depth, not with the number of
// lights, and a light's probability is the product of the choices on its way down.
#pragma once

#include "lights/light_sampler.h"

#include <utility>
#include <vector>

namespace caustica {

class BVHLightSampler final : public ImportanceLightSampler {
  public:
    explicit BVHLightSampler(const std::vector<LightPtr> &lights);

  private:
    std::optional<SampledLight> sample_bounded(const LightSampleContext &ctx, float u) const override;
    float pmf_bounded(const LightSampleContext &ctx, int bounded_index) const override;

    struct Node {
        LightBounds bounds;
        int parent = -1;
        // A leaf's light (index into bounded_), or an interior node's second child (its first
        // follows it).
        int light_or_second_child = -1;
        bool leaf = false;
        // An interior node whose children have the same bounds (same_bounds): their importances
        // are equal wherever they are evaluated, so one of them decides, and the choice is even.
        bool twins = false;
    };
    // The importances of interior node `node`'s two children at the receiving point.
    std::pair<double, double> child_importances(int node, const LightSampleContext &ctx) const;
    // Builds the subtree over lights[begin, end) of bounded_ indices; returns its root.
    int build(std::vector<int> &lights, size_t begin, size_t end, int parent);

    std::vector<Node> nodes_;
    std::vector<int> leaf_of_light_; // per bounded light
};

} // namespace caustica
