#include "spectral/wavelength_density.h"

#include "core/vecmath.h"
#include "spectral/sampled_wavelengths.h"

#include <algorithm>
#include <cmath>

namespace caustica {

namespace {

constexpr float BinWidth = 1;
constexpr int Bins = int((LambdaMax - LambdaMin) / BinWidth);
constexpr int PointsPerBin = 4;

// Mean over bin b of f, from PointsPerBin points at the centres of equal parts.
template <typename F> double bin_mean(int b, const F &f) {
    double sum = 0;
    for (int k = 0; k < PointsPerBin; ++k) sum += f(LambdaMin + (b + (k + 0.5f) / PointsPerBin) * BinWidth);
    return sum / PointsPerBin;
}

} // namespace

WavelengthDensity::WavelengthDensity(const std::function<float(float)> &power) : pdf_(Bins), cdf_(Bins + 1) {
    std::vector<double> visible(Bins), emitted(Bins);
    double visible_sum = 0, emitted_sum = 0;
    for (int b = 0; b < Bins; ++b) {
        visible[b] = bin_mean(b, visible_wavelengths_pdf);
        emitted[b] = bin_mean(b, [&](float lambda) {
            const float phi = power(lambda);
            return std::isfinite(phi) && phi > 0 ? visible_wavelengths_pdf(lambda) * phi : 0.f;
        });
        visible_sum += visible[b];
        emitted_sum += emitted[b];
    }
    const double emitted_share = emitted_sum > 0 ? 0.5 : 0;
    for (int b = 0; b < Bins; ++b) {
        double p = (1 - emitted_share) * visible[b] / visible_sum;
        if (emitted_share > 0) p += emitted_share * emitted[b] / emitted_sum;
        // Per nanometre, and the cumulative distribution in the same measure.
        pdf_[b] = float(p / BinWidth);
        cdf_[b + 1] = cdf_[b] + float(p);
    }
    // Rounding leaves the total a few ulps from 1; sample() inverts the stored total.
    for (float &c : cdf_) c /= cdf_.back();
    guide_.resize(Bins);
    for (int k = 0; k < Bins; ++k) guide_[k] = bin_of(float(k) / Bins);
}

int WavelengthDensity::bin_of(float u) const {
    return std::clamp(int(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin()) - 1, 0, Bins - 1);
}

float WavelengthDensity::pdf(float lambda) const {
    if (!(lambda >= LambdaMin && lambda <= LambdaMax)) return 0;
    return pdf_[std::min(int((lambda - LambdaMin) / BinWidth), Bins - 1)];
}

float WavelengthDensity::sample(float u) const {
    // The bin whose cumulative range holds u (empty bins are never chosen: their range is empty):
    // bin_of(u), found from the guide's bin for the start of u's slice of [0, 1) by the few steps
    // to it (Chen and Asau 1974's guide table), not by a binary search over every bin.
    const float slice = u * Bins; // compared before converting, so that no value is out of int's range
    int b = guide_[slice >= 0 ? (slice < Bins ? int(slice) : Bins - 1) : 0];
    while (b > 0 && cdf_[b] > u) --b;
    while (b < Bins - 1 && !(cdf_[b + 1] > u)) ++b;
    const float width = cdf_[b + 1] - cdf_[b];
    const float t = width > 0 ? std::clamp((u - cdf_[b]) / width, 0.f, 1.f) : 0.5f;
    return std::min(LambdaMin + (b + t) * BinWidth, LambdaMax);
}

} // namespace caustica
