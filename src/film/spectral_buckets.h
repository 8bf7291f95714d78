// The wavelength buckets of pbrt-v4's "spectral" film, and their channels in the OpenEXR
// spectral layout of Fichet et al. 2021, "An OpenEXR Layout for Spectral Images" (JCGT 10(3)).
//
// [lambda_min, lambda_max] is cut into `count` buckets of equal width. Each bucket's channel
// is named "S0.<centre>nm" with the centre printed to three decimals and its decimal point
// written as a comma (OpenEXR separates layers with points), so 16 buckets over [360, 830] give
// "S0.374,688nm" to "S0.815,312nm"; readers infer each bucket's width from its neighbours.
#pragma once

#include <string>

namespace caustica {

class SpectralBuckets {
  public:
    SpectralBuckets(int count, float lambda_min, float lambda_max)
        : count_(count), lambda_min_(lambda_min), lambda_max_(lambda_max) {}

    int count() const { return count_; }
    float lambda_min() const { return lambda_min_; }
    float lambda_max() const { return lambda_max_; }
    float width() const { return (lambda_max_ - lambda_min_) / count_; }
    // As pbrt-v4 computes it, so that channel names agree to the last digit.
    float centre(int bucket) const {
        const float t = (bucket + 0.5f) / count_;
        return (1 - t) * lambda_min_ + t * lambda_max_;
    }
    bool contains(float lambda) const { return lambda >= lambda_min_ && lambda <= lambda_max_; }
    // The bucket holding lambda, which must lie in the range.
    int bucket_of(float lambda) const {
        const int b = int(count_ * (lambda - lambda_min_) / (lambda_max_ - lambda_min_));
        return b < 0 ? 0 : b >= count_ ? count_ - 1 : b;
    }
    std::string channel_name(int bucket) const;

  private:
    int count_;
    float lambda_min_, lambda_max_;
};

} // namespace caustica
