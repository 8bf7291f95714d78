// What the medium tests share: a coefficient that varies with wavelength, and a running mean
// checked against its expectation.
#pragma once

#include "spectral/spectrum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace caustica::testing {

// A coefficient linear in wavelength, so that the four wavelengths of a path see different media
// (what the spectral MIS of free flights exists for).
class LinearSpectrum final : public Spectrum {
  public:
    LinearSpectrum(float at_360, float at_830) : a_(at_360), b_((at_830 - at_360) / 470) {}
    float operator()(float lambda) const override { return a_ + b_ * (lambda - 360); }
    float max_value() const override { return std::max(a_, a_ + b_ * 470); }

  private:
    float a_, b_;
};

struct RunningMean {
    double sum = 0, sum_sq = 0;
    long n = 0;
    void add(double x) { sum += x; sum_sq += x * x; ++n; }
    double mean() const { return sum / n; }
    double standard_error() const { return std::sqrt(std::max(0.0, sum_sq / n - mean() * mean()) / n); }
};

// The mean within 4.5 of its own standard errors (plus `slack`) of the expected value: a correct
// estimator exceeds that with probability below 1e-5.
inline void expect_mean(const RunningMean &m, double expected, const std::string &what, double slack = 1e-7) {
    EXPECT_LE(std::abs(m.mean() - expected), 4.5 * m.standard_error() + slack)
        << what << ": mean " << m.mean() << " expected " << expected << " (standard error " << m.standard_error()
        << ")";
}

} // namespace caustica::testing
