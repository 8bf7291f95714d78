#include "lights/light_sampler.h"

#include "lights/spectral_power.h"

#include <algorithm>
#include <cmath>

namespace caustica {

UniformLightSampler::UniformLightSampler(const std::vector<LightPtr> &lights) {
    for (const LightPtr &l : lights) {
        index_.emplace(l.get(), int(lights_.size()));
        lights_.push_back(l.get());
    }
}

std::optional<SampledLight> UniformLightSampler::sample(float u) const {
    if (lights_.empty()) return {};
    int n = int(lights_.size());
    int i = std::min(int(u * n), n - 1);
    return SampledLight{lights_[i], 1.f / n};
}

float UniformLightSampler::pmf(const Light *light) const {
    return index_.contains(light) ? 1.f / lights_.size() : 0.f;
}

PowerLightSampler::PowerLightSampler(const std::vector<LightPtr> &lights) {
    if (lights.empty()) return;
    std::vector<float> power;
    power.reserve(lights.size());
    for (const LightPtr &l : lights) {
        const float p = light_power(*l);
        power.push_back(std::isfinite(p) ? std::max(0.f, p) : 0.f);
        index_.emplace(l.get(), int(lights_.size()));
        lights_.push_back(l.get());
    }
    // DiscreteDistribution falls back to uniform weights when all are zero.
    distribution_ = DiscreteDistribution(power);
}

std::optional<SampledLight> PowerLightSampler::sample(float u) const {
    if (lights_.empty()) return {};
    float pmf;
    int i = distribution_.sample(u, &pmf);
    return SampledLight{lights_[i], pmf};
}

float PowerLightSampler::pmf(const Light *light) const {
    auto it = index_.find(light);
    return it == index_.end() ? 0.f : distribution_.pmf(it->second);
}

SpatialLightSampler::SpatialLightSampler(const std::vector<LightPtr> &lights) : by_power_(lights) {
    spatial_ = !lights.empty() && int(lights.size()) <= MaxLights;
    if (!spatial_) return;
    for (const LightPtr &l : lights) {
        index_.emplace(l.get(), int(lights_.size()));
        lights_.push_back(l.get());
        const float p = light_power(*l);
        power_.push_back(std::isfinite(p) ? std::max(0.f, p) : 0.f);
        std::optional<Bounds3f> bounds = l->spatial_bounds();
        Vec3f c{};
        float r = 0;
        if (bounds && !bounds->empty()) bounds->bounding_sphere(&c, &r);
        centre_.push_back(c);
        radius2_.push_back(r * r);
        at_infinity_.push_back(!bounds || bounds->empty());
        (at_infinity_.back() ? infinite_count_ : local_count_) += 1;
    }
}

float SpatialLightSampler::weights(Vec3f p, float *w) const {
    // Local lights: power / max(distance^2, radius^2), normalised among themselves, so that all
    // of them together weigh as much as one light at infinity.
    float local_sum = 0;
    const int n = int(lights_.size());
    for (int i = 0; i < n; ++i) {
        if (at_infinity_[i]) continue;
        const float d2 = std::max(distance_squared(p, centre_[i]), radius2_[i]);
        w[i] = d2 > 0 ? power_[i] / d2 : (power_[i] > 0 ? 1e30f : 0.f);
        if (!std::isfinite(w[i])) w[i] = 1e30f;
        local_sum += w[i];
    }
    // One share for every light at infinity and one for all local lights together.
    float total = 0;
    for (int i = 0; i < n; ++i) {
        if (at_infinity_[i]) w[i] = 1;
        else w[i] = local_sum > 0 ? w[i] / local_sum : 1.f / float(local_count_);
        total += w[i];
    }
    return total;
}

std::optional<SampledLight> SpatialLightSampler::sample(const LightSampleContext &ctx, float u) const {
    if (!spatial_) return by_power_.sample(u);
    float w[MaxLights];
    const float total = weights(ctx.p, w);
    if (!(total > 0)) return by_power_.sample(u);
    const int n = int(lights_.size());
    float target = u * total, running = 0;
    int chosen = n - 1;
    for (int i = 0; i < n; ++i) {
        running += w[i];
        if (target < running && w[i] > 0) {
            chosen = i;
            break;
        }
    }
    while (chosen > 0 && w[chosen] == 0) --chosen;
    if (!(w[chosen] > 0)) return {};
    return SampledLight{lights_[size_t(chosen)], w[chosen] / total};
}

float SpatialLightSampler::pmf(const LightSampleContext &ctx, const Light *light) const {
    if (!spatial_) return by_power_.pmf(light);
    auto it = index_.find(light);
    if (it == index_.end()) return 0;
    float w[MaxLights];
    const float total = weights(ctx.p, w);
    if (!(total > 0)) return by_power_.pmf(light);
    return w[it->second] / total;
}

}  // namespace caustica
