#include "sampler/pmj02bn_sequence.h"

#include "core/rng.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace caustica {

namespace {

constexpr int BestCandidates = 10;

// The top k bits of a fixed-point coordinate: its stratum among 2^k.
uint32_t top_bits(uint32_t v, int k) { return k == 0 ? 0 : v >> (32 - k); }

class Pmj02bnBuilder {
  public:
    explicit Pmj02bnBuilder(uint64_t seed) : rng_(seed, 0x706d6a3032626eULL) {}
    std::vector<FixedPoint2> build(int count);

  private:
    // Opens the next level: the count N = 2^level doubles, and every grid of the level is
    // marked with the points so far.
    void next_level();
    void mark(FixedPoint2 p);
    // Grid g of the level has 2^(level - g) columns and 2^g rows.
    bool occupied(int g, uint32_t column, uint32_t row) const {
        return strata_[g][(size_t(row) << (level_ - g)) | column];
    }
    // The valid x strata (of width 2^-level) below rectangle (column, row) of grid g, and the
    // valid y strata.
    void x_strata(uint32_t column, uint32_t row, int g, std::vector<uint32_t> &out) const;
    void y_strata(uint32_t column, uint32_t row, int g, std::vector<uint32_t> &out) const;
    // Adds the next point, the best of the candidates in sub-square (sx, sy).
    void place(uint32_t sx, uint32_t sy);
    void add(FixedPoint2 p);
    uint32_t square_x(FixedPoint2 p) const { return top_bits(p.x, side_log2_); }
    uint32_t square_y(FixedPoint2 p) const { return top_bits(p.y, side_log2_); }
    double nearest_distance_squared(FixedPoint2 p) const;

