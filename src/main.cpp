// The caustica command: `caustica render SCENE ...`, `info`, `diff`, `merge` and `compare`.
#include "cli/commands.h"
#include "cli/process_group.h"
#include "core/error.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <memory>

int main(int argc, char **argv) {
    using namespace caustica;
    // Started by mpirun (or srun), the processes render together (cli/process_group.h).
    std::unique_ptr<ProcessGroup> group;
    try {
        group = join_process_group(&argc, &argv);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    }
    const bool root = group->rank() == 0;
    CLI::App app{"Caustica: a spectral bidirectional renderer for pbrt-v4 scenes"};
    app.require_subcommand(1);

    RenderCommandOptions render;
    CLI::App *render_cmd = app.add_subcommand("render", "Render a pbrt-v4 scene file");
    render_cmd->add_option("scene", render.scene_path, "Scene file (.pbrt)")->required();
    render_cmd->add_option("--integrator", render.integrator,
                           "pt (also: path, volpath); overrides the scene's Integrator");
    auto *spp = render_cmd->add_option("--spp", render.spp, "Samples per pixel")->check(CLI::Range(1, 1 << 24));
    auto *time = render_cmd->add_option("--time", render.seconds, "Render for this many seconds")
                     ->check(CLI::Range(0.001, 1e7));
    spp->excludes(time);
    render_cmd->add_option("--threads", render.threads, "Worker threads (default: all cores)")
        ->check(CLI::Range(1, 4096));
    render_cmd->add_option("--seed", render.seed, "Random seed");
    render_cmd->add_option("--resolution", render.resolution, "Image size WxH");
    auto *crop = render_cmd->add_option("--cropwindow", render.crop_window,
                                        "Render only this part of the image: x0 x1 y0 y1 in [0, 1] (as pbrt-v4)")
                     ->expected(4);
    auto *bounds = render_cmd->add_option("--pixelbounds", render.pixel_bounds,
                                          "Render only these pixels: x0 x1 y0 y1, ends exclusive (as pbrt-v4)")
                       ->expected(4);
    crop->excludes(bounds);
    render_cmd->add_option("-o,--output", render.exr_path, "Output image (.exr, or .png)");
    render_cmd->add_option("--png", render.png_path, "Also write an 8-bit sRGB PNG here");
    render_cmd->add_option("--stats-json", render.stats_json, "Write render statistics as JSON");
    render_cmd->add_option("--wavelength", render.wavelength,
                           "Monochromatic render: radiance at this wavelength (nm) as grey");
    render_cmd->add_flag("--single-wavelength", render.single_wavelength,
                         "One wavelength per path instead of hero-wavelength sampling");
    render_cmd->add_flag("--spectral", render.spectral,
                         "Sample wavelengths even where the scene is achromatic (for comparisons)");
    render_cmd->add_flag("--variance", render.variance_layer,
                         "Add a \"variance\" layer to the EXR: each pixel's estimated variance of its mean");
    render_cmd->add_flag("-q,--quiet", render.quiet, "No progress output");
    render_cmd->add_option("--checkpoint", render.checkpoint_seconds,
                           "Save the render's state to OUT.checkpoint for --resume, at the first pause between "
                           "sweeps after each SECONDS (0: at every pause) and when interrupted")
        ->check(CLI::Range(0.0, 1e9));
    render_cmd->add_flag("--resume", render.resume,
                         "Continue from OUT.checkpoint (the same command line otherwise)");

    std::string info_scene;
    CLI::App *info_cmd = app.add_subcommand("info", "Describe what a scene contains");
    info_cmd->add_option("scene", info_scene, "Scene file (.pbrt)")->required();

    DiffCommandOptions diff;
    CLI::App *diff_cmd = app.add_subcommand("diff", "Error metrics of an EXR image against a reference");
    diff_cmd->add_option("image", diff.image_path, "Image (.exr)")->required();
    diff_cmd->add_option("reference", diff.reference_path, "Reference (.exr)")->required();
    diff_cmd->add_option("--threshold", diff.threshold, "Exit with status 1 when the relative MSE exceeds this")
        ->check(CLI::NonNegativeNumber);

    MergeCommandOptions merge;
    CLI::App *merge_cmd = app.add_subcommand(
        "merge", "Combine renders of parts of a frame, or of one part with different seeds, weighted by their "
                 "sample counts");
    merge_cmd->add_option("images", merge.input_paths, "Images written by caustica render (.exr)")->required();
    merge_cmd->add_option("-o,--output", merge.output_path, "The merged image (.exr)")->required();

    CompareCommandOptions compare;
    CLI::App *compare_cmd = app.add_subcommand(
        "compare", "Render a scene with several integrators at doubling time budgets and report their errors");
    compare_cmd->add_option("scene", compare.scene_path, "Scene file (.pbrt)")->required();
    compare_cmd->add_option("--integrators", compare.integrators, "Comma-separated integrators, e.g. pt,lt,bdpt")
        ->required()
        ->delimiter(',')
        ->allow_extra_args(false); // one list per --integrators: a scene after it is not a name
    compare_cmd->add_option("--time", compare.seconds, "Longest budget T in seconds; budgets are T/16, T/8, ..., T")
        ->required()
        ->check(CLI::Range(0.001, 1e7));
    compare_cmd->add_option("--reference", compare.reference_path,
                            "Reference image (.exr); default: none, errors are estimated from two renders per budget");
    compare_cmd->add_option("--out", compare.out_dir, "Output directory (created; files in it are replaced)")
        ->required();
    compare_cmd->add_option("--seed", compare.seed, "Random seed S: each budget renders with S and S + 1");
    compare_cmd->add_option("--resolution", compare.resolution, "Image size WxH");
    compare_cmd->add_option("--threads", compare.threads, "Worker threads (default: all cores)")
        ->check(CLI::Range(1, 4096));

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError &e) {
        int code = root ? app.exit(e) : e.get_exit_code();
        return code == 0 ? 0 : 2;
    }

    try {
        if (group->ranks() > 1 && !*render_cmd)
            throw InputError("only `caustica render` runs across the processes of an MPI job");
        render.group = group.get();
        if (*render_cmd) return run_render(render);
        if (*info_cmd) return run_info(info_scene);
        if (*diff_cmd) return run_diff(diff);
        if (*merge_cmd) return run_merge(merge);
        if (*compare_cmd) return run_compare(compare);
    } catch (const InputError &e) {
        // Every rank reads the same input, so every rank meets the same error: rank 0 reports it.
        if (root) std::fprintf(stderr, "%s\n", e.what());
        return 2;
    } catch (const std::exception &e) {
        // A failure on one rank, which the others may be waiting for: it ends the whole job.
        if (group->ranks() > 1) {
            std::fprintf(stderr, "caustica (MPI rank %d of %d): %s\n", group->rank(), group->ranks(), e.what());
            group->abort(1);
        }
        std::fprintf(stderr, "caustica: %s\n", e.what());
        return 1;
    }
    return 0;
}
