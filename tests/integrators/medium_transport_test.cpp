// Beer-Lambert transmittance through participating media, against the closed form, for every
// integrator: an absorbing block of medium between the camera and an emitter, and a camera that
// is itself inside an absorbing medium together with the emitter (issue #7's "camera inside a
// medium"). The coefficients are constant over wavelength and chosen so that the transmittance
// along every camera ray is exactly 1/2 (the narrow field of view keeps the path lengths within
// 0.1% of the axial one), so each image must be half of the same scene rendered with a clear
// medium, whatever the integrator's noise.
//
// Bound: the pixels of the central 12x12 block share one expectation, so their spread estimates
// the noise of their mean; the ratio of the two means is held to 6 of its standard errors plus
// 0.2% (the path-length spread). Light-tracing splats correlate neighbouring pixels somewhat,
// which 6 rather than 4 standard errors absorbs. A medium that is skipped (ratio 1), applied
// twice (1/4) or on the wrong side of a boundary fails by hundreds of standard errors.
#include "render_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace caustica::testing;

namespace {

struct Geometry {
    const char *name;
    // The scene with the medium's absorption coefficient left as %s.
    const char *text;
};

const Geometry AbsorbingBlock{"block", R"(
LookAt 0 0 20   0 0 0   0 1 0
Camera "perspective" "float fov" [ 4 ]
Film "rgb" "integer xresolution" [ 16 ] "integer yresolution" [ 16 ]
Integrator "path" "integer maxdepth" [ 6 ]
WorldBegin
MakeNamedMedium "absorber" "string type" "homogeneous" "spectrum sigma_a" [ %s ] "spectrum sigma_s" [ 0 ]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [ 1 1 1 ] "bool twosided" true
  Shape "bilinearmesh" "point3 P" [ -10 -10 -5   10 -10 -5   -10 10 -5   10 10 -5 ]
AttributeEnd
# A cube of side 2 whose faces only bound the medium: every camera ray crosses 2 units of it.
AttributeBegin
  MediumInterface "absorber" ""
  Material "interface"
  Shape "trianglemesh"
    "integer indices" [ 0 3 2 0 1 3 4 6 7 4 7 5 0 4 5 0 5 1 2 7 6 2 3 7 0 6 4 0 2 6 1 5 7 1 7 3 ]
    "point3 P" [ -1 -1 -1  -1 -1 1  -1 1 -1  -1 1 1  1 -1 -1  1 -1 1  1 1 -1  1 1 1 ]
AttributeEnd
)"};

const Geometry CameraInsideFog{"camera-inside", R"(
MakeNamedMedium "fog" "string type" "homogeneous" "spectrum sigma_a" [ %s ] "spectrum sigma_s" [ 0 ]
# The camera's medium is the outside medium in effect at the Camera directive.
MediumInterface "" "fog"
LookAt 0 0 5   0 0 0   0 1 0
Camera "perspective" "float fov" [ 4 ]
Film "rgb" "integer xresolution" [ 16 ] "integer yresolution" [ 16 ]
Integrator "path" "integer maxdepth" [ 6 ]
WorldBegin
# The emitter sits in the same fog (both sides), 5 units from the lens.
AttributeBegin
  MediumInterface "fog" "fog"
  AreaLightSource "diffuse" "rgb L" [ 1 1 1 ] "bool twosided" true
  Shape "bilinearmesh" "point3 P" [ -10 -10 0   10 -10 0   -10 10 0   10 10 0 ]
AttributeEnd
)"};

struct Case {
    const Geometry *geometry;
    const char *integrator;
    const char *sigma_a;  // giving transmittance 1/2 along the camera rays
};

struct BlockStatistics {
    double mean = 0, standard_error = 0;
};

BlockStatistics central_block(const RgbImage &img) {
    double sum = 0, sum_sq = 0;
    int n = 0;
    for (int y = 2; y < img.height - 2; ++y)
        for (int x = 2; x < img.width - 2; ++x)
            for (int c = 0; c < 3; ++c, ++n) {
                double v = img.at(x, y, c);
                sum += v;
                sum_sq += v * v;
            }
    BlockStatistics s;
    s.mean = sum / n;
    s.standard_error = std::sqrt(std::max(0.0, sum_sq / n - s.mean * s.mean) / n);
    return s;
}

class MediumTransmittance : public ::testing::TestWithParam<Case> {};

TEST_P(MediumTransmittance, HalvesTheImageExactly) {
    const Case &c = GetParam();
    const std::string dir = scratch_dir(std::string("medium-") + c.geometry->name + "-" + c.integrator);
    BlockStatistics stats[2];
    for (int clear = 0; clear < 2; ++clear) {
        const std::string scene = dir + (clear ? "/clear.pbrt" : "/absorbing.pbrt");
        char text[4096];
        std::snprintf(text, sizeof text, c.geometry->text, clear ? "0" : c.sigma_a);
        std::ofstream(scene) << text;
        const std::string out = dir + (clear ? "/clear.exr" : "/absorbing.exr");
        ASSERT_EQ(run_caustica("render " + scene + " --quiet --integrator " + c.integrator +
                               " --spp 64 --seed 5 -o " + out),
                  0);
        stats[clear] = central_block(read_rgb(out));
    }
    ASSERT_GT(stats[1].mean, 0.1) << "the emitter must be visible";
    const double ratio = stats[0].mean / stats[1].mean;
    const double ratio_error = ratio * std::hypot(stats[0].standard_error / stats[0].mean,
                                                  stats[1].standard_error / stats[1].mean);
    EXPECT_NEAR(ratio, 0.5, 6 * ratio_error + 0.002)
        << c.geometry->name << " " << c.integrator << ": means " << stats[0].mean << " / " << stats[1].mean;
}

std::vector<Case> cases() {
    std::vector<Case> all;
    // ln(2)/2 over the cube's 2 units, ln(2)/5 over the 5 units from the lens to the emitter.
    for (const char *integrator : {"pt", "lt", "bdpt", "sppm", "bpm", "vcm"}) {
        all.push_back({&AbsorbingBlock, integrator, "0.34657359"});
        all.push_back({&CameraInsideFog, integrator, "0.13862944"});
    }
    return all;
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, MediumTransmittance, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case> &info) {
                             std::string name = std::string(info.param.geometry->name) + "_" + info.param.integrator;
                             for (char &ch : name)
                                 if (ch == '-') ch = '_';
                             return name;
                         });

} // namespace
