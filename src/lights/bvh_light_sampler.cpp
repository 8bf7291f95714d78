#include "lights/bvh_light_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace caustica {

namespace {

// The solid-angle measure of the directions a node may emit towards (Conty Estevez and Kulla
// 2018, eq. 1): its normal cone widened by theta_e, weighted by the cosine of emission.
float orientation_measure(const EmissionDirections &d) {
    const float theta_o = std::acos(std::clamp(d.normals.cos_theta, -1.f, 1.f));
    const float theta_e = std::acos(std::clamp(d.cos_theta_e, -1.f, 1.f));
    const float theta_w = std::min(theta_o + theta_e, Pi);
    const float sin_o = std::sin(theta_o), cos_o = std::cos(theta_o);
    return 2 * Pi * (1 - cos_o) +
           Pi / 2 * (2 * theta_w * sin_o - std::cos(theta_o - 2 * theta_w) - 2 * theta_o * sin_o + cos_o);
}

float surface_area(const Bounds3f &b) {
    const Vec3f d = b.hi - b.lo;
    return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

// The cost of a node with these bounds (eq. 2): power times orientation measure times surface
// area, with the ratio of the box's longest side to its side along the split axis, which favours
// splitting boxes across their length.
float split_cost(const LightBounds &b, const Vec3f &node_diagonal, int axis) {
    const float kr = max_component(node_diagonal) / node_diagonal[axis];
    return b.phi * orientation_measure(b.directions) * surface_area(b.bounds) * kr;
}

} // namespace

BVHLightSampler::BVHLightSampler(const std::vector<LightPtr> &lights) : ImportanceLightSampler(lights) {
    if (bounded_.empty()) return;
    std::vector<int> order(bounded_.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
    leaf_of_light_.assign(bounded_.size(), -1);
    nodes_.reserve(2 * bounded_.size() - 1);
    build(order, 0, order.size(), -1);
}

int BVHLightSampler::build(std::vector<int> &lights, size_t begin, size_t end, int parent) {
    const int index = int(nodes_.size());
    nodes_.emplace_back();
    nodes_[size_t(index)].parent = parent;
    if (end - begin == 1) {
        Node &leaf = nodes_[size_t(index)];
        leaf.bounds = bounded_bounds_[size_t(lights[begin])];
        leaf.leaf = true;
        leaf.light_or_second_child = lights[begin];
        leaf_of_light_[size_t(lights[begin])] = index;
        return index;
    }

    LightBounds all;
    Bounds3f centroids;
    for (size_t i = begin; i < end; ++i) {
        const LightBounds &b = bounded_bounds_[size_t(lights[i])];
        all = bounds_union(all, b);
        centroids.expand(b.bounds.center());
    }
    const Vec3f diagonal = all.bounds.hi - all.bounds.lo;

    // The cheapest of the splits between 12 buckets of centroids along each axis (pbrt-v4's).
    constexpr int Buckets = 12;
    auto bucket_of = [&](int light, int axis) {
        const float lo = centroids.lo[axis], extent = centroids.hi[axis] - lo;
        const float c = bounded_bounds_[size_t(light)].bounds.center()[axis];
        return std::min(int(Buckets * (c - lo) / extent), Buckets - 1);
    };
    float best_cost = Infinity;
    int best_axis = -1, best_split = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (!(centroids.hi[axis] > centroids.lo[axis]) || !(diagonal[axis] > 0)) continue;
        std::array<LightBounds, Buckets> buckets{};
        for (size_t i = begin; i < end; ++i) {
            LightBounds &b = buckets[size_t(bucket_of(lights[i], axis))];
            b = bounds_union(b, bounded_bounds_[size_t(lights[i])]);
        }
        for (int split = 1; split < Buckets; ++split) {
            LightBounds below, above;
            for (int k = 0; k < split; ++k) below = bounds_union(below, buckets[size_t(k)]);
            for (int k = split; k < Buckets; ++k) above = bounds_union(above, buckets[size_t(k)]);
            if (below.phi == 0 || above.phi == 0) continue;
            const float cost = split_cost(below, diagonal, axis) + split_cost(above, diagonal, axis);
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = axis;
                best_split = split;
            }
        }
    }

    size_t middle;
    if (best_axis >= 0 && best_cost > 0 && std::isfinite(best_cost)) {
        auto below = [&](int light) { return bucket_of(light, best_axis) < best_split; };
        middle = size_t(std::partition(lights.begin() + long(begin), lights.begin() + long(end), below) -
                        lights.begin());
    } else {
        // Points, or lights all centred alike: halves by count along the widest axis.
        const int axis = max_dimension(centroids.hi - centroids.lo);
        middle = begin + (end - begin) / 2;
        std::nth_element(lights.begin() + long(begin), lights.begin() + long(middle), lights.begin() + long(end),
                         [&](int a, int b) {
                             const float ca = bounded_bounds_[size_t(a)].bounds.center()[axis];
                             const float cb = bounded_bounds_[size_t(b)].bounds.center()[axis];
                             return ca < cb || (ca == cb && a < b);
                         });
    }
    if (middle == begin || middle == end) middle = begin + (end - begin) / 2;

    build(lights, begin, middle, index);
    const int second = build(lights, middle, end, index);
    Node &node = nodes_[size_t(index)];
    node.bounds = all;
    node.light_or_second_child = second;
    node.twins = same_bounds(nodes_[size_t(index) + 1].bounds, nodes_[size_t(second)].bounds);
    return index;
}

std::pair<double, double> BVHLightSampler::child_importances(int node, const LightSampleContext &ctx) const {
    const Node &n = nodes_[size_t(node)];
    const double first = nodes_[size_t(node) + 1].bounds.importance(ctx.p, ctx.ns);
    if (n.twins) return {first, first};
    return {first, nodes_[size_t(n.light_or_second_child)].bounds.importance(ctx.p, ctx.ns)};
}

std::optional<SampledLight> BVHLightSampler::sample_bounded(const LightSampleContext &ctx, float u) const {
    int node = 0;
    double pmf = 1;
    while (!nodes_[size_t(node)].leaf) {
        const int first = node + 1, second = nodes_[size_t(node)].light_or_second_child;
        const auto [i0, i1] = child_importances(node, ctx);
        if (!(i0 + i1 > 0)) return {};
        const double p0 = i0 / (i0 + i1);
        if (double(u) < p0) {
            u = float(std::min(double(u) / p0, double(OneMinusEpsilon)));
            pmf *= p0;
            node = first;
        } else {
            u = float(std::min((double(u) - p0) / (1 - p0), double(OneMinusEpsilon)));
            pmf *= 1 - p0;
            node = second;
        }
    }
    // A single light at the root has had no choice to test its importance.
    if (node == 0 && !(nodes_[0].bounds.importance(ctx.p, ctx.ns) > 0)) return {};
    return SampledLight{bounded_[size_t(nodes_[size_t(node)].light_or_second_child)], float(pmf)};
}

float BVHLightSampler::pmf_bounded(const LightSampleContext &ctx, int bounded_index) const {
    int node = leaf_of_light_[size_t(bounded_index)];
    if (node == 0) return nodes_[0].bounds.importance(ctx.p, ctx.ns) > 0 ? 1.f : 0.f;
    double pmf = 1;
    while (node != 0) {
        const int parent = nodes_[size_t(node)].parent;
        const int first = parent + 1;
        const auto [i0, i1] = child_importances(parent, ctx);
        if (!(i0 + i1 > 0)) return 0;
        pmf *= (node == first ? i0 : i1) / (i0 + i1);
        node = parent;
    }
    return float(pmf);
}

} // namespace caustica
