// pbrt-v4's spherical camera against pbrt-v4's images of the same files
// (scenes/cameras/spherical-*.pbrt: a cube of differently coloured glowing walls around the
// camera, with off-centre details), with the hard-transport suite's check (render_test_support.h:
// image mean within 1%, every 16x16 block and channel within |z| < 5). A mirrored, rotated or
// shifted mapping moves the walls' edges and details between blocks and fails it: negative
// control (one run, then undone), the image mirrored in x gives |z| 164
// (equirectangular) and 325 (equal area).
#include "render_test_support.h"

#include <gtest/gtest.h>

using namespace caustica::testing;

namespace {

TEST(SphericalCamera, EquirectangularMatchesPbrtV4) {
    expect_agreement_with_pbrt("cameras/spherical-equirect", "pt", 64);
}

TEST(SphericalCamera, EqualAreaMatchesPbrtV4) {
    expect_agreement_with_pbrt("cameras/spherical-equalarea", "pt", 64);
}

// Integrators that connect light paths to the lens refuse a camera without importance, at its
// Camera directive (line 5 of the file).
TEST(SphericalCamera, LightPathIntegratorsRefuseItAtTheCameraLine) {
    const std::string dir = scratch_dir("spherical-lt");
    for (const char *integrator : {"lt", "bdpt", "bpm", "vcm"}) {
        const std::string scene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cameras/spherical-equirect.pbrt";
        EXPECT_EQ(run_caustica("render " + scene + " --quiet --integrator " + integrator + " --spp 1 -o " + dir +
                                   "/a.exr",
                               dir + "/err.txt"),
                  2)
            << integrator;
        EXPECT_NE(read_text(dir + "/err.txt").find("spherical-equirect.pbrt:5:1: error"), std::string::npos)
            << integrator << ": " << read_text(dir + "/err.txt");
    }
}

} // namespace
