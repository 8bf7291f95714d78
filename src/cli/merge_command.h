// `caustica merge A.exr B.exr ... -o OUT.exr`: one image from renders of parts of one frame
// (crop windows, pixel bounds) or of the same part with different seeds, as a render farm makes
// them. Each pixel is the average of the inputs that cover it, weighted by their sample counts
// (the "caustica:spp" attribute that `caustica render` writes): the mean of all their samples.
// A "variance" layer (the variance of a pixel's mean) combines as sum(w_i^2 var_i) / (sum w_i)^2,
// the variance of that weighted mean; other layers are averaged like the image.
#pragma once

#include "film/image.h"

#include <map>
#include <string>
#include <vector>

namespace caustica {

struct MergeInput {
    Image image;
    double samples_per_pixel = 0;
    std::string name; // for messages
};

struct MergeResult {
    Image image;
    // The samples behind each pixel of the result's data window: equal everywhere unless the
    // inputs' regions overlap unevenly. Pixels no input covers hold 0 (and count 0).
    double min_samples = 0, max_samples = 0;
    size_t uncovered_pixels = 0;
};

// Throws InputError when the inputs are of different frames (display windows) or have no
// positive sample count. Layers present in some inputs only are dropped, with a warning.
MergeResult merge_images(const std::vector<MergeInput> &inputs);

} // namespace caustica
