// `caustica compare SCENE --integrators a,b,... --time T --out DIR`: renders one scene with
// several integrators at doubling time budgets, measures each render's error against a
// reference and writes images, data files, a convergence plot and an HTML report into DIR.
#include "cli/commands.h"
#include "cli/compare_report.h"
#include "cli/error_colour_map.h"
#include "cli/render_session.h"
#include "core/error.h"
#include "film/image_io.h"
#include "parser/scene_description.h"

#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <set>

namespace caustica {

namespace {

// The budgets are T/16, T/8, T/4, T/2 and T: five points spanning 1.2 decades of time, enough
// to see a convergence rate, at a total cost of just under 2T per integrator.
constexpr int kBudgetHalvings = 4;

std::vector<double> time_budgets(double limit) {
    std::vector<double> budgets;
    for (int k = kBudgetHalvings; k >= 0; --k) budgets.push_back(limit / double(1 << k));
    return budgets;
}

std::string format_number(const char *spec, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, spec, v);
    return buf;
}

// images/<integrator>-<budget>s: %g keeps budgets that differ by a factor of two distinct.
std::string image_stem(const std::string &integrator, double budget) {
    return "images/" + integrator + "-" + format_number("%g", budget) + "s";
}

std::string local_date() {
    std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M", &local);
    return buf;
}

// Every pixel's relative error, sqrt of the mean over channels of (x - r)^2 / (r^2 + 0.01) (the
// per-pixel form of image_difference's relative MSE), through the error colour map on a log10
// scale over [kErrorImageLog10Min, kErrorImageLog10Max].
Image relative_error_image(const Image &image, const Image &reference) {
    Image out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            double squared = 0;
            for (int c = 0; c < 3; ++c) {
                double v = image.at(x, y, c), r = reference.at(x, y, c);
                squared += (v - r) * (v - r) / (r * r + 0.01);
            }
            double error = std::sqrt(squared / 3);
            double t = error > 0 ? (std::log10(error) - kErrorImageLog10Min) /
                                       (kErrorImageLog10Max - kErrorImageLog10Min)
                                 : 0;
            RGB colour = error_colour(t);
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = colour[c];
        }
    return out;
}

void print_summary(const Comparison &c, const std::string &out_dir) {
    std::printf("reference: %s\n", c.reference_description.c_str());
    std::printf("%-12s %10s %9s %8s %12s %12s\n", "integrator", "budget(s)", "time(s)", "spp", "rel.MSE", "RMSE");
    for (const ComparisonRun &r : c.runs)
        std::printf("%-12s %10g %9.3f %8d %12s %12.4g\n", r.integrator.c_str(), r.budget_seconds, r.seconds,
                    r.samples_per_pixel,
                    r.is_reference ? "reference" : format_number("%.4g", r.error.relative_mse).c_str(), r.error.rmse);
    std::printf("report: %s\n", (std::filesystem::path(out_dir) / "index.html").string().c_str());
}

} // namespace

