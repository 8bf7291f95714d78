// `caustica diff`: metrics against a reference and the threshold's exit status.
#include "../integrators/render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

// The metrics of an image against itself are zero; against the pbrt-v4 reference, a 16-spp
// Cornell render has a relative MSE near pbrt-v4's own 16-spp figure (0.0242 in
// shared/reference/README.md): between 0.005 and 0.1 (a wrong formula, e.g. without the square
// or the 0.01, lands far outside). The threshold turns that into an exit status.
TEST(Diff, ReportsMetricsAndHonoursTheThreshold) {
    std::string dir = scratch_dir("diff");
    std::string scene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt";
    std::string img = dir + "/img.exr", ref = data_path("reference/cornell-box.pbrt-v4.exr");
    ASSERT_EQ(run_caustica("render " + scene + " --quiet --spp 16 --seed 3 -o " + img), 0);
    std::string self = dir + "/self.txt";
    ASSERT_EQ(std::system((std::string(CAUSTICA_BINARY) + " diff " + img + " " + img + " > " + self).c_str()), 0);
    EXPECT_NE(read_text(self).find("relmse 0\n"), std::string::npos) << read_text(self);
    std::string against = dir + "/against.txt";
    ASSERT_EQ(std::system((std::string(CAUSTICA_BINARY) + " diff " + img + " " + ref + " > " + against).c_str()), 0);
    std::string text = read_text(against);
    double relmse = std::stod(text.substr(text.find("relmse ") + 7));
    EXPECT_GT(relmse, 0.005);
    EXPECT_LT(relmse, 0.1);
    EXPECT_EQ(run_caustica("diff " + img + " " + ref + " --threshold 0.001"), 1);
    EXPECT_EQ(run_caustica("diff " + img + " " + ref + " --threshold 1"), 0);
    EXPECT_EQ(run_caustica("diff " + img + " " + dir + "/missing.exr"), 2);
}

} // namespace
