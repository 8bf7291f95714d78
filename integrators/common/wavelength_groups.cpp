#include "integrators/common/wavelength_groups.h"

#include "core/rng.h"
#include "integrators/common/tile_renderer.h"

namespace caustica {

void WavelengthGroups::start_iteration(const Scene &scene, int iteration, size_t pixel_count,
                                       size_t light_path_count) {
    Rng rng(hash_values(seed_, iteration, 0x77a7e1e9), seed_);
    const float offset = rng.uniform();
    wavelengths_.clear();
    for (int g = 0; g < count_; ++g)
        wavelengths_.push_back(sample_wavelengths(scene, std::min((g + offset) / count_, OneMinusEpsilon)));

    group_of_pixel_.resize(pixel_count);
    for (size_t i = 0; i < pixel_count; ++i)
        group_of_pixel_[i] = uint8_t(hash_values(seed_, iteration, i) % uint64_t(count_));
    std::vector<size_t> group_start(count_ + 1, 0);
    for (size_t i = 0; i < pixel_count; ++i) ++group_start[group_of_pixel_[i] + 1];
    for (int g = 0; g < count_; ++g) group_start[g + 1] += group_start[g];
    pixels_by_group_.resize(pixel_count);
    for (size_t i = 0; i < pixel_count; ++i) pixels_by_group_[group_start[group_of_pixel_[i]]++] = uint32_t(i);
    group_of_light_path_.resize(light_path_count);
    light_paths_.assign(count_, 0);
    for (size_t i = 0; i < light_path_count; ++i) {
        // VCM pairs light path i with pixel i, so the two share a group when counts agree.
        int g = i < pixel_count ? group_of_pixel_[i] : int(hash_values(seed_, iteration, i) % uint64_t(count_));
        group_of_light_path_[i] = uint8_t(g);
        ++light_paths_[g];
    }
}

} // namespace caustica
