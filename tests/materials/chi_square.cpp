#include "chi_square.h"

#include "core/rng.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

namespace caustica::testing {

double gamma_q(double a, double x) {
    if (x <= 0) return 1;
    double log_prefactor = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1) {
        // Series for P(a, x) = e^-x x^a / Gamma(a) sum_n x^n / (a (a+1) ... (a+n)).
        double term = 1 / a, sum = term;
        for (int n = 1; n < 10000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::abs(term) < std::abs(sum) * 1e-15) break;
        }
        return std::max(0.0, 1 - sum * std::exp(log_prefactor));
    }
    // Continued fraction for Q(a, x), evaluated with the modified Lentz method.
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int n = 1; n < 10000; ++n) {
        double an = -n * (n - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < 1e-15) break;
    }
    return std::exp(log_prefactor) * h;
}

namespace {

struct ChartFrame {
    Vec3f x, y, z;
    double power;
    explicit ChartFrame(const SphereChart &c) : z(normalize(c.axis)), power(c.power) {
        coordinate_system(z, &x, &y);
    }
    // (t, phi) of a direction.
    void coordinates(Vec3f w, double *t, double *phi) const {
        double lx = dot(w, x), ly = dot(w, y), lz = dot(w, z);
        double theta = std::atan2(std::sqrt(lx * lx + ly * ly), lz);
        *t = std::pow(theta / Pi, 1 / power);
        *phi = std::atan2(ly, lx);
        if (*phi < 0) *phi += 2 * Pi;
    }
    // Direction at (t, phi) and the solid angle per unit dt dphi there.
    Vec3f direction(double t, double phi, double *jacobian) const {
        double theta = Pi * std::pow(t, power);
        double st = std::sin(theta), ct = std::cos(theta);
        *jacobian = st * Pi * power * std::pow(t, power - 1);
        Vec3f local = x * float(st * std::cos(phi)) + y * float(st * std::sin(phi)) + z * float(ct);
        return local;
    }
};

// Gauss-Legendre nodes and weights on [0, 1], three points: exact for quintics.
constexpr double GaussNodes[3] = {0.5 - 0.3872983346207417, 0.5, 0.5 + 0.3872983346207417};
constexpr double GaussWeights[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};

double integrate_cell(const ChartFrame &frame, const PdfFunction &pdf, double t0, double t1,
                      double p0, double p1) {
    double sum = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double t = t0 + (t1 - t0) * GaussNodes[i], phi = p0 + (p1 - p0) * GaussNodes[j];
            double jac;
            Vec3f w = frame.direction(t, phi, &jac);
            sum += GaussWeights[i] * GaussWeights[j] * pdf(w) * jac;
        }
    return sum * (t1 - t0) * (p1 - p0);
}

// Adaptive cubature: accept a cell when splitting it in four changes the estimate by less than
// the tolerance (in units of probability) plus 0.1% of it, else recurse with half the tolerance
// per child. A 0.1% error of an expected count e is below its Poisson deviation sqrt(e) for any
// e below 10^6, more than the sample counts used.
double integrate_adaptive(const ChartFrame &frame, const PdfFunction &pdf, double t0, double t1,
                          double p0, double p1, double whole, double tolerance, int depth) {
    double tm = (t0 + t1) / 2, pm = (p0 + p1) / 2;
    double q[4] = {integrate_cell(frame, pdf, t0, tm, p0, pm), integrate_cell(frame, pdf, tm, t1, p0, pm),
                   integrate_cell(frame, pdf, t0, tm, pm, p1), integrate_cell(frame, pdf, tm, t1, pm, p1)};
    double refined = q[0] + q[1] + q[2] + q[3];
    if (depth == 0 || std::abs(refined - whole) < tolerance + 1e-3 * refined) return refined;
    double half = tolerance / 2;
    return integrate_adaptive(frame, pdf, t0, tm, p0, pm, q[0], half, depth - 1) +
           integrate_adaptive(frame, pdf, tm, t1, p0, pm, q[1], half, depth - 1) +
           integrate_adaptive(frame, pdf, t0, tm, pm, p1, q[2], half, depth - 1) +
           integrate_adaptive(frame, pdf, tm, t1, pm, p1, q[3], half, depth - 1);
}

} // namespace

