// What `caustica compare` measured, and the files that report it: convergence.csv,
// results.json, convergence.svg and index.html in the output directory (image paths inside them
// are relative to it).
#pragma once

#include "cli/commands.h"

#include <cstdint>
#include <string>
#include <vector>

namespace caustica {

// One render of the comparison: one integrator at one time budget.
struct ComparisonRun {
    std::string integrator;
    double budget_seconds = 0;
    double seconds = 0;                 // wall time the render actually took
    int samples_per_pixel = 0;          // iterations for the light tracer and its kin
    uint64_t rays = 0, non_finite_samples = 0;
    ImageDifference error;              // against the comparison's reference
    bool is_reference = false;          // this run is the reference (no --reference given)
    std::string image, png, error_png;  // relative paths: images/<integrator>-<budget>s.exr, ...
};

struct Comparison {
    std::string scene_path;
    std::string date;                   // local time, ISO 8601
    int width = 0, height = 0;
    uint64_t seed = 0;
    int threads = 0;
    double time_limit = 0;
    std::vector<std::string> integrators;
    std::vector<double> budgets;        // ascending
    std::string reference_description;  // the --reference file, or which run served as reference
    std::string reference_png;          // relative path of the reference shown in index.html
    std::vector<ComparisonRun> runs;    // integrator by integrator, budgets ascending
};

// The error images map log10 of each pixel's relative error to the colour map of
// error_colour_map.h over this range (values outside are clamped to its ends).
constexpr double kErrorImageLog10Min = -3, kErrorImageLog10Max = 0;

// Relative MSE levels of the "time to reach" table.
constexpr double kRelativeMseLevels[] = {1e-1, 3e-2, 1e-2, 3e-3, 1e-3};

// The budget of the first (shortest) non-reference run of `integrator` whose relative MSE is
// at or below `level`; negative when none reaches it.
double budget_to_reach(const Comparison &comparison, const std::string &integrator, double level);

// The report files; std::runtime_error when one cannot be written.
void write_convergence_csv(const std::string &path, const Comparison &comparison);
void write_results_json(const std::string &path, const Comparison &comparison);
void write_convergence_svg(const std::string &path, const Comparison &comparison);
void write_index_html(const std::string &path, const Comparison &comparison);

} // namespace caustica
