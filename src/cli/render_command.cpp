#include "cli/checkpoint.h"
#include "cli/commands.h"
#include "cli/process_group.h"
#include "cli/progress_reporter.h"
#include "cli/render_session.h"
#include "core/error.h"
#include "film/image_io.h"
#include "parser/scene_description.h"

#include <tbb/global_control.h>

#include <chrono>
#include <csignal>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sys/resource.h>

namespace caustica {

namespace {

bool ends_with(const std::string &s, const std::string &suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// SIGINT / SIGTERM stop the render: the handler only raises a flag (a lock-free atomic store is
// async-signal-safe); the render loop sees it within one sample and the command then writes
// what was accumulated. The handlers reset themselves, so a second signal ends the process.
std::atomic<bool> interrupt_requested{false};
volatile std::sig_atomic_t interrupt_signal = 0;

extern "C" void request_interrupt(int signal_number) {
    interrupt_signal = signal_number;
    interrupt_requested.store(true, std::memory_order_relaxed);
}

void install_interrupt_handlers() {
    struct sigaction action {};
    action.sa_handler = request_interrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

double peak_memory_mib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0; // ru_maxrss is in KiB on Linux
}

// ranks: the processes of the render; reduce_seconds: the time rank 0 spent adding up their films.
void write_stats_json(const std::string &path, const Scene &scene, const RenderStats &stats, int threads, int ranks,
                      double reduce_seconds) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write statistics to \"" + path + "\"");
    Vec2i res = scene.film->resolution();
    double rays_per_second = stats.seconds > 0 ? stats.rays / stats.seconds : 0;
    out << std::setprecision(10) << "{\n"
        << "  \"integrator\": \"" << scene.integrator_name << "\",\n"
        << "  \"resolution\": [" << res.x << ", " << res.y << "],\n"
        << "  \"threads\": " << threads << ",\n"
        << "  \"processes\": " << ranks << ",\n"
        << "  \"reduce_seconds\": " << reduce_seconds << ",\n"
        << "  \"wall_seconds\": " << stats.seconds << ",\n"
        << "  \"samples_per_pixel\": " << stats.samples_per_pixel << ",\n"
        << "  \"rays\": " << stats.rays.load() << ",\n"
        << "  \"rays_per_second\": " << rays_per_second << ",\n"
        << "  \"non_finite_samples\": " << stats.non_finite_samples.load() << ",\n"
        << "  \"partial\": " << (stats.interrupted ? "true" : "false") << ",\n"
        << "  \"stored_light_vertices\": " << stats.stored_light_vertices.load() << ",\n"
        << "  \"peak_memory_mib\": " << peak_memory_mib() << "\n"
        << "}\n";
    if (!out) throw std::runtime_error("failed writing statistics to \"" + path + "\"");
}

} // namespace

