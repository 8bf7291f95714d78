#include "cli/render_agreement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

namespace caustica {

namespace {

// Blocks of 16x16 pixels; on small images smaller ones (down to 4x4), so that there are at least
// 64 of them: the variance of the image mean is estimated from the blocks, with about K / 9
// degrees of freedom for K blocks (block_noise), and with fewer the test loses most of its power.
// Smaller blocks hold the estimate's bound (noise correlated over less than a block) less well.
constexpr int kBlockSize = 16, kMinBlockSize = 4, kMinBlocks = 64;

struct BlockGrid {
    int size, columns, rows;
    int count() const { return columns * rows; }
};

BlockGrid block_grid(int width, int height) {
    auto grid = [&](int size) { return BlockGrid{size, (width + size - 1) / size, (height + size - 1) / size}; };
    int size = kBlockSize;
    while (size > kMinBlockSize && grid(size).count() < kMinBlocks) size /= 2;
    return grid(size);
}

// Sums over each block's pixels and channels of f(mean, half_difference).
template <typename F> std::vector<double> block_sums(const TwoRuns &runs, const BlockGrid &grid, F f) {
    std::vector<double> sums(size_t(grid.count()), 0.0);
    const Image &m = runs.mean, &h = runs.half_difference;
    for (int y = 0; y < m.height; ++y)
        for (int x = 0; x < m.width; ++x) {
            double &sum = sums[size_t(y / grid.size) * grid.columns + x / grid.size];
            for (int c = 0; c < 3; ++c) sum += f(double(m.at(x, y, c)), double(h.at(x, y, c)));
        }
    return sums;
}

// What one pair of renders says about its average's blocks.
struct BlockNoise {
    std::vector<double> sums;                 // of the mean image over each block
    std::vector<double> independent_variance; // of each block sum if pixel channels were independent: sum of H^2
    std::vector<double> values;               // pixel channels in each block
    // The factor by which neighbouring pixels' correlation (the pixel filter, splatting, photon
    // merging, a path's shared channels) raises a block sum's variance over that.
    double correlation_factor = 1;
    double image_sum_variance = 0; // of the sum of the mean image over all pixels and channels
    double image_sum_dof = 0;      // degrees of freedom of that estimate
};

// For block sums h_k of H, E[h_k h_j] is the covariance of the mean image's block sums k and j
// (two_run_noise.h), so h_k^2 estimates each block sum's variance with every correlation inside
// the block included. The image sum's variance is the sum of all those covariances; adjacent
// blocks (the 8 around each) are correlated through pixels near their common edge, so their
// products h_k h_j are included too. Blocks further apart are taken as uncorrelated: the bound of
// this estimate is that pixel noise be correlated over less than one block (16 pixels on large
// images); a longer correlation, a photon-merging radius of more pixels than that, makes the
// variance read low and z high. The cross products can make the sum smaller than the sum of
// squares alone by chance; the larger of the two is taken, as a negative correlation of
// neighbouring blocks is implausible for a render.
//
// The estimate is itself noisy, which makes the tails of z heavier than normal's on small images.
// With K blocks of similar variance s^2 it adds K squares (each of variance 2 s^4) and about 4K
// products of neighbouring sums, each counted twice (variance 4 s^4): about 9 times the variance
// of K squares alone, so it is taken as a scaled chi-square with K / 9 degrees of freedom
// (Satterthwaite 1946, "An approximate distribution of estimates of variance components").
BlockNoise block_noise(const TwoRuns &runs, const BlockGrid &grid) {
    BlockNoise noise;
    noise.sums = block_sums(runs, grid, [](double m, double) { return m; });
    noise.independent_variance = block_sums(runs, grid, [](double, double h) { return h * h; });
    noise.values = block_sums(runs, grid, [](double, double) { return 1.0; });
    const std::vector<double> h = block_sums(runs, grid, [](double, double h) { return h; });

    double squares = 0, neighbours = 0, independent = 0;
    for (int by = 0; by < grid.rows; ++by)
        for (int bx = 0; bx < grid.columns; ++bx) {
            const double hk = h[size_t(by) * grid.columns + bx];
            squares += hk * hk;
            independent += noise.independent_variance[size_t(by) * grid.columns + bx];
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = bx + dx, ny = by + dy;
                    if ((dx || dy) && nx >= 0 && ny >= 0 && nx < grid.columns && ny < grid.rows)
                        neighbours += hk * h[size_t(ny) * grid.columns + nx];
                }
        }
    noise.image_sum_variance = std::max(squares, squares + neighbours);
    noise.image_sum_dof = grid.count() / 9.0;
    // Measured over all blocks and applied to each: per block, h_k^2 has a single degree of
    // freedom, while the sum of H^2 over a block's pixel channels has hundreds. Never below 1:
    // a measured factor below it is noise.
    if (independent > 0) noise.correlation_factor = std::max(1.0, squares / independent);
    return noise;
}

// Welch-Satterthwaite: the degrees of freedom of the sum of two independent variance estimates
// with `dof_a` and `dof_b`.
double combined_dof(double variance_a, double dof_a, double variance_b, double dof_b) {
    const double terms = variance_a * variance_a / dof_a + variance_b * variance_b / dof_b;
    return terms > 0 ? (variance_a + variance_b) * (variance_a + variance_b) / terms : dof_a + dof_b;
}

// The normal-equivalent z of difference / sqrt(variance), a variance estimated with `dof` degrees
// of freedom: the ratio follows Student's t, converted to the standard normal value with the same
// tail probability by Wallace's approximation (1959, "Bounds on normal approximations to
// Student's and the chi-square distributions"), which errs on the safe side (a smaller z): for
// 5 degrees of freedom, 3.85 where the exact value is 3.89 at p = 1e-4, 4.73 for 4.80 at 1.6e-6.
// So one normal threshold serves every image size. No noise at all with a difference gives an
// infinite z.
double z_score(double difference, double variance, double dof) {
    if (difference == 0) return 0;
    if (variance <= 0) return std::copysign(std::numeric_limits<double>::infinity(), difference);
    const double t = difference / std::sqrt(variance);
    return std::copysign((8 * dof + 1) / (8 * dof + 3) * std::sqrt(dof * std::log1p(t * t / dof)), t);
}

std::string format(const char *spec, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, spec, v);
    return buf;
}

} // namespace

