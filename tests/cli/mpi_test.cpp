// `mpirun -np N caustica render ...`: the ranks share the samples (pt, lt, bdpt) or the
// iterations (bpm, vcm), or each iteration's pixels and photons (sppm), and rank 0 writes the
// sum of their films. Since every sample's random numbers depend only on (pixel, sample index,
// seed) and the film sums in fixed point, the image must equal a one-process render of the same
// command line bit for bit, whatever N: the one-process render is the reference, so nothing
// here depends on the code's own output. N = 4 runs oversubscribed on a 2-core machine; with 3
// samples or iterations, some ranks of bpm and vcm render nothing and hold no store.
//
// A rank that dies ends the job with a message naming it, and the last checkpoint (one state
// per rank) remains: resumed with the same N, the render gives the uninterrupted image; resumed
// with another N, or damaged, it is refused.
#include "process_test_support.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <dirent.h>
#include <filesystem>
#include <fstream>

using namespace caustica::testing;
namespace fs = std::filesystem;

#ifdef CAUSTICA_MPIEXEC

namespace {

// mpirun as the test runs it: oversubscribed, and allowed to run as root (CI's containers do).
pid_t start_mpirun(int ranks, std::vector<std::string> args, const std::string &log) {
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    args.insert(args.begin(), {"--oversubscribe", "-np", std::to_string(ranks), CAUSTICA_BINARY});
    return start_process(CAUSTICA_MPIEXEC, std::move(args), log);
}

std::vector<std::string> render_args(const std::string &scene, const std::string &integrator, const std::string &out,
                                     std::vector<std::string> extra = {}) {
    std::vector<std::string> a = {"render", scene, "--integrator", integrator, "--spp", "3", "--seed", "3",
                                  "--resolution", "40x32", "-q", "-o", out};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
}

struct RankCase {
    std::string scene, integrator;
    std::vector<std::string> extra;
};

class MpiRender : public ::testing::TestWithParam<RankCase> {};

TEST_P(MpiRender, EveryRankCountGivesTheOneProcessImage) {
    const RankCase &c = GetParam();
    const std::string dir = scratch_dir("mpi-" + c.integrator + (c.extra.empty() ? "" : "-layers"));
    const std::string scene = std::string(CAUSTICA_SOURCE_DIR) + "/" + c.scene;
    const std::string reference = dir + "/one.exr";
    ASSERT_EQ(wait_for(start_caustica(render_args(scene, c.integrator, reference, c.extra), dir + "/one.log")), 0)
        << read_text(dir + "/one.log");
    for (int ranks : {1, 2, 4}) {
        const std::string out = dir + "/ranks" + std::to_string(ranks) + ".exr";
        std::vector<std::string> extra = c.extra;
        extra.insert(extra.end(), {"--threads", "1"});
        const std::string log = dir + "/ranks" + std::to_string(ranks) + ".log";
        ASSERT_EQ(wait_for(start_mpirun(ranks, render_args(scene, c.integrator, out, extra), log)), 0) << read_text(log);
        EXPECT_TRUE(bit_identical(read_rgb(out), read_rgb(reference))) << ranks << " ranks";
        if (!c.extra.empty()) {
            EXPECT_TRUE(bit_identical(read_layer(out, "variance"), read_layer(reference, "variance")));
        }
    }
}

// Media, glass and photons in a refractive medium; a spectral film and the variance layer.
INSTANTIATE_TEST_SUITE_P(
    Integrators, MpiRender,
    ::testing::Values(RankCase{"scenes/transport/medium-glass-block.pbrt", "pt", {}},
                      RankCase{"scenes/transport/medium-glass-block.pbrt", "lt", {}},
                      RankCase{"scenes/transport/medium-glass-block.pbrt", "bdpt", {}},
                      RankCase{"scenes/transport/medium-glass-block.pbrt", "sppm", {}},
                      RankCase{"scenes/transport/medium-glass-block.pbrt", "bpm", {}},
                      RankCase{"scenes/transport/medium-glass-block.pbrt", "vcm", {}},
                      RankCase{"scenes/film/spectral.pbrt", "pt", {"--variance"}}),
    [](const ::testing::TestParamInfo<RankCase> &info) {
        return info.param.integrator + (info.param.extra.empty() ? "" : "SpectralFilmWithVariance");
    });

// The processes mpirun started (its children).
std::vector<pid_t> children_of(pid_t parent) {
    std::vector<pid_t> children;
    DIR *proc = opendir("/proc");
    while (dirent *entry = proc ? readdir(proc) : nullptr) {
        const pid_t pid = std::atoi(entry->d_name);
        if (pid <= 0) continue;
        std::ifstream stat("/proc/" + std::string(entry->d_name) + "/stat");
        std::string line;
        std::getline(stat, line);
        // pid (comm) state ppid ...: the command may hold spaces, so read after the last ')'.
        const size_t close = line.rfind(')');
        if (close == std::string::npos) continue;
        char state = 0;
        int ppid = 0;
        if (std::sscanf(line.c_str() + close + 1, " %c %d", &state, &ppid) == 2 && ppid == parent)
            children.push_back(pid);
    }
    if (proc) closedir(proc);
    return children;
}

TEST(Mpi, ARankThatDiesEndsTheJobAndItsCheckpointResumesToTheUninterruptedImage) {
    const std::string dir = scratch_dir("mpi-killed");
    const std::string scene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt";
    auto args = [&](const std::string &out, std::vector<std::string> extra) {
        std::vector<std::string> a = {"render", scene, "--integrator", "bdpt", "--spp", "96", "--seed", "5",
                                      "--resolution", "48x48", "-q", "-o", out, "--threads", "1"};
        a.insert(a.end(), extra.begin(), extra.end());
        return a;
    };
    const std::string reference = dir + "/reference.exr", out = dir + "/out.exr", checkpoint = out + ".checkpoint";
    ASSERT_EQ(wait_for(start_caustica(args(reference, {}), dir + "/reference.log")), 0);

    const pid_t mpirun = start_mpirun(2, args(out, {"--checkpoint", "0"}), dir + "/killed.log");
    ASSERT_TRUE(wait_until(mpirun, [&] { return fs::exists(checkpoint); })) << read_text(dir + "/killed.log");
    std::vector<pid_t> ranks = children_of(mpirun);
    ASSERT_FALSE(ranks.empty()) << "mpirun's processes were not found";
    kill(ranks.back(), SIGKILL);
    const int status = wait_for(mpirun);
    ASSERT_NE(status, 0) << "the job finished before a rank could be killed: make the render longer";
    EXPECT_NE(read_text(dir + "/killed.log").find("signal 9"), std::string::npos)
        << "no message names the rank that died:\n" << read_text(dir + "/killed.log");
    ASSERT_TRUE(fs::exists(checkpoint));
    ASSERT_FALSE(fs::exists(out));

    // Another number of ranks cannot continue it.
    EXPECT_EQ(wait_for(start_caustica(args(out, {"--checkpoint", "0", "--resume"}), dir + "/alone.log")), 2);
    EXPECT_NE(read_text(dir + "/alone.log").find("resume with the same number of MPI ranks"), std::string::npos)
        << read_text(dir + "/alone.log");

    // A damaged copy is refused on every rank, with no rank left waiting.
    const std::string good = dir + "/good.checkpoint";
    fs::copy_file(checkpoint, good);
    fs::resize_file(checkpoint, fs::file_size(checkpoint) / 2);
    EXPECT_NE(wait_for(start_mpirun(2, args(out, {"--checkpoint", "0", "--resume"}), dir + "/damaged.log")), 0);
    EXPECT_NE(read_text(dir + "/damaged.log").find("is damaged"), std::string::npos) << read_text(dir + "/damaged.log");
    ASSERT_FALSE(fs::exists(out));
    fs::copy_file(good, checkpoint, fs::copy_options::overwrite_existing);

    ASSERT_EQ(wait_for(start_mpirun(2, args(out, {"--checkpoint", "0", "--resume"}), dir + "/resumed.log")), 0)
        << read_text(dir + "/resumed.log");
    EXPECT_TRUE(bit_identical(read_rgb(out), read_rgb(reference)));
    EXPECT_FALSE(fs::exists(checkpoint));
}

} // namespace

#else

TEST(Mpi, BuiltWithoutMpi) {
    GTEST_SKIP() << "caustica was built without MPI (scripts/setup.sh installs Open MPI; CMake then finds it)";
}

#endif
