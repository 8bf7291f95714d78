#include "core/piecewise_linear_2d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace caustica {

namespace {

// The last index i in [0, size - 2] with below(i) true (below is true, then false, along the
// indices), or 0 when below(1) is false.
template <typename Below>
uint32_t find_interval(uint32_t size, Below below) {
    uint32_t lo = 0, hi = size - 1;  // below(lo) is taken as true, the answer is < hi
    while (hi - lo > 1) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (below(mid))
            lo = mid;
        else
            hi = mid;
    }
    return std::min(lo, size - 2);
}

// The t in [0, 1] at which the integral from 0 to t of the linear density a + (b - a) s equals
// area (with area at most (a + b) / 2).
float invert_trapezoid(float a, float b, float area) {
    if (std::abs(a - b) < 1e-4f * (a + b)) return 2 * area / (a + b);
    return (a - safe_sqrt(a * a - 2 * area * (a - b))) / (a - b);
}

} // namespace

PiecewiseLinear2D::PiecewiseLinear2D(std::span<const float> data, int nx, int ny,
                                     std::vector<std::vector<float>> parameters, Kind kind)
    : nx_(nx), ny_(ny), parameters_(std::move(parameters)) {
    if (nx < 2 || ny < 2) throw std::invalid_argument("a grid needs at least 2 x 2 values");
    if (parameters_.size() > size_t(MaxParameters)) throw std::invalid_argument("more than 3 parameters");
    size_t slices = 1;
    for (const auto &values : parameters_) {
        if (values.empty()) throw std::invalid_argument("a parameter without values");
        for (size_t i = 0; i < values.size(); ++i)
            if (!std::isfinite(values[i]) || (i > 0 && !(values[i] > values[i - 1])))
                throw std::invalid_argument("parameter values must be finite and increasing");
        slices *= values.size();
    }
    const size_t cells = size_t(nx) * ny;
    if (data.size() != slices * cells) throw std::invalid_argument("the table's size does not match its shape");
    data_.assign(data.begin(), data.end());
    if (kind == Kind::Interpolant) return;

    to_unit_square_ = float(nx - 1) * float(ny - 1);
    conditional_cdf_.resize(slices * cells);
    marginal_cdf_.resize(slices * ny);
    for (size_t s = 0; s < slices; ++s) {
        float *values = data_.data() + s * cells, *conditional = conditional_cdf_.data() + s * cells;
        float *marginal = marginal_cdf_.data() + s * ny;
        for (size_t i = 0; i < cells; ++i)
            if (!(values[i] >= 0) || !std::isfinite(values[i]))
                throw std::invalid_argument("a density with a negative or non-finite value");
        // Trapezoids along each row, then along the column of row totals.
        for (int y = 0; y < ny; ++y) {
            double sum = 0;
            conditional[y * nx] = 0;
            for (int x = 0; x + 1 < nx; ++x) {
                sum += 0.5 * (double(values[y * nx + x]) + values[y * nx + x + 1]);
                conditional[y * nx + x + 1] = float(sum);
            }
        }
        double total = 0;
        marginal[0] = 0;
        for (int y = 0; y + 1 < ny; ++y) {
            total += 0.5 * (double(conditional[y * nx + nx - 1]) + conditional[(y + 1) * nx + nx - 1]);
            marginal[y + 1] = float(total);
        }
        if (!(total > 0) || !std::isfinite(total))
            throw std::invalid_argument("a density that is zero everywhere for some parameter values");
        const float normalize = float(1 / total);
        for (size_t i = 0; i < cells; ++i) {
            values[i] *= normalize;
            conditional[i] *= normalize;
        }
        for (int y = 0; y < ny; ++y) marginal[y] *= normalize;
    }
}

PiecewiseLinear2D::Blend PiecewiseLinear2D::blend(std::span<const float> parameters) const {
    Blend b;
    b.count = 1;
    b.slice[0] = 0;
    b.weight[0] = 1;
    for (size_t d = 0; d < parameters_.size(); ++d) {
        const std::vector<float> &values = parameters_[d];
        const uint32_t n = uint32_t(values.size());
        for (int k = 0; k < b.count; ++k) b.slice[k] *= n;
        if (n == 1) continue;
        const float p = d < parameters.size() ? parameters[d] : values[0];
        const uint32_t i = find_interval(n, [&](uint32_t j) { return values[j] <= p; });
        const float ratio = (p - values[i]) / (values[i + 1] - values[i]);
        const float t = ratio >= 0 ? std::min(ratio, 1.f) : 0.f;  // NaN to 0
        for (int k = 0; k < b.count; ++k) {
            b.slice[b.count + k] = b.slice[k] + i + 1;
            b.weight[b.count + k] = b.weight[k] * t;
            b.slice[k] += i;
            b.weight[k] *= 1 - t;
        }
        b.count *= 2;
    }
    return b;
}