double two_sided_normal_quantile(double p) {
    if (!(p > 0 && p <= 1)) throw std::invalid_argument("two_sided_normal_quantile: p outside (0, 1]");
    // P(|Z| > z) = erfc(z / sqrt 2) falls from 1 at z = 0 to below 1e-300 at z = 38; bisection
    // to double precision.
    double lo = 0, hi = 40;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

Agreement check_agreement(const std::string &first, const TwoRuns &first_runs, const std::string &second,
                          const TwoRuns &second_runs) {
    const Image &m1 = first_runs.mean, &m2 = second_runs.mean;
    if (m1.width != m2.width || m1.height != m2.height)
        throw std::logic_error("check_agreement: the renders differ in size");
    const BlockGrid grid = block_grid(m1.width, m1.height);
    const BlockNoise a = block_noise(first_runs, grid), b = block_noise(second_runs, grid);

    Agreement result;
    result.first = first;
    result.second = second;
    result.block_size = grid.size;
    result.blocks = grid.count();

    double sum_a = 0, sum_b = 0;
    for (int k = 0; k < grid.count(); ++k) {
        sum_a += a.sums[size_t(k)];
        sum_b += b.sums[size_t(k)];
    }
    // z is the same for sums as for means over the n pixel channels.
    result.z = z_score(sum_a - sum_b, a.image_sum_variance + b.image_sum_variance,
                       combined_dof(a.image_sum_variance, a.image_sum_dof, b.image_sum_variance, b.image_sum_dof));
    result.relative_difference = sum_a + sum_b != 0 ? (sum_a - sum_b) / (0.5 * (sum_a + sum_b)) : 0;
    result.threshold = two_sided_normal_quantile(kAgreementFalseAlarmRate);

    for (int k = 0; k < grid.count(); ++k) {
        const size_t i = size_t(k);
        // The sum of a block's H^2 over n correlated values has at least n / f degrees of freedom
        // (f the correlation factor): for correlations r_ij in [0, 1] it has n^2 / sum r_ij^2 of
        // them, and sum r_ij^2 <= sum r_ij = n f.
        const double va = a.correlation_factor * a.independent_variance[i],
                     vb = b.correlation_factor * b.independent_variance[i];
        const double z = z_score(a.sums[i] - b.sums[i], va + vb,
                                 combined_dof(va, a.values[i] / a.correlation_factor, vb,
                                              b.values[i] / b.correlation_factor));
        if (std::abs(z) > std::abs(result.worst_block_z) || k == 0) {
            result.worst_block_z = z;
            result.worst_block_x = (k % grid.columns) * grid.size;
            result.worst_block_y = (k / grid.columns) * grid.size;
        }
    }
    // The largest of K standard normal |z| exceeds the quantile of rate / K with probability at
    // most `rate` (Bonferroni's inequality), however the blocks are correlated.
    result.block_threshold = two_sided_normal_quantile(kAgreementFalseAlarmRate / grid.count());
    result.agree = std::abs(result.z) <= result.threshold && std::abs(result.worst_block_z) <= result.block_threshold;
    return result;
}

std::string agreement_sentence(const Agreement &a) {
    const std::string block = std::to_string(a.block_size) + "x" + std::to_string(a.block_size);
    return std::string(a.agree ? "agree" : "DISAGREE") + ": " + a.first + " and " + a.second + " differ by " +
           format("%.3g", 100 * std::abs(a.relative_difference)) + "% in image mean (z = " + format("%.3g", a.z) +
           ", threshold " + format("%.3g", a.threshold) + "); worst " + block + " block at (" +
           std::to_string(a.worst_block_x) + ", " + std::to_string(a.worst_block_y) +
           "): z = " + format("%.3g", a.worst_block_z) + " (threshold " + format("%.3g", a.block_threshold) + ")";
}

} // namespace caustica
