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
    const PbrtAgreement a = pbrt_agreement("cameras/spherical-equirect", "pt", 64);
    EXPECT_LT(a.mean_relative_error, 0.01);
    EXPECT_LT(a.worst_z, 5.0);
}

TEST(SphericalCamera, EqualAreaMatchesPbrtV4) {
    const PbrtAgreement a = pbrt_agreement("cameras/spherical-equalarea", "pt", 64);
    EXPECT_LT(a.mean_relative_error, 0.01);
    EXPECT_LT(a.worst_z, 5.0);
}

// Integrators that connect light paths to the lens refuse a camera without importance.
TEST(SphericalCamera, LightTracingRefusesIt) {
    const std::string dir = scratch_dir("spherical-lt");
    EXPECT_EQ(run_caustica("render " + std::string(CAUSTICA_SOURCE_DIR) +
                           "/scenes/cameras/spherical-equirect.pbrt --quiet --integrator lt --spp 1 -o " + dir + "/a.exr"),
              2);
}

} // namespace