float PiecewiseLinear2D::lookup(const std::vector<float> &table, uint32_t stride, uint32_t i, const Blend &b) {
    float v = 0;
    for (int k = 0; k < b.count; ++k) v += b.weight[k] * table[size_t(b.slice[k]) * stride + i];
    return v;
}

PiecewiseLinear2D::Sample PiecewiseLinear2D::sample(Vec2f u, std::span<const float> parameters) const {
    const Blend b = blend(parameters);
    const uint32_t cells = uint32_t(nx_) * ny_;
    u.x = clamp(u.x, 1 - OneMinusEpsilon, OneMinusEpsilon);
    u.y = clamp(u.y, 1 - OneMinusEpsilon, OneMinusEpsilon);

    // The row, then the position t within it, under the linear change of the row totals.
    const uint32_t row = find_interval(ny_, [&](uint32_t y) { return lookup(marginal_cdf_, ny_, y, b) < u.y; });
    const float row_total0 = lookup(conditional_cdf_, cells, row * nx_ + nx_ - 1, b);
    const float row_total1 = lookup(conditional_cdf_, cells, (row + 1) * nx_ + nx_ - 1, b);
    const float t = invert_trapezoid(row_total0, row_total1, u.y - lookup(marginal_cdf_, ny_, row, b));

    // The column, and the position s within it, in the row interpolated at t.
    const float target = u.x * lerp(t, row_total0, row_total1);
    auto conditional = [&](uint32_t x) {
        return lerp(t, lookup(conditional_cdf_, cells, row * nx_ + x, b),
                    lookup(conditional_cdf_, cells, (row + 1) * nx_ + x, b));
    };
    const uint32_t col = find_interval(nx_, [&](uint32_t x) { return conditional(x) < target; });
    const uint32_t i = row * nx_ + col;
    const float c0 = lerp(t, lookup(data_, cells, i, b), lookup(data_, cells, i + nx_, b));
    const float c1 = lerp(t, lookup(data_, cells, i + 1, b), lookup(data_, cells, i + nx_ + 1, b));
    const float s = invert_trapezoid(c0, c1, target - conditional(col));

    return {{(col + s) / float(nx_ - 1), (row + t) / float(ny_ - 1)}, lerp(s, c0, c1) * to_unit_square_};
}

PiecewiseLinear2D::Cell PiecewiseLinear2D::cell(Vec2f p, const Blend &b) const {
    const uint32_t cells = uint32_t(nx_) * ny_;
    // Points are kept in the unit square (a NaN goes to 0), so that the cell is always valid.
    auto unit = [](float v) { return v >= 0 ? std::min(v, 1.f) : 0.f; };
    const float gx = unit(p.x) * float(nx_ - 1), gy = unit(p.y) * float(ny_ - 1);
    Cell c;
    c.col = uint32_t(std::clamp(int(gx), 0, nx_ - 2));
    c.row = uint32_t(std::clamp(int(gy), 0, ny_ - 2));
    c.s = gx - float(c.col);
    c.t = gy - float(c.row);
    const uint32_t i = c.row * nx_ + c.col;
    c.left = lerp(c.t, lookup(data_, cells, i, b), lookup(data_, cells, i + nx_, b));
    c.right = lerp(c.t, lookup(data_, cells, i + 1, b), lookup(data_, cells, i + nx_ + 1, b));
    return c;
}

PiecewiseLinear2D::Sample PiecewiseLinear2D::invert(Vec2f p, std::span<const float> parameters) const {
    const Blend b = blend(parameters);
    const uint32_t cells = uint32_t(nx_) * ny_;
    const Cell c = cell(p, b);
    const uint32_t i = c.row * nx_ + c.col;
    const float row_total0 = lookup(conditional_cdf_, cells, c.row * nx_ + nx_ - 1, b);
    const float row_total1 = lookup(conditional_cdf_, cells, (c.row + 1) * nx_ + nx_ - 1, b);

    // The integral of the row interpolated at t up to x, over its total; then that of the row
    // totals up to y.
    const float before = lerp(c.t, lookup(conditional_cdf_, cells, i, b), lookup(conditional_cdf_, cells, i + nx_, b));
    const float ux = (before + c.s * (c.left + 0.5f * c.s * (c.right - c.left))) / lerp(c.t, row_total0, row_total1);
    const float uy = lookup(marginal_cdf_, ny_, c.row, b) + c.t * (row_total0 + 0.5f * c.t * (row_total1 - row_total0));
    return {{ux, uy}, lerp(c.s, c.left, c.right) * to_unit_square_};
}

float PiecewiseLinear2D::evaluate(Vec2f p, std::span<const float> parameters) const {
    const Cell c = cell(p, blend(parameters));
    return lerp(c.s, c.left, c.right) * to_unit_square_;
}

} // namespace caustica