int run_compare(const CompareCommandOptions &options) {
    RenderOverrides overrides;
    overrides.seed = options.seed;
    if (!options.resolution.empty()) parse_resolution(options.resolution, &overrides.width, &overrides.height);
    if (options.integrators.empty()) throw InputError("--integrators: name at least one integrator");
    if (options.out_dir.empty()) throw InputError("--out: an output directory is needed");

    Image given_reference;
    if (!options.reference_path.empty()) {
        try {
            given_reference = read_exr(options.reference_path);
        } catch (const std::runtime_error &e) {
            throw InputError(e.what());
        }
    }

    SceneDescription description = parse_scene_file(options.scene_path);

    // Everything the user can get wrong is checked before the first render: each integrator is
    // created once (showing the scene's warnings once and each integrator's own), and the
    // reference must match the rendered size.
    Comparison comparison;
    comparison.scene_path = options.scene_path;
    comparison.date = local_date();
    comparison.seed = options.seed;
    comparison.time_limit = options.seconds;
    comparison.budgets = time_budgets(options.seconds);
    std::set<std::string> seen;
    for (size_t i = 0; i < options.integrators.size(); ++i) {
        if (options.integrators[i].empty()) throw InputError("--integrators: empty integrator name");
        RenderOverrides o = overrides;
        o.integrator = options.integrators[i];
        RenderSession session = create_render_session(description, o, {.scene = i == 0, .integrator = true});
        const std::string &name = session.scene->integrator_name;
        if (!seen.insert(name).second)
            throw InputError("--integrators: \"" + options.integrators[i] + "\" names " + name + " a second time");
        comparison.integrators.push_back(name);
        const PixelBounds &bounds = session.scene->film->pixel_bounds();
        comparison.width = bounds.width();
        comparison.height = bounds.height();
    }
    if (!options.reference_path.empty() &&
        (given_reference.width != comparison.width || given_reference.height != comparison.height))
        throw InputError("the reference \"" + options.reference_path + "\" is " +
                         std::to_string(given_reference.width) + "x" + std::to_string(given_reference.height) +
                         " but the renders are " + std::to_string(comparison.width) + "x" +
                         std::to_string(comparison.height) + " (use --resolution)");

    const std::filesystem::path out_dir(options.out_dir);
    std::filesystem::create_directories(out_dir / "images");
    comparison.threads = worker_thread_count(options.threads);
    tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism, comparison.threads);

    for (const std::string &name : comparison.integrators) {
        RenderOverrides o = overrides;
        o.integrator = name;
        for (double budget_seconds : comparison.budgets) {
            // A fresh scene per render: the film accumulates. Its warnings were shown above.
            RenderSession session = create_render_session(description, o, {.scene = false, .integrator = false});
            RenderBudget budget;
            budget.spp = 0; // time alone decides
            budget.seconds = budget_seconds;
            RenderStats stats;
            session.render(budget, stats, [](double, uint64_t) {});
            Image image = session.image(stats);

            ComparisonRun run;
            run.integrator = name;
            run.budget_seconds = budget_seconds;
            run.seconds = stats.seconds;
            run.samples_per_pixel = stats.samples_per_pixel;
            run.rays = stats.rays;
            run.non_finite_samples = stats.non_finite_samples;
            const std::string stem = image_stem(name, budget_seconds);
            run.image = stem + ".exr";
            run.png = stem + ".png";
            run.error_png = stem + "-error.png";
            write_exr((out_dir / run.image).string(), image,
                      render_metadata(*session.scene, stats, options.seed, options.scene_path));
            write_png((out_dir / run.png).string(), image);
            std::fprintf(stderr, "compare: %s, %g s budget: %d spp in %.3f s\n", name.c_str(), budget_seconds,
                         run.samples_per_pixel, run.seconds);
            comparison.runs.push_back(std::move(run));
        }
    }

    // Without --reference the first integrator's longest run is the reference: its own error
    // reads zero, and that integrator's shorter runs share their first samples with it (same
    // seed), so their errors are somewhat lower than against an independent reference.
    Image reference;
    if (!options.reference_path.empty()) {
        reference = std::move(given_reference);
        comparison.reference_description = "reference image " + options.reference_path;
        comparison.reference_png = "images/reference.png";
        write_png((out_dir / comparison.reference_png).string(), reference);
    } else {
        ComparisonRun &longest = comparison.runs[comparison.budgets.size() - 1];
        longest.is_reference = true;
        reference = read_exr((out_dir / longest.image).string());
        comparison.reference_description = "no --reference given: the longest run of the first integrator, " +
                                           longest.integrator + " at " + format_number("%g", longest.budget_seconds) +
                                           " s (" + longest.image + ")";
        comparison.reference_png = longest.png;
    }
    for (ComparisonRun &run : comparison.runs) {
        Image image = read_exr((out_dir / run.image).string());
        run.error = image_difference(image, reference);
        write_png((out_dir / run.error_png).string(), relative_error_image(image, reference));
    }

    write_convergence_csv((out_dir / "convergence.csv").string(), comparison);
    write_results_json((out_dir / "results.json").string(), comparison);
    write_convergence_svg((out_dir / "convergence.svg").string(), comparison);
    write_index_html((out_dir / "index.html").string(), comparison);
    print_summary(comparison, options.out_dir);
    return 0;
}

} // namespace caustica
