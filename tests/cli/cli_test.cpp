// The caustica command as a user meets it: exit statuses, error messages, outputs.
#include "../integrators/render_test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace caustica::testing;
namespace fs = std::filesystem;

namespace {

const std::string kCornell = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt";

// Every malformed scene of the parser's corpus: exit status 2, a file:line:column message at
// the expected place, and no image written.
TEST(Cli, MalformedScenesExitWithStatusTwoAndWriteNothing) {
    std::string corpus = data_path("parser/malformed");
    std::ifstream manifest(corpus + "/expected.txt");
    ASSERT_TRUE(manifest) << "missing manifest in " << corpus;
    std::string dir = scratch_dir("malformed");
    int checked = 0;
    std::string line;
    while (std::getline(manifest, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream in(line);
        // scene, file the error points into, line, column, message substring
        std::string file, located_in;
        int l = 0, c = 0;
        in >> file >> located_in >> l >> c;
        std::string out = dir + "/" + file + ".exr";
        std::string err = dir + "/" + file + ".err";
        EXPECT_EQ(run_caustica("render " + corpus + "/" + file + " --spp 1 -o " + out, err), 2) << file;
        EXPECT_FALSE(fs::exists(out)) << file;
        std::string message = read_text(err);
        EXPECT_NE(message.find(fs::path(located_in).filename().string() + ":" + std::to_string(l) + ":" +
                               std::to_string(c) + ": error:"),
                  std::string::npos)
            << file << ": " << message;
        ++checked;
    }
    EXPECT_GE(checked, 30);
}

TEST(Cli, BadArgumentsExitWithStatusTwo) {
    std::string dir = scratch_dir("bad-args");
    EXPECT_EQ(run_caustica("render " + kCornell + " --spp -3 -o " + dir + "/a.exr"), 2);
    EXPECT_EQ(run_caustica("render " + kCornell + " --resolution 12by4 -o " + dir + "/a.exr"), 2);
    EXPECT_EQ(run_caustica("render " + kCornell + " --integrator nonsense -o " + dir + "/a.exr"), 2);
    EXPECT_EQ(run_caustica("render " + dir + "/missing.pbrt -o " + dir + "/a.exr"), 2);
    EXPECT_EQ(run_caustica("render " + kCornell + " --spp 1 --time 1 -o " + dir + "/a.exr"), 2);
    // Crop windows that are not numbers, empty, or incomplete.
    EXPECT_EQ(run_caustica("render " + kCornell + " --spp 1 --cropwindow nan 1 0 1 -o " + dir + "/a.exr"), 2);
    EXPECT_EQ(run_caustica("render " + kCornell + " --spp 1 --cropwindow 0.5 0.5 0 1 -o " + dir + "/a.exr"), 2);
    EXPECT_EQ(run_caustica("render " + kCornell + " --spp 1 --pixelbounds 0 10 0 -o " + dir + "/a.exr"), 2);
    EXPECT_EQ(run_caustica("merge " + dir + "/missing.exr -o " + dir + "/m.exr"), 2);
    EXPECT_EQ(run_caustica("frobnicate"), 2);
    EXPECT_FALSE(fs::exists(dir + "/a.exr"));
}

TEST(Cli, RenderWritesExrPngAndStatistics) {
    std::string dir = scratch_dir("outputs");
    std::string err = dir + "/stderr.txt";
    ASSERT_EQ(run_caustica("render " + kCornell + " --spp 2 --resolution 40x30 -o " + dir +
                               "/img.exr --png " + dir + "/img.png --stats-json " + dir + "/stats.json",
                           err),
              0);
    RgbImage exr = read_rgb(dir + "/img.exr");
    EXPECT_EQ(exr.width, 40);
    EXPECT_EQ(exr.height, 30);
    RgbImage png = read_rgb(dir + "/img.png");
    EXPECT_EQ(png.width, 40);
    for (float v : exr.rgb) ASSERT_TRUE(std::isfinite(v));
    std::string stats = read_text(dir + "/stats.json");
    for (const char *key : {"wall_seconds", "samples_per_pixel", "rays", "rays_per_second",
                            "non_finite_samples", "stored_light_vertices", "peak_memory_mib"})
        EXPECT_NE(stats.find(std::string("\"") + key + "\""), std::string::npos) << key;
    EXPECT_NE(stats.find("\"samples_per_pixel\": 2"), std::string::npos);
    // Not a terminal: plain progress lines, one per 10%, ending at 100%.
    std::string progress = read_text(err);
    EXPECT_NE(progress.find("progress: 100%"), std::string::npos) << progress;
    EXPECT_EQ(progress.find('\r'), std::string::npos);
}

TEST(Cli, TimeBudgetRendersAtLeastOneSample) {
    std::string dir = scratch_dir("time");
    ASSERT_EQ(run_caustica("render " + kCornell + " --quiet --time 0.5 --resolution 32x32 -o " + dir +
                           "/t.exr --stats-json " + dir + "/s.json"),
              0);
    std::string stats = read_text(dir + "/s.json");
    EXPECT_EQ(stats.find("\"samples_per_pixel\": 0"), std::string::npos) << stats;
}

TEST(Cli, InfoDescribesTheScene) {
    std::string dir = scratch_dir("info");
    std::string out = dir + "/info.txt";
    std::string cmd = std::string(CAUSTICA_BINARY) + " info " + std::string(CAUSTICA_SOURCE_DIR) +
                      "/scenes/glass-sphere-caustic.pbrt > " + out + " 2>/dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::string text = read_text(out);
    EXPECT_NE(text.find("triangles:        4"), std::string::npos) << text;
    EXPECT_NE(text.find("lights:           1"), std::string::npos) << text;
    EXPECT_NE(text.find("dispersive materials:      yes"), std::string::npos) << text;
    EXPECT_NE(text.find("delta-specular surfaces:   yes"), std::string::npos) << text;
}

} // namespace
