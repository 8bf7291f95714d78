#include "lights/emission_image.h"

#include "spectral/color_space.h"
#include "spectral/rgb_spectrum.h"

#include <algorithm>

namespace caustica {

EmissionImage::EmissionImage(RGBImage image) : image_(std::move(image)) {}

SampledSpectrum EmissionImage::emitted(RGB rgb, const SampledWavelengths &lambda) {
    const RGB clamped{std::max(rgb.r, 0.f), std::max(rgb.g, 0.f), std::max(rgb.b, 0.f)};
    return RGBIlluminantSpectrum(RGBColorSpace::srgb(), clamped).sample(lambda);
}

SampledSpectrum EmissionImage::radiance(Vec2f uv, const SampledWavelengths &lambda) const {
    return emitted(image_.bilerp({uv.x, 1 - uv.y}), lambda);
}

SampledSpectrum EmissionImage::mean_radiance(const SampledWavelengths &lambda) const {
    std::lock_guard<std::mutex> lock(cache_mutex_);
    bool same = cached_;
    for (int i = 0; same && i < NumWavelengths; ++i) same = cached_lambda_[i] == lambda[i];
    if (same) return cached_mean_;
    SampledSpectrum sum(0.f);
    for (int y = 0; y < image_.height; ++y)
        for (int x = 0; x < image_.width; ++x) {
            const float *p = image_.at(x, y);
            sum += emitted(RGB{p[0], p[1], p[2]}, lambda);
        }
    cached_mean_ = sum * (1 / (float(image_.width) * float(image_.height)));
    cached_lambda_ = lambda;
    cached_ = true;
    return cached_mean_;
}

float EmissionImage::mean_luminance() const {
    const RGB mean = image_.average();
    const auto &y = RGBColorSpace::srgb().xyz_from_rgb_matrix()[1];
    return y[0] * mean.r + y[1] * mean.g + y[2] * mean.b;
}

}  // namespace caustica
