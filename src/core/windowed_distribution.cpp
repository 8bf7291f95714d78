#include "core/windowed_distribution.h"

#include <algorithm>
#include <cmath>

namespace caustica {

WindowedDistribution2D::WindowedDistribution2D(std::vector<float> f, int nx, int ny)
    : nx_(nx), ny_(ny), f_(std::move(f)), table_(size_t(nx + 1) * (ny + 1), 0.0) {
    const double cell = 1.0 / (double(nx) * ny);
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x)
            table_[size_t(y + 1) * (nx + 1) + x + 1] = f_[size_t(y) * nx + x] * cell +
                                                      table_[size_t(y) * (nx + 1) + x + 1] +
                                                      table_[size_t(y + 1) * (nx + 1) + x] -
                                                      table_[size_t(y) * (nx + 1) + x];
}

double WindowedDistribution2D::cumulative(double x, double y) const {
    // Within a cell the integral is bilinear in (x, y), so interpolating the corners is exact.
    const double fx = std::clamp(x, 0.0, 1.0) * nx_, fy = std::clamp(y, 0.0, 1.0) * ny_;
    const int x0 = std::min(int(fx), nx_ - 1), y0 = std::min(int(fy), ny_ - 1);
    const double dx = fx - x0, dy = fy - y0;
    auto at = [&](int i, int j) { return table_[size_t(j) * (nx_ + 1) + i]; };
    return (1 - dx) * (1 - dy) * at(x0, y0) + dx * (1 - dy) * at(x0 + 1, y0) + (1 - dx) * dy * at(x0, y0 + 1) +
           dx * dy * at(x0 + 1, y0 + 1);
}

double WindowedDistribution2D::integral(const UVWindow &w) const {
    return cumulative(w.max.x, w.max.y) - cumulative(w.min.x, w.max.y) - cumulative(w.max.x, w.min.y) +
           cumulative(w.min.x, w.min.y);
}

float WindowedDistribution2D::value(Vec2f p) const {
    const int x = std::clamp(int(p.x * nx_), 0, nx_ - 1), y = std::clamp(int(p.y * ny_), 0, ny_ - 1);
    return f_[size_t(y) * nx_ + x];
}

template <typename G>
double WindowedDistribution2D::invert(G g, double target, double lo, double hi, int n) const {
    // The last cell edge in [lo, hi] at which g is still at most the target, by bisection over
    // the edges; g is linear between it and the next edge.
    int first = int(std::floor(lo * n)), last = int(std::ceil(hi * n));
    while (last - first > 1) {
        const int mid = (first + last) / 2;
        if (g(std::clamp(double(mid) / n, lo, hi)) <= target) first = mid;
        else last = mid;
    }
    const double a = std::clamp(double(first) / n, lo, hi), b = std::clamp(double(last) / n, lo, hi);
    const double ga = g(a), gb = g(b);
    return gb > ga ? std::clamp(a + (target - ga) / (gb - ga) * (b - a), a, b) : a;
}

std::optional<Vec2f> WindowedDistribution2D::sample(Vec2f u, const UVWindow &w, float *pdf) const {
    const double total = integral(w);
    if (!(total > 0)) return std::nullopt;
    // x from the window's marginal, then y from the conditional in the cell column holding x,
    // where f does not depend on x.
    auto marginal = [&](double x) { return integral({w.min, {float(x), w.max.y}}); };
    const double x = invert(marginal, u.x * total, w.min.x, w.max.x, nx_);
    const int column = std::clamp(int(x * nx_), 0, nx_ - 1);
    const UVWindow strip{{float(column) / nx_, w.min.y}, {float(column + 1) / nx_, w.max.y}};
    const double strip_total = integral(strip);
    if (!(strip_total > 0)) return std::nullopt;
    auto conditional = [&](double y) { return integral({strip.min, {strip.max.x, float(y)}}); };
    const double y = invert(conditional, u.y * strip_total, w.min.y, w.max.y, ny_);
    const Vec2f p{float(x), float(y)};
    *pdf = float(value(p) / total);
    if (!(*pdf > 0)) return std::nullopt;
    return p;
}

float WindowedDistribution2D::pdf(Vec2f p, const UVWindow &w) const {
    const double total = integral(w);
    return total > 0 ? float(value(p) / total) : 0.f;
}

} // namespace caustica
