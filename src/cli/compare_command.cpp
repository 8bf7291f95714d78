// `caustica compare SCENE --integrators a,b,... --time T --out DIR`: renders one scene with
// several integrators at doubling time budgets, each budget as two independent renders whose
// difference estimates the error of their average (two_run_noise.h), or measures it against
// --reference; checks that the integrators agree within that noise (render_agreement.h); and
// writes images, data files, a convergence plot and an HTML report into DIR.
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
#include <map>
#include <optional>
#include <set>

namespace caustica {

namespace {

// The budgets are T/16, T/8, T/4, T/2 and T: five points spanning 1.2 decades of time, enough
// to see a convergence rate, at a total cost of just under 2T per integrator (each budget is
// split between its two renders).
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

// (x - r)^2 per pixel and channel.
Image squared_difference(const Image &image, const Image &reference) {
    Image out(image.width, image.height);
    for (size_t i = 0; i < out.rgb.size(); ++i) {
        const float d = image.rgb[i] - reference.rgb[i];
        out.rgb[i] = d * d;
    }
    return out;
}

// Every pixel's relative error, sqrt of the mean over channels of e / (r^2 + 0.01) for a squared
// error e (the per-pixel form of image_difference's relative MSE, or of its estimate from two
// renders), through the error colour map on a log10 scale over [kErrorImageLog10Min,
// kErrorImageLog10Max].
Image relative_error_image(const Image &squared_error, const Image &reference) {
    Image out(reference.width, reference.height);
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            double squared = 0;
            for (int c = 0; c < 3; ++c) {
                double r = reference.at(x, y, c);
                squared += squared_error.at(x, y, c) / (r * r + 0.01);
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
    std::printf("%-12s %10s %9s %8s %12s %12s %12s\n", "integrator", "budget(s)", "time(s)", "spp", "rel.MSE", "RMSE",
                "est.rel.MSE");
    for (const ComparisonRun &r : c.runs)
        std::printf("%-12s %10g %9.3f %8d %12.4g %12.4g %12.4g\n", r.integrator.c_str(), r.budget_seconds, r.seconds,
                    r.samples_per_pixel, r.error.relative_mse, r.error.rmse, r.estimated_error.relative_mse);
    if (!c.agreements.empty()) std::printf("agreement at the longest budget:\n");
    for (const Agreement &a : c.agreements) std::printf("  %s\n", agreement_sentence(a).c_str());
    std::printf("first to reach a relative MSE (log-log interpolation between budgets):\n");
    for (double level : kRelativeMseLevels) {
        const std::string first = first_to_reach(c, level);
        if (first.empty()) {
            std::printf("  <= %g: none\n", level);
            continue;
        }
        const ReachTime reach = time_to_reach(c, first, level);
        std::printf("  <= %g: %s at %s%.3g s\n", level, first.c_str(), reach.at_most ? "<= " : "", reach.seconds);
    }
    std::printf("report: %s\n", (std::filesystem::path(out_dir) / "index.html").string().c_str());
}

struct HalfRender {
    Image image;
    std::map<std::string, std::string> metadata;
};

// One of a budget's two renders, for `seconds`, written to `path`; its statistics are added to
// `run`'s.
HalfRender render_half(const SceneDescription &description, const RenderOverrides &overrides, double seconds,
                       const std::filesystem::path &path, const std::string &scene_path, ComparisonRun &run) {
    // A fresh scene per render: the film accumulates. Its warnings were shown before rendering.
    RenderSession session = create_render_session(description, overrides, {.scene = false, .integrator = false});
    RenderBudget budget;
    budget.spp = 0; // time alone decides
    budget.seconds = seconds;
    RenderStats stats;
    session.render(budget, stats, [](double, uint64_t) {});
    HalfRender half{session.image(stats), render_metadata(*session.scene, stats, overrides.seed, scene_path)};
    write_exr(path.string(), half.image, half.metadata);
    run.seconds += stats.seconds;
    run.samples_per_pixel += stats.samples_per_pixel;
    run.rays += stats.rays;
    run.non_finite_samples += stats.non_finite_samples;
    return half;
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

    std::optional<SceneWarningOrder> in_file_order(std::in_place);
    SceneDescription description = parse_scene_file(options.scene_path);
    // The two renders of a budget must be independent; a Sampler "seed" would give both the same.
    if (description.sampler.params.has("seed"))
        throw InputError(description.sampler.params.location("seed"),
                         "compare renders every budget twice, with seeds S and S + 1, to measure its noise; "
                         "this \"seed\" would override both (remove it)");

    // Everything the user can get wrong is checked before the first render: each integrator is
    // created once (showing the scene's warnings once and each integrator's own), and the
    // reference must match the rendered size. An Integrator parameter is reported unused when no
    // integrator of the comparison read it (sppm's "photonsperiteration" is no fault of pt's).
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
        RenderSession session = create_render_session(
            description, o, {.scene = i == 0, .integrator = true, .unused_integrator_parameters = false});
        description.integrator.params.add_lookups_of(session.scene->integrator_params);
        const std::string &name = session.scene->integrator_name;
        if (!seen.insert(name).second)
            throw InputError("--integrators: \"" + options.integrators[i] + "\" names " + name + " a second time");
        comparison.integrators.push_back(name);
        const PixelBounds &bounds = session.scene->film->pixel_bounds();
        comparison.width = bounds.width();
        comparison.height = bounds.height();
    }
    description.integrator.params.report_unused();
    in_file_order.reset();
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

    Image reference;
    if (!options.reference_path.empty()) {
        reference = std::move(given_reference);
        comparison.reference_description = "reference image " + options.reference_path;
        comparison.reference_png = "images/reference.png";
        write_png((out_dir / comparison.reference_png).string(), reference);
    } else {
        comparison.reference_description =
            "none given: each error is estimated from the difference of the budget's two independent renders";
    }

    // Each integrator's longest budget, for the agreement check.
    std::vector<TwoRuns> longest;
    for (const std::string &name : comparison.integrators) {
        RenderOverrides first_seed = overrides, second_seed = overrides;
        first_seed.integrator = second_seed.integrator = name;
        second_seed.seed = overrides.seed + 1;
        for (double budget_seconds : comparison.budgets) {
            ComparisonRun run;
            run.integrator = name;
            run.budget_seconds = budget_seconds;
            const std::string stem = image_stem(name, budget_seconds);
            run.image = stem + ".exr";
            run.png = stem + ".png";
            run.error_png = stem + "-error.png";
            run.render_a = stem + "-a.exr";
            run.render_b = stem + "-b.exr";

            const double half = budget_seconds / 2;
            const HalfRender a =
                render_half(description, first_seed, half, out_dir / run.render_a, options.scene_path, run);
            const HalfRender b =
                render_half(description, second_seed, half, out_dir / run.render_b, options.scene_path, run);
            TwoRuns runs(a.image, b.image);
            // The average's metadata: the first render's, with both renders' samples.
            std::map<std::string, std::string> metadata = a.metadata;
            metadata["caustica:spp"] = std::to_string(run.samples_per_pixel);
            metadata["caustica:average_of"] = run.render_a + " " + run.render_b;
            write_exr((out_dir / run.image).string(), runs.mean, metadata);
            write_png((out_dir / run.png).string(), runs.mean);

            run.estimated_error = estimated_error(runs);
            if (options.reference_path.empty()) {
                run.error = run.estimated_error;
                write_png((out_dir / run.error_png).string(),
                          relative_error_image(estimated_variance(runs), runs.mean));
            } else {
                const ImageDifference d = image_difference(runs.mean, reference);
                run.error = {d.rmse, d.relative_mse};
                write_png((out_dir / run.error_png).string(),
                          relative_error_image(squared_difference(runs.mean, reference), reference));
            }
            std::fprintf(stderr, "compare: %s, %g s budget: %d spp in %.3f s (two renders)\n", name.c_str(),
                         budget_seconds, run.samples_per_pixel, run.seconds);
            comparison.runs.push_back(std::move(run));
            if (budget_seconds == comparison.budgets.back()) longest.push_back(std::move(runs));
        }
    }
    for (size_t i = 0; i < longest.size(); ++i)
        for (size_t j = i + 1; j < longest.size(); ++j)
            comparison.agreements.push_back(check_agreement(comparison.integrators[i], longest[i],
                                                            comparison.integrators[j], longest[j]));

    write_convergence_csv((out_dir / "convergence.csv").string(), comparison);
    write_results_json((out_dir / "results.json").string(), comparison);
    write_convergence_svg((out_dir / "convergence.svg").string(), comparison);
    write_index_html((out_dir / "index.html").string(), comparison);
    print_summary(comparison, options.out_dir);
    return 0;
}

} // namespace caustica
