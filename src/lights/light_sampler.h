// Choosing one light for next-event estimation or for starting a light path.
#pragma once

#include "core/sampling.h"
#include "lights/light.h"

#include <optional>
#include <unordered_map>
#include <vector>

namespace caustica {

struct SampledLight {
    const Light *light = nullptr;
    float pmf = 0;
};

class LightSampler {
  public:
    virtual ~LightSampler() = default;
    // Empty when there are no lights.
    virtual std::optional<SampledLight> sample(float u) const = 0;
    // Probability that sample() returns `light` (0 for a light it does not know).
    virtual float pmf(const Light *light) const = 0;
    // The same for next-event estimation from a receiving point: samplers that know where lights
    // are may prefer the lights near it. Default: the choice does not depend on the point.
    virtual std::optional<SampledLight> sample(const LightSampleContext &ctx, float u) const {
        (void)ctx;
        return sample(u);
    }
    virtual float pmf(const LightSampleContext &ctx, const Light *light) const {
        (void)ctx;
        return pmf(light);
    }
};

// Every light equally likely.
class UniformLightSampler final : public LightSampler {
  public:
    explicit UniformLightSampler(const std::vector<LightPtr> &lights);
    std::optional<SampledLight> sample(float u) const override;
    float pmf(const Light *light) const override;

  private:
    std::vector<const Light *> lights_;
    std::unordered_map<const Light *, int> index_;
};

// Lights chosen in proportion to their emitted power (pbrt-v4's PowerLightSampler). Power is
// phi() integrated over the visible spectrum (light_sampler.cpp); lights are therefore to be
// preprocessed (scene bounds known) before the sampler is built. If every light has zero power,
// falls back to uniform selection.
class PowerLightSampler final : public LightSampler {
  public:
    explicit PowerLightSampler(const std::vector<LightPtr> &lights);
    std::optional<SampledLight> sample(float u) const override;
    float pmf(const Light *light) const override;

  private:
    std::vector<const Light *> lights_;
    std::unordered_map<const Light *, int> index_;
    DiscreteDistribution distribution_;
};

// Lights chosen by power (as PowerLightSampler) where the choice cannot depend on a point (light
// paths), and for next-event estimation by each light's power over its squared distance from
// the receiving point, the distance taken no shorter than the radius of the light's bounding
// sphere: the estimate of its contribution that pbrt-v4's light BVH (Conty Estevez and Kulla
// 2018, "Importance Sampling of Many Lights with Adaptive Tree Splitting") refines, without the
// orientation bounds. A small bright lamp near a wall then gets the wall's samples that its power
// alone would give to a distant, more powerful light. Lights at infinity share, each as much as
// all local lights together, as in pbrt-v4. The choice costs time linear in the number of
// lights, so scenes with more than MaxLights lights (emissive meshes) keep choosing by power.
class SpatialLightSampler final : public LightSampler {
  public:
    static constexpr int MaxLights = 64;
    explicit SpatialLightSampler(const std::vector<LightPtr> &lights);
    std::optional<SampledLight> sample(float u) const override { return by_power_.sample(u); }
    float pmf(const Light *light) const override { return by_power_.pmf(light); }
    std::optional<SampledLight> sample(const LightSampleContext &ctx, float u) const override;
    float pmf(const LightSampleContext &ctx, const Light *light) const override;

  private:
    // Each light's selection weight at p (unnormalised), into weights; returns their sum.
    float weights(Vec3f p, float *weights) const;

    PowerLightSampler by_power_;
    bool spatial_ = false;
    std::vector<const Light *> lights_;
    std::unordered_map<const Light *, int> index_;
    std::vector<float> power_;
    std::vector<Vec3f> centre_;
    std::vector<float> radius2_;
    std::vector<bool> at_infinity_;
    int local_count_ = 0, infinite_count_ = 0;
};

}  // namespace caustica
