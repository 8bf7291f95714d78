// Wavelength groups for spectral photon mapping and VCM.
//
// A connection or a merge joins a camera subpath to a light subpath, which is only meaningful
// when both carry the same wavelengths. Sharing one wavelength set per iteration across the
// whole image (pbrt-v4's SPPM) is exact but makes colour noise frame-wide: every pixel of an
// iteration is tinted the same way. Here each iteration splits its pixels at random into
// `count` groups. A group has its own hero wavelength set; a pixel's camera path and the light
// path traced for that pixel both use their group's set, and merges only gather photons of the
// same group, normalised by the group's own light-path count. (In VCM the light path traced
// for a pixel belongs to the pixel's group, so that the two can also be connected.) Each pixel's wavelengths are
// therefore distributed exactly as hero sampling prescribes (the estimator stays unbiased),
// while neighbouring pixels usually carry different sets.
//
// The groups' hero wavelengths are stratified: group g draws its hero from the g-th of `count`
// equal slices of the sampling distribution, offset by one random number per iteration.
#pragma once

#include "spectral/sampled_wavelengths.h"

#include <cstdint>
#include <vector>

namespace caustica {

class Scene;

class WavelengthGroups {
  public:
    WavelengthGroups(int count, uint64_t seed) : count_(count), seed_(seed) {}

    // Draws the groups' wavelengths for an iteration and assigns each of pixel_count pixels
    // and light_path_count light paths to a group (the same count for VCM, one light path per
    // pixel; photon mapping may trace any number).
    void start_iteration(const Scene &scene, int iteration, size_t pixel_count, size_t light_path_count);

    int count() const { return count_; }
    int group_of_pixel(size_t pixel_index) const { return group_of_pixel_[pixel_index]; }
    int group_of_light_path(size_t path_index) const { return group_of_light_path_[path_index]; }
    const SampledWavelengths &wavelengths(int group) const { return wavelengths_[group]; }
    // Light paths traced with the group's wavelengths this iteration.
    size_t light_path_count(int group) const { return light_paths_[group]; }
    // The pixel indices of group 0, then of group 1, ..., each group's in increasing order.
    const std::vector<uint32_t> &pixels_by_group() const { return pixels_by_group_; }

  private:
    int count_;
    uint64_t seed_;
    std::vector<uint8_t> group_of_pixel_, group_of_light_path_;
    std::vector<uint32_t> pixels_by_group_;
    std::vector<SampledWavelengths> wavelengths_;
    std::vector<size_t> light_paths_;
};

} // namespace caustica
