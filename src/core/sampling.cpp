#include "core/sampling.h"

#include <algorithm>
#include <numeric>

namespace caustica {

DiscreteDistribution::DiscreteDistribution(std::span<const float> weights) {
    double total = 0;
    for (float w : weights) total += std::max(0.f, w);
    pmf_.resize(weights.size());
    cdf_.resize(weights.size() + 1);
    cdf_[0] = 0;
    double run = 0;
    for (size_t i = 0; i < weights.size(); ++i) {
        double w = total > 0 ? std::max(0.f, weights[i]) / total : 1.0 / weights.size();
        pmf_[i] = float(w);
        run += w;
        cdf_[i + 1] = float(run);
    }
    if (!cdf_.empty()) cdf_.back() = 1;
}

int DiscreteDistribution::sample(float u, float *pmf, float *u_remapped) const {
    // Largest i with cdf_[i] <= u, skipping zero-probability bins.
    auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    int i = clamp(int(it - cdf_.begin()) - 1, 0, int(pmf_.size()) - 1);
    while (pmf_[i] == 0 && i + 1 < int(pmf_.size())) ++i;
    while (pmf_[i] == 0 && i > 0) --i;
    if (pmf) *pmf = pmf_[i];
    if (u_remapped)
        *u_remapped = std::min(OneMinusEpsilon, pmf_[i] > 0 ? (u - cdf_[i]) / pmf_[i] : 0.f);
    return i;
}

PiecewiseConstant1D::PiecewiseConstant1D(std::span<const float> f) : func_(f.begin(), f.end()) {
    for (float &v : func_) v = std::abs(v);
    int n = int(func_.size());
    cdf_.resize(n + 1);
    cdf_[0] = 0;
    for (int i = 1; i <= n; ++i) cdf_[i] = cdf_[i - 1] + func_[i - 1] / n;
    func_int_ = cdf_[n];
    if (func_int_ == 0)
        for (int i = 1; i <= n; ++i) cdf_[i] = float(i) / n;
    else
        for (int i = 1; i <= n; ++i) cdf_[i] /= func_int_;
}

float PiecewiseConstant1D::sample(float u, float *pdf, int *offset) const {
    int n = int(func_.size());
    // The last cdf entry <= u (std::upper_bound minus one), by a binary search whose steps are
    // conditional moves: u is random, so a branching search mispredicts about half its steps,
    // which made this the costliest part of sampling the pixel filter for every camera ray.
    const float *first = cdf_.data();
    for (size_t length = cdf_.size(); length > 1;) {
        const size_t half = length / 2;
        first = first[half] <= u ? first + half : first;
        length -= half;
    }
    int o = clamp(int(first - cdf_.data()), 0, n - 1);
    if (offset) *offset = o;
    float du = u - cdf_[o];
    if (cdf_[o + 1] - cdf_[o] > 0) du /= cdf_[o + 1] - cdf_[o];
    if (pdf) *pdf = func_int_ > 0 ? func_[o] / func_int_ : 1.f;
    return std::min((o + du) / n, OneMinusEpsilon);
}

float PiecewiseConstant1D::pdf(float x) const {
    int n = int(func_.size());
    int o = clamp(int(x * n), 0, n - 1);
    return func_int_ > 0 ? func_[o] / func_int_ : 1.f;
}

PiecewiseConstant2D::PiecewiseConstant2D(std::span<const float> f, int nu, int nv) {
    conditional_.reserve(nv);
    std::vector<float> marginal(nv);
    for (int v = 0; v < nv; ++v) {
        conditional_.emplace_back(f.subspan(size_t(v) * nu, nu));
        marginal[v] = conditional_.back().integral();
    }
    marginal_ = PiecewiseConstant1D(marginal);
}

Vec2f PiecewiseConstant2D::sample(Vec2f u, float *pdf) const {
    float pdf_v, pdf_u;
    int v;
    float d1 = marginal_.sample(u.y, &pdf_v, &v);
    float d0 = conditional_[v].sample(u.x, &pdf_u);
    if (pdf) *pdf = pdf_v * pdf_u;
    return {d0, d1};
}

float PiecewiseConstant2D::pdf(Vec2f p) const {
    int nv = int(conditional_.size());
    int v = clamp(int(p.y * nv), 0, nv - 1);
    return marginal_.pdf(p.y) * conditional_[v].pdf(p.x);
}

} // namespace caustica
