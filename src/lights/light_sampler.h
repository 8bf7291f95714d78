// Choosing one light for next-event estimation or for starting a light path.
#pragma once

#include "core/sampling.h"
#include "lights/light.h"
#include "lights/light_bounds.h"

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

// The samplers of pbrt-v4's "bvh" and "exhaustive": for next-event estimation, each light is
// chosen in proportion to its importance at the receiving point (LightBounds::importance, Conty
// Estevez and Kulla 2018), which is zero only where the light cannot contribute; lights at
// infinity share, each as much as all local lights together, as in pbrt-v4. Where the choice
// cannot depend on a point (light paths), lights are chosen by power (as PowerLightSampler).
class ImportanceLightSampler : public LightSampler {
  public:
    std::optional<SampledLight> sample(float u) const final { return by_power_.sample(u); }
    float pmf(const Light *light) const final { return by_power_.pmf(light); }
    std::optional<SampledLight> sample(const LightSampleContext &ctx, float u) const final;
    float pmf(const LightSampleContext &ctx, const Light *light) const final;

  protected:
    // Sorts the lights into those with bounds (bounded_, with bounded_bounds_) and the rest.
    explicit ImportanceLightSampler(const std::vector<LightPtr> &lights);
    // The choice among the bounded lights (u in [0, 1)), and its probability.
    virtual std::optional<SampledLight> sample_bounded(const LightSampleContext &ctx, float u) const = 0;
    virtual float pmf_bounded(const LightSampleContext &ctx, int bounded_index) const = 0;

    std::vector<const Light *> bounded_;
    std::vector<LightBounds> bounded_bounds_;

  private:
    int shares() const; // one per unbounded light, one for the bounded ones together
    PowerLightSampler by_power_;
    // Lights without spatial bounds (at infinity). Bounded lights without power are never
    // chosen, as in pbrt-v4: nothing they could send would be seen.
    std::vector<const Light *> unbounded_;
    // Each light's index in bounded_ (>= 0) or in unbounded_ (-1 - index).
    std::unordered_map<const Light *, int> index_;
};

// pbrt-v4's "exhaustive": every bounded light's importance, in time linear in their number.
class ExhaustiveLightSampler final : public ImportanceLightSampler {
  public:
    explicit ExhaustiveLightSampler(const std::vector<LightPtr> &lights) : ImportanceLightSampler(lights) {}

  private:
    std::optional<SampledLight> sample_bounded(const LightSampleContext &ctx, float u) const override;
    float pmf_bounded(const LightSampleContext &ctx, int bounded_index) const override;
};

}  // namespace caustica
