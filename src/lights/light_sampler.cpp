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

ImportanceLightSampler::ImportanceLightSampler(const std::vector<LightPtr> &lights) : by_power_(lights) {
    for (const LightPtr &l : lights) {
        const std::optional<Bounds3f> bounds = l->spatial_bounds();
        if (!bounds || bounds->empty()) {
            index_.emplace(l.get(), -1 - int(unbounded_.size()));
            unbounded_.push_back(l.get());
        } else if (const std::optional<LightBounds> b = light_bounds(*l)) {
            index_.emplace(l.get(), int(bounded_.size()));
            bounded_.push_back(l.get());
            bounded_bounds_.push_back(*b);
        }
    }
}

// One share for every light at infinity, and one for all bounded lights together.
int ImportanceLightSampler::shares() const { return int(unbounded_.size()) + (bounded_.empty() ? 0 : 1); }

std::optional<SampledLight> ImportanceLightSampler::sample(const LightSampleContext &ctx, float u) const {
    const int shares = this->shares();
    if (shares == 0) return {};
    const float p_unbounded = float(unbounded_.size()) / float(shares);
    if (u < p_unbounded) {
        const int i = std::min(int(u * float(shares)), int(unbounded_.size()) - 1);
        return SampledLight{unbounded_[size_t(i)], 1 / float(shares)};
    }
    u = std::min((u - p_unbounded) / (1 - p_unbounded), OneMinusEpsilon);
    std::optional<SampledLight> s = sample_bounded(ctx, u);
    if (s) s->pmf *= 1 - p_unbounded;
    return s;
}

float ImportanceLightSampler::pmf(const LightSampleContext &ctx, const Light *light) const {
    const auto it = index_.find(light);
    if (it == index_.end()) return 0;
    const int shares = this->shares();
    if (it->second < 0) return 1 / float(shares);
    return pmf_bounded(ctx, it->second) * (1 - float(unbounded_.size()) / float(shares));
}

std::optional<SampledLight> ExhaustiveLightSampler::sample_bounded(const LightSampleContext &ctx, float u) const {
    double total = 0;
    for (const LightBounds &b : bounded_bounds_) total += b.importance(ctx.p, ctx.ns);
    if (!(total > 0)) return {};
    const double target = double(u) * total;
    double running = 0;
    int last_positive = -1;
    for (size_t i = 0; i < bounded_.size(); ++i) {
        const float importance = bounded_bounds_[i].importance(ctx.p, ctx.ns);
        if (!(importance > 0)) continue;
        last_positive = int(i);
        running += importance;
        if (target < running) return SampledLight{bounded_[i], float(importance / total)};
    }
    // Rounding left target at the end of the sum.
    return SampledLight{bounded_[size_t(last_positive)],
                        float(bounded_bounds_[size_t(last_positive)].importance(ctx.p, ctx.ns) / total)};
}

float ExhaustiveLightSampler::pmf_bounded(const LightSampleContext &ctx, int bounded_index) const {
    double total = 0;
    for (const LightBounds &b : bounded_bounds_) total += b.importance(ctx.p, ctx.ns);
    if (!(total > 0)) return 0;
    return float(bounded_bounds_[size_t(bounded_index)].importance(ctx.p, ctx.ns) / total);
}

}  // namespace caustica
