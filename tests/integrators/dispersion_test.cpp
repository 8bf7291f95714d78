// Dispersion as the camera sees it through a prism (scenes/prism-dispersion.pbrt): rendered
// monochromatically at 450 and 650 nm, the thin emissive line behind the prism lands where
// Snell's law with N-BK7's Sellmeier indices predicts, each within 2 pixels.
#include "prism_prediction.h"
#include "render_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>
#include <cmath>
#include <optional>

using namespace caustica::testing;

namespace {

TEST(Dispersion, PrismSpreadsTheLineWhereSnellsLawPredicts) {
    std::string dir = scratch_dir("prism");
    const std::string scene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/prism-dispersion.pbrt";
    double predicted_blue = predicted_column(450), predicted_red = predicted_column(650);
    // The prediction itself must separate the colours by far more than the tolerance, or the
    // test could not tell a dispersive renderer from one that ignores dispersion.
    ASSERT_GT(predicted_blue - predicted_red, 8.0);
    for (auto [lambda, expected] : {std::pair{450, predicted_blue}, std::pair{650, predicted_red}}) {
        std::string out = dir + "/" + std::to_string(lambda) + ".exr";
        ASSERT_EQ(run_caustica("render " + scene + " --quiet --spp 16 --seed 1 --wavelength " +
                               std::to_string(lambda) + " -o " + out),
                  0);
        const RgbImage img = read_rgb(out);
        double column = measured_column(img.width, [&](int x, int y) { return img.at(x, y, 1); });
        EXPECT_NEAR(column, expected, 2.0) << lambda << " nm";
    }
}

} // namespace
