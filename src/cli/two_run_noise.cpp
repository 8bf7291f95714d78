#include "cli/two_run_noise.h"

#include <cmath>
#include <stdexcept>

namespace caustica {

TwoRuns::TwoRuns(const Image &a, const Image &b) : mean(a.width, a.height), half_difference(a.width, a.height) {
    if (a.width != b.width || a.height != b.height) throw std::logic_error("TwoRuns: the renders differ in size");
    // A crop window's place in the frame carries over to the images written from these.
    mean.origin = half_difference.origin = a.origin;
    mean.full_resolution = half_difference.full_resolution = a.full_resolution;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        mean.rgb[i] = 0.5f * (a.rgb[i] + b.rgb[i]);
        half_difference.rgb[i] = 0.5f * (a.rgb[i] - b.rgb[i]);
    }
}

RenderError estimated_error(const TwoRuns &runs) {
    double squared = 0, relative_squared = 0;
    const size_t n = runs.mean.rgb.size();
    for (size_t i = 0; i < n; ++i) {
        double h = runs.half_difference.rgb[i], m = runs.mean.rgb[i];
        squared += h * h;
        relative_squared += h * h / (m * m + 0.01);
    }
    if (n == 0) return {};
    return {std::sqrt(squared / double(n)), relative_squared / double(n)};
}

Image estimated_variance(const TwoRuns &runs) {
    Image variance(runs.mean.width, runs.mean.height);
    for (size_t i = 0; i < variance.rgb.size(); ++i)
        variance.rgb[i] = runs.half_difference.rgb[i] * runs.half_difference.rgb[i];
    return variance;
}

} // namespace caustica
