// The subcommands of the `caustica` program. Each returns the process exit status:
// 0 success, 1 runtime failure (e.g. an image could not be written), 2 bad input.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace caustica {

class ProcessGroup;

struct RenderCommandOptions {
    std::string scene_path;
    std::string integrator;     // empty: the scene's Integrator directive
    int spp = 0;                // 0: the scene's Sampler "pixelsamples"
    double seconds = 0;         // > 0: render for this long instead of a sample count
    int threads = 0;            // 0: all cores
    uint64_t seed = 0;
    std::string resolution;     // "WxH", empty: the scene's
    std::vector<float> crop_window; // x0 x1 y0 y1, empty: the Film's
    std::vector<int> pixel_bounds;  // x0 x1 y0 y1, empty: the Film's
    std::string exr_path;       // empty: the Film "filename"
    std::string png_path;       // empty: no PNG
    std::string stats_json;     // empty: no statistics file
    float wavelength = 0;       // > 0: monochromatic render at this wavelength in nm
    bool single_wavelength = false;
    bool spectral = false;      // no achromatic fast path
    bool variance_layer = false; // add a "variance" layer to the EXR
    bool quiet = false;
    double checkpoint_seconds = -1; // >= 0: save a checkpoint at most this often (cli/checkpoint.h)
    bool resume = false;            // continue from the output's checkpoint
    // The processes rendering together (an MPI job); null: this process alone.
    const ProcessGroup *group = nullptr;
};

struct DiffCommandOptions {
    std::string image_path, reference_path;
    double threshold = -1; // >= 0: exit 1 when the relative MSE exceeds it
};

struct CompareCommandOptions {
    std::string scene_path;
    std::vector<std::string> integrators; // in the order given
    double seconds = 0;                   // the longest time budget, T
    std::string reference_path;           // empty: errors estimated from two renders per budget
    std::string out_dir;
    uint64_t seed = 0;
    std::string resolution;               // "WxH", empty: the scene's
    int threads = 0;                      // 0: all cores
};

// Error of an image against a reference, over all pixels and channels: root mean squared
// error, relative MSE (x - r)^2 / (r^2 + 0.01) and mean relative difference |x - r| / (|r| + 0.01).
struct ImageDifference {
    double rmse = 0, relative_mse = 0, mean_relative_difference = 0;
};
struct Image;
ImageDifference image_difference(const Image &image, const Image &reference);

int run_render(const RenderCommandOptions &options);
int run_diff(const DiffCommandOptions &options);

struct MergeCommandOptions {
    std::vector<std::string> input_paths;
    std::string output_path;
};
// cli/merge_command.h
int run_merge(const MergeCommandOptions &options);
int run_compare(const CompareCommandOptions &options);
int run_info(const std::string &scene_path);

} // namespace caustica
