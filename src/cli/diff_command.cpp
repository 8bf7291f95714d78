// `caustica diff A.exr B.exr`: error metrics of image A against reference B.
#include "cli/commands.h"
#include "core/error.h"
#include "film/image_io.h"

#include <cmath>
#include <cstdio>

namespace caustica {

ImageDifference image_difference(const Image &image, const Image &reference) {
    if (image.width != reference.width || image.height != reference.height)
        throw InputError("images differ in size: " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + " against " + std::to_string(reference.width) +
                         "x" + std::to_string(reference.height));
    double squared = 0, relative_squared = 0, relative = 0;
    const size_t n = image.rgb.size();
    for (size_t i = 0; i < n; ++i) {
        double x = image.rgb[i], r = reference.rgb[i];
        // The 0.01 keeps black reference pixels from dominating (the convention of the pbrt-v4
        // timings in shared/reference/README.md, so figures compare directly).
        squared += (x - r) * (x - r);
        relative_squared += (x - r) * (x - r) / (r * r + 0.01);
        relative += std::abs(x - r) / (std::abs(r) + 0.01);
    }
    return {std::sqrt(squared / n), relative_squared / n, relative / n};
}

int run_diff(const DiffCommandOptions &options) {
    Image image, reference;
    try {
        image = read_exr(options.image_path);
        reference = read_exr(options.reference_path);
    } catch (const std::runtime_error &e) {
        throw InputError(e.what());
    }
    ImageDifference d = image_difference(image, reference);
    std::printf("rmse %.6g\nrelmse %.6g\nmean_relative_difference %.6g\n", d.rmse, d.relative_mse,
                d.mean_relative_difference);
    if (options.threshold >= 0 && d.relative_mse > options.threshold) {
        std::fprintf(stderr, "relative MSE %.6g exceeds the threshold %.6g\n", d.relative_mse, options.threshold);
        return 1;
    }
    return 0;
}

} // namespace caustica