int run_render(const RenderCommandOptions &options) {
    RenderOverrides overrides;
    overrides.integrator = options.integrator;
    overrides.spp = options.spp;
    overrides.seed = options.seed;
    overrides.wavelength = options.wavelength;
    overrides.single_wavelength = options.single_wavelength;
    overrides.spectral = options.spectral;
    overrides.crop_window = options.crop_window;
    overrides.pixel_bounds = options.pixel_bounds;
    if (!options.resolution.empty()) parse_resolution(options.resolution, &overrides.width, &overrides.height);
    if (options.wavelength != 0 && (options.wavelength < LambdaMin || options.wavelength > LambdaMax))
        throw InputError("--wavelength must lie in [360, 830] nm");
    // Several processes (an MPI job) render together; rank 0 reports and writes.
    const ProcessGroup alone;
    const ProcessGroup &group = options.group ? *options.group : alone;
    const bool root = group.rank() == 0;
    const bool quiet = options.quiet || !root;

    SceneDescription description;
    RenderSession session;
    {
        SceneWarningOrder in_file_order;
        description = parse_scene_file(options.scene_path);
        session = create_render_session(description, overrides);
    }
    Scene *scene = session.scene.get();

    std::string exr_path = options.exr_path.empty() ? scene->output_filename : options.exr_path;
    std::string png_path = options.png_path;
    if (ends_with(exr_path, ".png")) {
        if (png_path.empty()) png_path = exr_path;
        exr_path.clear();
    } else if (!exr_path.empty() && !ends_with(exr_path, ".exr")) {
        throw InputError("output \"" + exr_path + "\" must end in .exr or .png");
    }
    if (exr_path.empty() && (scene->film->spectral() || scene->film->gbuffer()))
        warning(std::string("a PNG holds only the RGB image: the ") + (scene->film->spectral() ? "spectral" : "G-buffer") +
                " film's other channels are written only to an OpenEXR file (--output NAME.exr)");

    int threads = worker_thread_count(options.threads);
    tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism, threads);

    if (options.variance_layer) scene->film->enable_variance();
    install_interrupt_handlers();
    RenderBudget budget;
    budget.cancel = &interrupt_requested;
    if (group.ranks() > 1) budget.share = &group;
    budget.spp = scene->sampler->samples_per_pixel();
    budget.seconds = options.seconds;
    if (options.seconds > 0 && options.spp == 0) budget.spp = 0; // time alone decides

    // Checkpoints live next to the image (the EXR, else the PNG).
    const bool checkpointing = options.checkpoint_seconds >= 0;
    const std::string checkpoint = checkpoint_path(exr_path.empty() ? png_path : exr_path);
    RenderFingerprint fingerprint;
    if (checkpointing || options.resume)
        fingerprint = render_fingerprint(options.scene_path, description, *scene, budget, options.variance_layer);
    RenderStats stats;
    if (options.resume) {
        resume_from_checkpoint(checkpoint, fingerprint, group, session, stats);
        if (!quiet)
            std::fprintf(stderr, "resuming from %s: %d samples per pixel done%s\n", checkpoint.c_str(),
                         stats.samples_per_pixel,
                         stats.pixel_sample_counts.empty() ? "" : " (and part of the next sweep)");
    } else if (checkpointing && root && std::filesystem::exists(checkpoint)) {
        warning("replacing the checkpoint \"" + checkpoint + "\" of an earlier render (--resume continues from it)");
    }
    std::optional<CheckpointWriter> writer;
    if (checkpointing) {
        writer.emplace(checkpoint, fingerprint, options.checkpoint_seconds, session, stats, &interrupt_requested, group);
        budget.at_boundary = [&writer] { writer->at_boundary(); };
    }

    // Progress of this process's part of the render, so that its rate and the time left are
    // measured over what it did.
    const double fraction_before = budget.seconds > 0 ? std::min(1.0, stats.seconds / budget.seconds)
                                   : budget.spp > 0   ? double(stats.samples_per_pixel) / budget.spp
                                                      : 0;
    const uint64_t samples_before = stats.pixel_samples;
    ProgressReporter progress(!quiet);
    session.render(budget, stats, [&](double fraction, uint64_t samples) {
        progress.update(fraction_before < 1 ? (fraction - fraction_before) / (1 - fraction_before) : 1,
                        samples - std::min(samples, samples_before));
    });
    progress.finish();
    double reduce_seconds = 0;
    if (group.ranks() > 1) {
        group.sum(0); // every rank has finished rendering: the time below is the reduction's alone
        const auto reduce_start = std::chrono::steady_clock::now();
        group.reduce(*scene->film, stats);
        reduce_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - reduce_start).count();
        if (!root) return stats.interrupted ? 128 + int(interrupt_signal) : 0;
    }

    std::map<std::string, std::string> metadata = render_metadata(*scene, stats, options.seed, options.scene_path);
    Image image = session.image(stats, &metadata);

    if (!exr_path.empty())
        write_exr(exr_path, image, metadata, scene->film->save_fp16() ? ExrPixelType::Half : ExrPixelType::Float);
    if (!png_path.empty()) write_png(png_path, image);
    if (!options.stats_json.empty()) write_stats_json(options.stats_json, *scene, stats, threads, group.ranks(), reduce_seconds);
    // Only once the image is written: a render killed before that can still be resumed.
    if ((checkpointing || options.resume) && !stats.interrupted) std::filesystem::remove(checkpoint);

    if (stats.interrupted) {
        // Shell convention: 128 + the signal number (130 for SIGINT, 143 for SIGTERM).
        std::fprintf(stderr, "interrupted: wrote the partial image (%llu pixel samples)\n",
                     (unsigned long long)stats.pixel_samples.load());
        if (writer && writer->saved_samples_per_pixel() >= 0)
            std::fprintf(stderr, "checkpoint %s holds %d samples per pixel%s: add --resume to continue\n",
                         checkpoint.c_str(), writer->saved_samples_per_pixel(),
                         writer->saved_partial_sweep() ? " and part of the next sweep" : "");
        else if (options.resume)
            std::fprintf(stderr, "checkpoint %s is unchanged: add --resume to continue from it again\n",
                         checkpoint.c_str());
        else if (writer)
            std::fprintf(stderr, "no checkpoint was written: none was due yet, and an iteration cut short "
                                 "cannot be saved\n");
        return 128 + int(interrupt_signal);
    }
    if (!quiet) {
        std::fprintf(stderr, "rendered %d spp in %.2fs, %.2fM rays/s, %llu non-finite samples dropped\n",
                     stats.samples_per_pixel, stats.seconds,
                     stats.seconds > 0 ? stats.rays / stats.seconds / 1e6 : 0.0,
                     (unsigned long long)stats.non_finite_samples.load());
        if (!exr_path.empty()) std::fprintf(stderr, "wrote %s\n", exr_path.c_str());
        if (!png_path.empty()) std::fprintf(stderr, "wrote %s\n", png_path.c_str());
    }
    return 0;
}

} // namespace caustica
