// Chi-square goodness-of-fit of a BxDF's (or distribution's) sampling routine against its pdf,
// in the manner of pbrt-v4's bsdfs_test.cpp: histogram the sampled directions over a chart of
// the sphere, integrate the pdf over each bin numerically to get the expected counts, pool
// bins with small expectations and compare with Pearson's statistic.
//
// Two additions: the chart can be centred on a lobe's peak with bins that shrink as a power of
// the angle (so lobes of width 1e-3 rad and below are resolved), and samples that sampling fails
// to produce form their own category with expected count N (1 - integral of the pdf), which also
// tests that the pdf integrates to the probability of producing a sample.
#pragma once

#include "core/vecmath.h"

#include <functional>
#include <string>

namespace caustica::testing {

// Directions are charted as (t, phi) in [0,1] x [0, 2 pi): theta' = pi t^power is the angle from
// the axis. power 1 with the axis +z puts the horizon on a bin boundary (with an even number of
// t bins); larger powers magnify the neighbourhood of the axis.
struct SphereChart {
    Vec3f axis{0, 0, 1};
    float power = 1;
};

struct ChiSquareResult {
    double statistic = 0;
    int degrees_of_freedom = 0;
    double p_value = 1;
    std::string details;  // the worst bins, for failure messages
};

// sample(u1, u2, u3, &w) returns false when no sample is produced; pdf(w) is the solid-angle
// density of returned samples. Samples are drawn with a PCG stream seeded by `seed`.
using SampleFunction = std::function<bool(float, Vec2f, Vec3f *)>;
using PdfFunction = std::function<double(Vec3f)>;
ChiSquareResult chi_square_test(const SampleFunction &sample, const PdfFunction &pdf,
                                const SphereChart &chart, int sample_count, uint64_t seed,
                                int theta_bins = 16, int phi_bins = 32);

// Regularised upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a): the chi-square
// tail probability is Q(dof / 2, statistic / 2).
double gamma_q(double a, double x);

} // namespace caustica::testing