ChiSquareResult chi_square_test(const SampleFunction &sample, const PdfFunction &pdf,
                                const SphereChart &chart, int sample_count, uint64_t seed,
                                int theta_bins, int phi_bins) {
    ChartFrame frame(chart);
    int bins = theta_bins * phi_bins;
    // Bin `bins` counts samples that were not produced.
    std::vector<double> observed(bins + 1, 0.0), expected(bins + 1, 0.0);

    Rng rng(seed, 0x5eed);
    for (int n = 0; n < sample_count; ++n) {
        float uc = rng.uniform();
        Vec2f u = rng.uniform2();
        Vec3f w;
        if (!sample(uc, u, &w)) {
            observed[bins] += 1;
            continue;
        }
        w = normalize(w);
        double t, phi;
        frame.coordinates(w, &t, &phi);
        int ti = std::clamp(int(t * theta_bins), 0, theta_bins - 1);
        int pi = std::clamp(int(phi / (2 * Pi) * phi_bins), 0, phi_bins - 1);
        observed[ti * phi_bins + pi] += 1;
    }

    // Integration tolerance: 0.02 expected samples per bin, far below the Poisson noise of any
    // bin that is not pooled.
    double tolerance = 0.02 / sample_count;
    double total = 0;
    for (int ti = 0; ti < theta_bins; ++ti)
        for (int pi = 0; pi < phi_bins; ++pi) {
            double t0 = double(ti) / theta_bins, t1 = double(ti + 1) / theta_bins;
            double p0 = 2 * Pi * pi / phi_bins, p1 = 2 * Pi * (pi + 1) / phi_bins;
            // Start from a 2 x 2 split of the bin so that features much smaller than a bin
            // are seen by some Gauss node before the refinement test decides to stop.
            double p = 0;
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b) {
                    double ca = t0 + (t1 - t0) * a / 2, cb = t0 + (t1 - t0) * (a + 1) / 2;
                    double pa = p0 + (p1 - p0) * b / 2, pb = p0 + (p1 - p0) * (b + 1) / 2;
                    double whole = integrate_cell(frame, pdf, ca, cb, pa, pb);
                    p += integrate_adaptive(frame, pdf, ca, cb, pa, pb, whole, tolerance / 4, 6);
                }
            expected[ti * phi_bins + pi] = p * sample_count;
            total += p;
        }
    expected[bins] = std::max(0.0, 1 - total) * sample_count;

    // Pool every bin expecting fewer than 5 samples (Pearson's approximation needs about that
    // many per cell); if the pool itself stays small, merge it into the smallest regular bin.
    std::vector<int> order(bins + 1);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return expected[a] < expected[b]; });
    double pooled_expected = 0, pooled_observed = 0;
    std::vector<std::pair<double, double>> cells;  // (observed, expected)
    for (int i : order) {
        if (expected[i] < 5)
            pooled_expected += expected[i], pooled_observed += observed[i];
        else
            cells.push_back({observed[i], expected[i]});
    }
    if (pooled_expected >= 5 || cells.empty())
        cells.push_back({pooled_observed, pooled_expected});
    else {
        cells.front().first += pooled_observed;
        cells.front().second += pooled_expected;
    }

    ChiSquareResult result;
    std::vector<std::pair<double, int>> contributions;
    for (size_t i = 0; i < cells.size(); ++i) {
        auto [o, e] = cells[i];
        double c = e > 0 ? sqr(o - e) / e : (o > 0 ? Infinity : 0);
        result.statistic += c;
        contributions.push_back({c, int(i)});
    }
    result.degrees_of_freedom = int(cells.size()) - 1;
    result.p_value = result.degrees_of_freedom > 0
                         ? gamma_q(result.degrees_of_freedom / 2.0, result.statistic / 2)
                         : 1.0;
    std::sort(contributions.rbegin(), contributions.rend());
    std::ostringstream s;
    s << "chi2 = " << result.statistic << ", dof = " << result.degrees_of_freedom
      << ", p = " << result.p_value << ", pdf integral = " << total
      << ", failed samples observed " << observed[bins] << " expected " << expected[bins]
      << "; worst cells (observed/expected):";
    for (size_t i = 0; i < std::min<size_t>(5, contributions.size()); ++i) {
        auto [o, e] = cells[contributions[i].second];
        s << " " << o << "/" << e;
    }
    result.details = s.str();
    return result;
}

} // namespace caustica::testing
