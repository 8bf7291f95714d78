// What `caustica compare` measured, and the files that report it: convergence.csv,
// results.json, convergence.svg and index.html in the output directory (image paths inside them
// are relative to it).
#pragma once

#include "cli/render_agreement.h"
#include "cli/two_run_noise.h"

#include <cstdint>
#include <string>
#include <vector>

namespace caustica {

// One point of the comparison: one integrator at one time budget, spent as two independent
// renders of half the budget each (seeds S and S + 1) whose average is the image measured.
struct ComparisonRun {
    std::string integrator;
    double budget_seconds = 0;
    double seconds = 0;                 // wall time both renders actually took, the average's cost
    int samples_per_pixel = 0;          // of both renders (iterations for the light tracer and its kin)
    uint64_t rays = 0, non_finite_samples = 0;
    RenderError error;                  // against the reference when given, else `estimated_error`
    RenderError estimated_error;        // from the two renders' difference (two_run_noise.h)
    std::string image, png, error_png;  // relative paths: images/<integrator>-<budget>s.exr, ...
    std::string render_a, render_b;     // the two renders: images/<integrator>-<budget>s-a.exr, -b.exr
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
    std::string reference_description;  // the --reference file, or how errors were estimated without one
    std::string reference_png;          // relative path of the reference shown in index.html; empty: none
    std::vector<ComparisonRun> runs;    // integrator by integrator, budgets ascending
    std::vector<Agreement> agreements;  // every pair of integrators at the longest budget
};

// The error images map log10 of each pixel's relative error to the colour map of
// error_colour_map.h over this range (values outside are clamped to its ends).
constexpr double kErrorImageLog10Min = -3, kErrorImageLog10Max = 0;

// Relative MSE levels of the "first to reach" table.
constexpr double kRelativeMseLevels[] = {1e-1, 3e-2, 1e-2, 3e-3, 1e-3};

// When `integrator`'s relative MSE (run.error) first reaches `level`, in seconds of render time:
// interpolated on log-log axes between the last run above the level and the first at or below
// it, as error falls as a power of time between budgets. When the shortest run is already at or
// below, its time is an upper bound (`at_most`). Negative seconds: no run reached it.
struct ReachTime {
    double seconds = -1;
    bool at_most = false;
};
ReachTime time_to_reach(const Comparison &comparison, const std::string &integrator, double level);

// The integrator that reaches `level` in the least time (the first listed on a tie); empty when
// none reaches it.
std::string first_to_reach(const Comparison &comparison, double level);

// The report files; std::runtime_error when one cannot be written.
void write_convergence_csv(const std::string &path, const Comparison &comparison);
void write_results_json(const std::string &path, const Comparison &comparison);
void write_convergence_svg(const std::string &path, const Comparison &comparison);
void write_index_html(const std::string &path, const Comparison &comparison);

} // namespace caustica
