#include "core/catmull_rom.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace caustica {
namespace {

// The largest i in [0, size - 2] with below(i), for a predicate true up to some index and false
// after it (below(0) is assumed): the interval [i, i + 1] of a table of `size` entries.
template <typename Below> int find_interval(int size, Below below) {
    int first = 1, count = size - 2;
    while (count > 0) {
        int half = count / 2, middle = first + half;
        if (below(middle)) {
            first = middle + 1;
            count -= half + 1;
        } else {
            count = half;
        }
    }
    return std::clamp(first - 1, 0, size - 2);
}

// The spline on interval i as a function of t in [0, 1]: end values f0, f1 and end derivatives
// d0, d1 per unit t.
struct Segment {
    float x0, width, f0, f1, d0, d1;

    float value(float t) const {
        float t2 = t * t, t3 = t2 * t;
        return (2 * t3 - 3 * t2 + 1) * f0 + (-2 * t3 + 3 * t2) * f1 + (t3 - 2 * t2 + t) * d0 +
               (t3 - t2) * d1;
    }
    float derivative(float t) const {
        float t2 = t * t;
        return (6 * t2 - 6 * t) * (f0 - f1) + (3 * t2 - 4 * t + 1) * d0 + (3 * t2 - 2 * t) * d1;
    }
    // int_0^t value(s) ds.
    float integral(float t) const {
        float c3 = (-2 * d0 - d1) / 3 + f1 - f0, c4 = (d0 + d1) / 4 + (f0 - f1) / 2;
        return t * (f0 + t * (0.5f * d0 + t * (c3 + t * c4)));
    }
    float total() const { return (f0 + f1) / 2 + (d0 - d1) / 12; }
};

template <typename Value>
Segment segment(std::span<const float> nodes, const Value &f, int i) {
    const int n = int(nodes.size());
    Segment s;
    s.x0 = nodes[i];
    s.width = nodes[i + 1] - nodes[i];
    s.f0 = f(i);
    s.f1 = f(i + 1);
    s.d0 = i > 0 ? s.width * (s.f1 - f(i - 1)) / (nodes[i + 1] - nodes[i - 1]) : s.f1 - s.f0;
    s.d1 = i + 2 < n ? s.width * (f(i + 2) - s.f0) / (nodes[i + 2] - nodes[i]) : s.f1 - s.f0;
    return s;
}

// Root in [0, 1] of a monotone g given as (g, g'): Newton steps, falling back to bisection when a
// step leaves the bracket. Stops when the bracket or |g| falls below 1e-6 (pbrt-v4's
// NewtonBisection tolerances, which the tabulated profiles' samples depend on).
template <typename G> float newton_bisection(const G &g) {
    constexpr float Eps = 1e-6f;
    float lo = 0, hi = 1;
    float g_lo = g(lo).first, g_hi = g(hi).first;
    if (std::abs(g_lo) < Eps) return lo;
    if (std::abs(g_hi) < Eps) return hi;
    const bool rising = g_lo < 0;
    float x = -g_lo / (g_hi - g_lo);
    while (true) {
        if (!(lo < x && x < hi)) x = (lo + hi) / 2;
        auto [value, slope] = g(x);
        ((value < 0) == rising ? lo : hi) = x;
        if (hi - lo < Eps || std::abs(value) < Eps) return x;
        x -= value / slope;
    }
}

} // namespace

std::optional<CatmullRomWeights> catmull_rom_weights(std::span<const float> nodes, float x) {
    if (!(x >= nodes.front() && x <= nodes.back())) return std::nullopt;
    const int n = int(nodes.size());
    const int i = find_interval(n, [&](int j) { return nodes[j] <= x; });
    const float x0 = nodes[i], x1 = nodes[i + 1];
    const float t = (x - x0) / (x1 - x0), t2 = t * t, t3 = t2 * t;
    // The Hermite basis of Segment::value, with each end derivative's finite difference spread
    // over the values it is made of.
    CatmullRomWeights w;
    w.offset = i - 1;
    w.weights = {0, 2 * t3 - 3 * t2 + 1, -2 * t3 + 3 * t2, 0};
    const float h0 = t3 - 2 * t2 + t, h1 = t3 - t2;
    if (i > 0) {
        float s = h0 * (x1 - x0) / (x1 - nodes[i - 1]);
        w.weights[0] = -s;
        w.weights[2] += s;
    } else {
        w.weights[1] -= h0;
        w.weights[2] += h0;
    }
    if (i + 2 < n) {
        float s = h1 * (x1 - x0) / (nodes[i + 2] - x0);
        w.weights[1] -= s;
        w.weights[3] = s;
    } else {
        w.weights[1] -= h1;
        w.weights[2] += h1;
    }
    return w;
}

float integrate_catmull_rom(std::span<const float> nodes, std::span<const float> values,
                            std::span<float> cdf) {
    auto f = [&](int j) { return values[j]; };
    float sum = 0;
    cdf[0] = 0;
    for (int i = 0; i + 1 < int(nodes.size()); ++i) {
        Segment s = segment(nodes, f, i);
        sum += s.width * s.total();
        cdf[i + 1] = sum;
    }
    return sum;
}

float invert_catmull_rom(std::span<const float> nodes, std::span<const float> values, float y) {
    if (!(y > values.front())) return nodes.front();
    if (!(y < values.back())) return nodes.back();
    const int i = find_interval(int(values.size()), [&](int j) { return values[j] <= y; });
    Segment s = segment(nodes, [&](int j) { return values[j]; }, i);
    float t = newton_bisection([&](float t) { return std::pair(s.value(t) - y, s.derivative(t)); });
    return s.x0 + t * s.width;
}

float sample_catmull_rom_2d(std::span<const float> nodes1, std::span<const float> nodes2,
                            std::span<const float> values, std::span<const float> cdf, float alpha,
                            float u) {
    std::optional<CatmullRomWeights> w = catmull_rom_weights(nodes1, alpha);
    if (!w) return 0;
    const int n2 = int(nodes2.size());
    auto blend = [&](std::span<const float> table, int j) {
        float v = 0;
        for (int k = 0; k < 4; ++k)
            if (w->weights[k] != 0) v += w->weights[k] * table[(w->offset + k) * n2 + j];
        return v;
    };
    // Invert the blended running integral: first the interval, then the cubic integral within it.
    u *= blend(cdf, n2 - 1);
    const int i = find_interval(n2, [&](int j) { return blend(cdf, j) <= u; });
    Segment s = segment(nodes2, [&](int j) { return blend(values, j); }, i);
    const float target = (u - blend(cdf, i)) / s.width;
    float t = newton_bisection(
        [&](float t) { return std::pair(s.integral(t) - target, s.value(t)); });
    return s.x0 + t * s.width;
}

} // namespace caustica
