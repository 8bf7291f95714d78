// An area light's emission image (pbrt-v4's "filename" on AreaLightSource "diffuse"): sRGB
// values over the shape's (u, v), each emitted as the RGB illuminant spectrum of its colour.
// One image is shared by every shape of the light's Shape directive (a mesh's triangles), so
// the mean radiance that the light sampler asks each of them for is computed once.
#pragma once

#include "lights/rgb_image.h"
#include "spectral/sampled_wavelengths.h"

#include <mutex>

namespace caustica {

class EmissionImage {
  public:
    explicit EmissionImage(RGBImage image);

    // Radiance at a shape's uv (v flipped: the image's first row is v = 1), bilinear, as pbrt-v4.
    SampledSpectrum radiance(Vec2f uv, const SampledWavelengths &lambda) const;
    // The radiance averaged over the pixels, as if the image covered the shape evenly (pbrt-v4's
    // assumption in Phi). The last wavelengths asked for are remembered: the light sampler asks
    // every light of a mesh at the same ones.
    SampledSpectrum mean_radiance(const SampledWavelengths &lambda) const;
    // The mean of the pixels' luminance, for the "power" parameter (pbrt-v4 takes it in the
    // image's colour space: sRGB here).
    float mean_luminance() const;

  private:
    static SampledSpectrum emitted(RGB rgb, const SampledWavelengths &lambda);

    RGBImage image_;
    mutable std::mutex cache_mutex_;
    mutable SampledWavelengths cached_lambda_;
    mutable SampledSpectrum cached_mean_;
    mutable bool cached_ = false;
};

}  // namespace caustica
