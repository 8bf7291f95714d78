// `caustica render --checkpoint SECONDS` and `--resume`: a render killed (SIGKILL) after a
// checkpoint, or stopped by SIGINT, and then resumed, writes exactly the image of a render that
// was never stopped; a checkpoint of a different render is refused.
//
// The expectations are independent of the code's output: the uninterrupted render of the same
// command line is the reference, and it must be matched bit for bit, since every sample's
// random numbers depend only on (pixel, sample index, seed), the film sums in order-independent
// fixed point, and photon-mapping state is saved exactly (see cli/checkpoint.h). The stopped
// renders run on one thread, the references on all: the result must not depend on it.
#include "process_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>

using namespace caustica::testing;
namespace fs = std::filesystem;

namespace {

std::string partial_attribute(const std::string &exr) {
    auto in = OIIO::ImageInput::open(exr);
    if (!in) return "";
    std::string partial = in->spec().get_string_attribute("caustica:partial");
    in->close();
    return partial;
}

// A render of a private copy of the Cornell box (so that the test can change the scene).
struct CheckpointRender {
    std::string dir, scene, out, checkpoint;
    std::vector<std::string> options; // integrator, sample count, seed, resolution

    CheckpointRender(const std::string &name, std::vector<std::string> render_options)
        : dir(scratch_dir("checkpoint-" + name)), scene(dir + "/scene.pbrt"), out(dir + "/out.exr"),
          checkpoint(out + ".checkpoint"), options(std::move(render_options)) {
        fs::copy_file(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt", scene);
    }
    std::vector<std::string> args(const std::string &output, std::vector<std::string> extra = {}) const {
        std::vector<std::string> a = {"render", scene, "-o", output};
        a.insert(a.end(), options.begin(), options.end());
        a.insert(a.end(), extra.begin(), extra.end());
        return a;
    }
    // The uninterrupted render, on all threads.
    std::string reference() const {
        const std::string path = dir + "/reference.exr";
        EXPECT_EQ(wait_for(start_caustica(args(path, {"-q"}), dir + "/reference.log")), 0)
            << read_text(dir + "/reference.log");
        return path;
    }
    // Starts the render to be stopped: on one thread, so that it runs long enough.
    pid_t start(const std::vector<std::string> &extra, const std::string &log) const {
        std::vector<std::string> e = {"--threads", "1"};
        e.insert(e.end(), extra.begin(), extra.end());
        return start_caustica(args(out, e), log);
    }
    int resume(const std::string &log, std::vector<std::string> extra = {}) const {
        extra.insert(extra.begin(), {"--resume", "-q"});
        return wait_for(start_caustica(args(out, extra), log));
    }
};

// Kills the render with SIGKILL as soon as its first checkpoint exists (--checkpoint 0: one at
// every boundary), then resumes it.
void kill_and_resume(const CheckpointRender &render) {
    const std::string reference = render.reference();
    pid_t pid = render.start({"--checkpoint", "0", "-q"}, render.dir + "/killed.log");
    ASSERT_TRUE(wait_until(pid, [&] { return fs::exists(render.checkpoint); }))
        << read_text(render.dir + "/killed.log");
    kill(pid, SIGKILL);
    ASSERT_EQ(wait_for(pid), 1000 + SIGKILL) << "the render finished before it could be killed: make it longer";
    ASSERT_TRUE(fs::exists(render.checkpoint));
    ASSERT_FALSE(fs::exists(render.out));

    EXPECT_EQ(render.resume(render.dir + "/resumed.log"), 0) << read_text(render.dir + "/resumed.log");
    EXPECT_TRUE(bit_identical(read_rgb(render.out), read_rgb(reference)));
    if (std::find(render.options.begin(), render.options.end(), "--variance") != render.options.end()) {
        EXPECT_TRUE(bit_identical(read_layer(render.out, "variance"), read_layer(reference, "variance")));
    }
    EXPECT_EQ(partial_attribute(render.out), "false");
    EXPECT_FALSE(fs::exists(render.checkpoint)) << "the checkpoint outlived the completed render";
}

TEST(Checkpoint, PathTracerKilledAndResumedMatchesTheUninterruptedRender) {
    // With the variance layer, whose moments are part of the film's state.
    kill_and_resume(CheckpointRender(
        "pt", {"--integrator", "pt", "--spp", "64", "--seed", "7", "--resolution", "32x32", "--variance"}));
}

TEST(Checkpoint, SppmKilledAndResumedMatchesTheUninterruptedRender) {
    kill_and_resume(
        CheckpointRender("sppm", {"--integrator", "sppm", "--spp", "60", "--seed", "7", "--resolution", "24x24"}));
}

TEST(Checkpoint, VcmKilledAndResumedMatchesTheUninterruptedRender) {
    kill_and_resume(
        CheckpointRender("vcm", {"--integrator", "vcm", "--spp", "60", "--seed", "7", "--resolution", "24x24"}));
}

// SIGINT in the middle of a sweep: the path tracer saves each pixel's own sample count, so the
// checkpoint taken as it stops continues exactly, although no timed checkpoint was due.
TEST(Checkpoint, PathTracerInterruptedBySigintAndResumedMatchesTheUninterruptedRender) {
    CheckpointRender render("sigint",
                            {"--integrator", "pt", "--spp", "128", "--seed", "3", "--resolution", "32x32"});
    const RgbImage reference = read_rgb(render.reference());
    const std::string log = render.dir + "/interrupted.log";
    pid_t pid = render.start({"--checkpoint", "100000"}, log);
    ASSERT_TRUE(wait_until(pid, [&] { return read_text(log).find("progress:") != std::string::npos; }))
        << read_text(log);
    kill(pid, SIGINT);
    ASSERT_EQ(wait_for(pid), 130) << read_text(log);
    EXPECT_EQ(partial_attribute(render.out), "true");
    ASSERT_TRUE(fs::exists(render.checkpoint)) << read_text(log);
    EXPECT_NE(read_text(log).find("add --resume to continue"), std::string::npos) << read_text(log);

    EXPECT_EQ(render.resume(render.dir + "/resumed.log"), 0) << read_text(render.dir + "/resumed.log");
    EXPECT_TRUE(bit_identical(read_rgb(render.out), reference));
    EXPECT_FALSE(fs::exists(render.checkpoint));
}

TEST(Checkpoint, ResumingADifferentRenderIsRefusedAndWritesNothing) {
    CheckpointRender render("mismatch", {"--integrator", "pt", "--spp", "64", "--resolution", "32x32"});
    pid_t pid = render.start({"--seed", "7", "--checkpoint", "0", "-q"}, render.dir + "/killed.log");
    ASSERT_TRUE(wait_until(pid, [&] { return fs::exists(render.checkpoint); }))
        << read_text(render.dir + "/killed.log");
    kill(pid, SIGKILL);
    ASSERT_EQ(wait_for(pid), 1000 + SIGKILL);
    const std::string saved = read_text(render.checkpoint);

    const std::string seed_log = render.dir + "/seed.log";
    EXPECT_EQ(render.resume(seed_log, {"--seed", "8"}), 2);
    EXPECT_NE(read_text(seed_log).find("seed is 7 there, 8 here"), std::string::npos) << read_text(seed_log);

    // Any change to the scene's text, even a comment, makes it another scene.
    std::FILE *scene = std::fopen(render.scene.c_str(), "a");
    ASSERT_TRUE(scene);
    std::fputs("# edited\n", scene);
    std::fclose(scene);
    const std::string scene_log = render.dir + "/scene.log";
    EXPECT_EQ(render.resume(scene_log, {"--seed", "7"}), 2);
    EXPECT_NE(read_text(scene_log).find("the scene or a file it reads has changed"), std::string::npos)
        << read_text(scene_log);

    EXPECT_FALSE(fs::exists(render.out));
    EXPECT_EQ(read_text(render.checkpoint), saved) << "a refused resume changed the checkpoint";
}

TEST(Checkpoint, ResumingWithoutACheckpointIsAnError) {
    CheckpointRender render("missing", {"--integrator", "pt", "--spp", "4", "--resolution", "8x8"});
    const std::string log = render.dir + "/resume.log";
    EXPECT_EQ(render.resume(log), 2);
    EXPECT_NE(read_text(log).find("there is no checkpoint"), std::string::npos) << read_text(log);
    EXPECT_FALSE(fs::exists(render.out));
}

} // namespace
