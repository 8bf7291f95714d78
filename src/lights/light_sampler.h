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

}  // namespace caustica