    Rng rng_;
    std::vector<FixedPoint2> points_;
    int level_ = 0;
    // The sub-squares: 2^side_log2_ a side, each holding at most one point (index, or -1).
    int side_log2_ = 0;
    std::vector<int> squares_;
    std::vector<std::vector<uint8_t>> strata_;
    std::vector<uint32_t> valid_x_, valid_y_;
};

void Pmj02bnBuilder::next_level() {
    ++level_;
    side_log2_ = (level_ + 1) / 2;
    strata_.assign(level_ + 1, std::vector<uint8_t>(size_t(1) << level_, 0));
    squares_.assign(size_t(1) << (2 * side_log2_), -1);
    for (size_t i = 0; i < points_.size(); ++i) {
        mark(points_[i]);
        squares_[(size_t(square_y(points_[i])) << side_log2_) | square_x(points_[i])] = int(i);
    }
}

void Pmj02bnBuilder::mark(FixedPoint2 p) {
    for (int g = 0; g <= level_; ++g)
        strata_[g][(size_t(top_bits(p.y, g)) << (level_ - g)) | top_bits(p.x, level_ - g)] = 1;
}

// Descending from a rectangle to the ones half as wide and twice as tall (Pharr 2019): a fine x
// stratum is valid when no rectangle above it, on the way down, holds a point.
void Pmj02bnBuilder::x_strata(uint32_t column, uint32_t row, int g, std::vector<uint32_t> &out) const {
    if (occupied(g, column, row)) return;
    if (g == 0) {
        out.push_back(column);
        return;
    }
    x_strata(2 * column, row / 2, g - 1, out);
    x_strata(2 * column + 1, row / 2, g - 1, out);
}

void Pmj02bnBuilder::y_strata(uint32_t column, uint32_t row, int g, std::vector<uint32_t> &out) const {
    if (occupied(g, column, row)) return;
    if (g == level_) {
        out.push_back(row);
        return;
    }
    y_strata(column / 2, 2 * row, g + 1, out);
    y_strata(column / 2, 2 * row + 1, g + 1, out);
}

void Pmj02bnBuilder::place(uint32_t sx, uint32_t sy) {
    valid_x_.clear();
    valid_y_.clear();
    if (level_ % 2 == 0) {
        // The sub-squares are the rectangles of the square grid.
        x_strata(sx, sy, level_ / 2, valid_x_);
        y_strata(sx, sy, level_ / 2, valid_y_);
    } else {
        // A sub-square is half of a rectangle of each of the two grids nearest to square.
        x_strata(sx, sy / 2, side_log2_ - 1, valid_x_);
        y_strata(sx / 2, sy, side_log2_, valid_y_);
    }
    if (valid_x_.empty() || valid_y_.empty())
        throw std::logic_error("pmj02bn: a sub-square has no valid strata");
    FixedPoint2 best{};
    double best_distance = -1;
    for (int c = 0; c < BestCandidates; ++c) {
        const uint32_t xs = valid_x_[rng_.next_uint32() % valid_x_.size()];
        const uint32_t ys = valid_y_[rng_.next_uint32() % valid_y_.size()];
        const FixedPoint2 candidate{(xs << (32 - level_)) | (rng_.next_uint32() >> level_),
                                    (ys << (32 - level_)) | (rng_.next_uint32() >> level_)};
        const double d = nearest_distance_squared(candidate);
        if (d > best_distance) {
            best_distance = d;
            best = candidate;
        }
    }
    add(best);
}

void Pmj02bnBuilder::add(FixedPoint2 p) {
    mark(p);
    squares_[(size_t(square_y(p)) << side_log2_) | square_x(p)] = int(points_.size());
    points_.push_back(p);
}

// Rings of sub-squares around p's, on the torus, until no farther square can hold a nearer point.
double Pmj02bnBuilder::nearest_distance_squared(FixedPoint2 p) const {
    const int side = 1 << side_log2_;
    const uint32_t mask = uint32_t(side - 1);
    const double square = 1.0 / side;
    double nearest = std::numeric_limits<double>::infinity();
    const int px = int(square_x(p)), py = int(square_y(p));
    for (int r = 0; r <= side / 2; ++r) {
        for (int dy = -r; dy <= r; ++dy) {
            const int step = (dy == -r || dy == r) ? 1 : 2 * r;
            for (int dx = -r; dx <= r; dx += step) {
                const int i = squares_[(size_t((py + dy) & mask) << side_log2_) | ((px + dx) & mask)];
                if (i < 0) continue;
                // Unsigned differences wrap around the torus.
                const uint32_t ux = points_[i].x - p.x, uy = points_[i].y - p.y;
                const double ex = std::min(ux, 0u - ux) * 0x1p-32, ey = std::min(uy, 0u - uy) * 0x1p-32;
                nearest = std::min(nearest, ex * ex + ey * ey);
            }
        }
        // Squares of ring r + 1 and beyond lie at least r squares away.
        if (nearest <= (r * square) * (r * square)) break;
    }
    return nearest;
}

std::vector<FixedPoint2> Pmj02bnBuilder::build(int count) {
    points_.reserve(size_t(count));
    strata_.assign(1, std::vector<uint8_t>(1, 0));
    squares_.assign(1, -1);
    add({rng_.next_uint32(), rng_.next_uint32()});
    for (size_t n = 1; points_.size() < size_t(count); n *= 4) {
        // n = 4^j points: each gets a partner diagonally opposite, visited in an order
        // scrambled by an xor, which keeps the new half as balanced as the old.
        next_level();
        const uint32_t order = rng_.next_uint32() % n;
        for (size_t s = 0; s < n && points_.size() < size_t(count); ++s) {
            const FixedPoint2 old = points_[s ^ order];
            place(square_x(old) ^ 1, square_y(old) ^ 1);
        }
        // 2n points: each quadrant's two empty sub-squares, one beside the quadrant's first
        // point (left-right or up-down at random), then the one opposite it.
        next_level();
        std::vector<std::pair<uint32_t, uint32_t>> chosen(n);
        const uint32_t order2 = rng_.next_uint32() % n;
        for (size_t s = 0; s < n; ++s) {
            const FixedPoint2 old = points_[s ^ order2];
            const bool flip_x = rng_.next_uint32() & 1;
            chosen[s] = {square_x(old) ^ uint32_t(flip_x), square_y(old) ^ uint32_t(!flip_x)};
        }
        for (size_t s = 0; s < n && points_.size() < size_t(count); ++s) place(chosen[s].first, chosen[s].second);
        for (size_t s = 0; s < n && points_.size() < size_t(count); ++s)
            place(chosen[s].first ^ 1, chosen[s].second ^ 1);
    }
    return std::move(points_);
}

} // namespace

std::vector<FixedPoint2> generate_pmj02bn(int count, uint64_t seed) {
    if (count < 1 || count > (1 << 20)) throw std::invalid_argument("pmj02bn: count out of range");
    return Pmj02bnBuilder(seed).build(count);
}

} // namespace caustica
