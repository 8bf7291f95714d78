// The photon-mapping integrators (sppm, bpm, vcm) beyond the agreement scenes: determinism
// across thread counts (splats are summed in fixed point, photons are gathered in path order),
// and their parameters on the command line.
#include "render_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace caustica::testing;

namespace {

const std::string kScene = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/transport/glass-block.pbrt";

class PhotonIntegrator : public ::testing::TestWithParam<const char *> {};

// Two renders that must agree value for value; the first must not be black (which would make
// the comparison trivial).
void expect_identical(const RgbImage &a, const RgbImage &b, const std::string &what) {
    ASSERT_EQ(a.rgb.size(), b.rgb.size()) << what;
    size_t differing = 0;
    double sum = 0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        differing += a.rgb[i] != b.rgb[i];
        sum += a.rgb[i];
    }
    EXPECT_EQ(differing, 0u) << what;
    EXPECT_GT(sum, 0) << what;
}

TEST_P(PhotonIntegrator, OneAndTwoThreadsGiveBitIdenticalImages) {
    const std::string dir = scratch_dir(std::string("photon-threads-") + GetParam());
    for (int threads : {1, 2}) {
        const std::string out = dir + "/t" + std::to_string(threads) + ".exr";
        ASSERT_EQ(run_caustica("render " + kScene + " --quiet --integrator " + GetParam() +
                               " --spp 4 --seed 5 --threads " + std::to_string(threads) + " -o " + out),
                  0);
    }
    expect_identical(read_rgb(dir + "/t1.exr"), read_rgb(dir + "/t2.exr"), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Integrators, PhotonIntegrator, ::testing::Values("sppm", "bpm", "vcm"));

// Writes the transport scene `source` to `path` with its Integrator directive replaced by
// `integrator` and its stage included from the source tree; with `sphere_as_mesh`, its sphere of
// radius 0.3 becomes the octahedron of the same radius; with `block_material`, its block's
// dielectric becomes that material (after the given Texture directives).
void write_transport_scene(const std::string &source, const std::string &integrator, const std::string &path,
                           bool sphere_as_mesh = false, const std::string &block_material = "",
                           const std::string &textures = "") {
    std::string text = read_text(source);
    if (!block_material.empty()) {
        const std::string glass = "Material \"dielectric\" \"float eta\" [ 1.5 ]";
        const size_t g = text.find(glass);
        ASSERT_NE(g, std::string::npos) << source;
        text.replace(g, glass.size(), block_material);
        text.replace(text.find("WorldBegin"), 10, "WorldBegin\n" + textures);
    }
    const size_t at = text.find("Integrator \"path\"");
    ASSERT_NE(at, std::string::npos) << source;
    text.replace(at, text.find('\n', at) - at, integrator);
    text.replace(text.find("Include \"stage.pbrt\""), 20,
                 "Include \"" + std::string(CAUSTICA_SOURCE_DIR) + "/scenes/transport/stage.pbrt\"");
    if (sphere_as_mesh) {
        const std::string sphere = "Shape \"sphere\" \"float radius\" [ 0.3 ]";
        const size_t s = text.find(sphere);
        ASSERT_NE(s, std::string::npos) << source;
        text.replace(s, sphere.size(),
                     "Shape \"trianglemesh\" \"point3 P\" [ 0.3 0 0  -0.3 0 0  0 0.3 0  0 -0.3 0  0 0 0.3  0 0 -0.3 ] "
                     "\"integer indices\" [ 0 2 4  2 1 4  1 3 4  3 0 4  2 0 5  1 2 5  3 1 5  0 3 5 ]");
    }
    std::FILE *f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
}

// vcm keeps its light vertices without their BSDFs and shades each again, from the surface hit
// it kept, when its pixel's camera path is traced ("lightvertices" "store", the default).
// "retrace" traces each pixel's light path a second time instead, from the same random numbers,
// and shades it as it goes. The connections are then the same to the rounding of the kept
// vertices' directions (about 1e-4 radians) and surface parameters (2^-17): the BSDFs rebuilt
// from them differ that little. The merges read directions rounded alike (photons and kept
// vertices encode them the same way), but the two maps visit their records in different orders.
// So each vcm value must lie within 5e-4 of the other's, relative to the larger of the value and
// 0.01; the largest difference found here is 4.2e-5 (skin block). bpm keeps no light vertex
// either way: its images must be equal value for value.
// Negative controls (one run each, then undone): giving the rebuilt light vertices 1% more
// throughput (which biases only the connections) moves values of every vcm case by 7.4e-3 to
// 2.2e-2; rebuilding the points in the fog with their direction reversed fails the fog block.
// The skin block is the glass block made of Disney's random-walk subsurface under a textured
// colour, whose interior medium is made anew at every entry (DisneyMaterial::interior_medium):
// light vertices inside it must keep that medium through the iteration, not point into the
// memory of the sample that made it (which crashed the render before the medium was kept).
TEST(PhotonIntegratorParameters, RetracedLightPathsGiveTheStoredImage) {
    const std::string dir = scratch_dir("photon-retrace");
    const std::string checks = "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" [ 4 ] "
                               "\"float vscale\" [ 4 ] \"rgb tex1\" [ 0.9 0.6 0.5 ] \"rgb tex2\" [ 0.5 0.8 0.9 ]\n";
    const std::string skin = "Material \"disney\" \"texture baseColor\" \"checks\" \"rgb scatterDistance\" [ 0.3 0.2 0.1 ]";
    for (bool sphere_as_mesh : {true, false})
        for (const char *name : {"glass-block", "fog-block", "skin-block"})
            for (const char *integrator : {"vcm", "bpm"}) {
                const bool is_skin = std::string(name) == "skin-block";
                const std::string source = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/transport/" +
                                           (is_skin ? "glass-block" : name) + ".pbrt";
                std::string images[2];
                for (const char *mode : {"store", "retrace"}) {
                    const std::string scene = dir + "/" + mode + ".pbrt", out = dir + "/" + mode + ".exr";
                    write_transport_scene(source,
                                          std::string("Integrator \"") + integrator +
                                              "\" \"integer maxdepth\" [ 8 ] \"string lightvertices\" \"" + mode + "\"",
                                          scene, sphere_as_mesh, is_skin ? skin : "", is_skin ? checks : "");
                    ASSERT_EQ(run_caustica("render " + scene + " --quiet --spp 3 --seed 7 -o " + out), 0) << mode;
                    images[mode[0] == 'r'] = out;
                }
                const std::string what = std::string(name) + " " + integrator + (sphere_as_mesh ? " (mesh)" : "");
                const RgbImage stored = read_rgb(images[0]), retraced = read_rgb(images[1]);
                if (std::string(integrator) == "bpm") {
                    expect_identical(stored, retraced, what);
                    continue;
                }
                ASSERT_EQ(stored.rgb.size(), retraced.rgb.size());
                double sum = 0;
                for (size_t i = 0; i < stored.rgb.size(); ++i) {
                    ASSERT_NEAR(stored.rgb[i], retraced.rgb[i], 5e-4 * std::max(0.01f, std::abs(retraced.rgb[i])))
                        << what << " value " << i;
                    sum += retraced.rgb[i];
                }
                EXPECT_GT(sum, 0) << what;
            }
}

// Kept light vertices name their surfaces by one 32-bit index over every placed shape
// (GeometryScene::pack). A scene placing 2^32 shapes (here 2^16 instances of an object of 2^16
// spheres, under the floor, out of the light's reach) cannot: vcm says so and traces its light
// paths again, as "retrace" does, so the two images are the same value for value. Negative
// control (one run, then undone): keeping the vertices regardless fails the "store" render.
TEST(PhotonIntegratorParameters, ScenesTooLargeToPackTheirHitsRetraceTheirLightPaths) {
    const std::string dir = scratch_dir("photon-unpackable");
    std::string objects = "ObjectBegin \"dots\"\n";
    for (int i = 0; i < (1 << 16); ++i) objects += "Shape \"sphere\" \"float radius\" [ 0.01 ]\n";
    objects += "ObjectEnd\nAttributeBegin\nTranslate 0 0 -5\n";
    for (int i = 0; i < (1 << 16); ++i) objects += "ObjectInstance \"dots\"\n";
    objects += "AttributeEnd\n";
    std::string images[2], notes[2];
    for (const char *mode : {"store", "retrace"}) {
        const int m = mode[0] == 'r';
        const std::string scene = dir + "/" + mode + ".pbrt";
        images[m] = dir + "/" + mode + ".exr";
        notes[m] = dir + "/" + mode + ".txt";
        std::ofstream(scene) << "LookAt 0 -3 2  0 0 0  0 0 1\nCamera \"perspective\" \"float fov\" [ 45 ]\n"
                                "Film \"rgb\" \"integer xresolution\" [ 16 ] \"integer yresolution\" [ 12 ]\n"
                                "Integrator \"vcm\" \"string lightvertices\" \""
                             << mode << "\"\nWorldBegin\n"
                                "LightSource \"point\" \"point3 from\" [ 0 0 2 ] \"blackbody I\" [ 3000 ]\n"
                             << objects
                             << "Material \"diffuse\"\n"
                                "Shape \"bilinearmesh\" \"point3 P\" [ -4 -4 0 4 -4 0 -4 4 0 4 4 0 ]\n"
                                "Shape \"sphere\" \"float radius\" [ 0.5 ]\n";
        ASSERT_EQ(run_caustica("render " + scene + " --spp 2 --seed 5 -o " + images[m], notes[m]), 0) << mode;
    }
    EXPECT_NE(read_text(notes[0]).find("traced again"), std::string::npos) << read_text(notes[0]);
    EXPECT_EQ(read_text(notes[1]).find("traced again"), std::string::npos) << read_text(notes[1]);
    expect_identical(read_rgb(images[0]), read_rgb(images[1]), "store on an unpackable scene");
}

// The film's "maxcomponentvalue" clamps samples, not sppm's photon density estimates (pbrt-v4's
// sppm clamps neither): the caustic under a glass ball, rendered with a clamp of 100 that no
// camera sample's direct light reaches at this seed and size, must be the image with no clamp
// that acts at all (1e30; both films clamp, so both draw the same wavelengths), value for value.
// Negative control (one run, then undone): clamping each iteration's photon sum at a visible
// point as a sample, as sppm once did, changes 42 of the image's 9216 values.
TEST(PhotonIntegratorParameters, TheClampLeavesSppmPhotonEstimatesAlone) {
    const std::string dir = scratch_dir("sppm-clamp");
    const std::string source = read_text(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/glass-sphere-caustic.pbrt");
    const char *clamps[] = {"1e30", "100"};
    std::string images[2];
    for (int i = 0; i < 2; ++i) {
        const std::string clamp = clamps[i];
        std::string text = source;
        const size_t at = text.find("Film \"rgb\"");
        ASSERT_NE(at, std::string::npos);
        text.insert(at + 10, " \"float maxcomponentvalue\" " + clamp);
        const std::string scene = dir + "/clamp-" + clamp + ".pbrt", out = dir + "/clamp-" + clamp + ".exr";
        std::FILE *f = std::fopen(scene.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fwrite(text.data(), 1, text.size(), f);
        std::fclose(f);
        ASSERT_EQ(run_caustica("render " + scene + " --quiet --integrator sppm --spp 16 --seed 3 --resolution 64x48 -o " +
                               out),
                  0)
            << clamp;
        images[i] = out;
    }
    expect_identical(read_rgb(images[0]), read_rgb(images[1]), "sppm under a clamp that no sample reaches");
}

// Parameters are checked where they are read: an out-of-range value is an error at its location
// in the scene file (exit status 2, nothing written).
TEST(PhotonIntegratorParameters, OutOfRangeValuesAreErrorsAtTheirLocation) {
    const std::string dir = scratch_dir("photon-parameters");
    const std::string cases[][2] = {
        {"\"vcm\" \"float alpha\" [ 1.5 ]", "alpha"},
        {"\"vcm\" \"integer wavelengthgroups\" [ 0 ]", "wavelengthgroups"},
        {"\"bpm\" \"float radius\" [ -1 ]", "radius"},
        {"\"sppm\" \"string photonsearch\" [ \"octree\" ]", "photonsearch"},
        {"\"sppm\" \"integer photonsperiteration\" [ 0 ]", "photonsperiteration"},
        {"\"vcm\" \"string lightvertices\" [ \"discard\" ]", "lightvertices"},
        // Photons keep path lengths in 15 bits.
        {"\"vcm\" \"integer maxdepth\" [ 40000 ]", "maxdepth"},
        {"\"sppm\" \"integer maxdepth\" [ 40000 ]", "maxdepth"},
    };
    for (const auto &c : cases) {
        const std::string scene = dir + "/scene.pbrt";
        write_transport_scene(kScene, "Integrator " + c[0], scene);
        const std::string err = dir + "/err.txt", out = dir + "/out.exr";
        EXPECT_EQ(run_caustica("render " + scene + " --quiet --spp 1 -o " + out, err), 2) << c[0];
        const std::string message = read_text(err);
        EXPECT_NE(message.find("scene.pbrt:"), std::string::npos) << message;
        EXPECT_NE(message.find(c[1]), std::string::npos) << message;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
}

} // namespace

namespace {

// Writes the Cornell box with its area light replaced by `lights` (scene directives).
std::string cornell_box_lit_by(const std::string &dir, const std::string &name, const std::string &lights) {
    std::string text = read_text(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt");
    const size_t begin = text.find("AttributeBegin\n  AreaLightSource");
    const size_t end = text.find("AttributeEnd", begin);
    EXPECT_NE(begin, std::string::npos);
    text.replace(begin, end + std::string("AttributeEnd").size() - begin, lights);
    const std::string path = dir + "/" + name + ".pbrt";
    std::FILE *f = std::fopen(path.c_str(), "wb");
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
    return path;
}

double image_mean(const RgbImage &img) {
    double sum = 0;
    for (float v : img.rgb) sum += v;
    return sum / double(img.rgb.size());
}

// Every light type starts light paths: the Cornell box lit by a point and a spot light, and
// by an environment and a distant light (entering through the open front), rendered at one
// wavelength (so that only transport is compared) by the photon integrators and by the path
// tracer, at 64x64. The photon integrators are biased low near the box's edges and corners,
// where part of the gather disk leaves the surface (the classic boundary bias of density
// estimation; at 64x64 the default radius is about 2% of the box's width): the ratios were
// 0.974 to 1.006 when this was written (the test prints them), against 0.996 to 1.001 at
// 128x128 with half that radius. The 4% bound is loose for that reason, yet a light type whose
// light paths were missing or misweighted (its merged or light-traced share lost or doubled)
// moves the mean by tens of percent.
TEST(PhotonIntegratorLights, EveryLightTypeAgreesWithThePathTracer) {
    const std::string dir = scratch_dir("photon-lights");
    const std::string scenes[] = {
        cornell_box_lit_by(dir, "point-spot",
                           "LightSource \"point\" \"point3 from\" [0 1.6 0] \"blackbody I\" [4000] \"float scale\" [3]\n"
                           "LightSource \"spot\" \"point3 from\" [0.5 1.7 0.5] \"point3 to\" [0 0 0] \"rgb I\" [2 2 2]"
                           " \"float coneangle\" [30]\n"),
        cornell_box_lit_by(dir, "environment-distant",
                           "LightSource \"infinite\" \"rgb L\" [0.5 0.6 0.8]\n"
                           "LightSource \"distant\" \"point3 from\" [1 3 2] \"point3 to\" [0 0 0] \"rgb L\" [2 2 2]\n"),
    };
    for (const std::string &scene : scenes) {
        auto render = [&](const std::string &integrator, int spp) {
            const std::string out = dir + "/" + integrator + ".exr";
            EXPECT_EQ(run_caustica("render " + scene + " --quiet --resolution 64x64 --wavelength 550 --integrator " + integrator +
                                   " --spp " + std::to_string(spp) + " --seed 3 -o " + out),
                      0);
            return image_mean(read_rgb(out));
        };
        const double reference = render("pt", 256);
        for (const char *integrator : {"sppm", "bpm", "vcm"}) {
            const double mean = render(integrator, 64);
            std::printf("%s on %s: mean / path tracer's = %.4f\n", integrator, scene.c_str(), mean / reference);
            EXPECT_NEAR(mean / reference, 1.0, 0.04) << integrator << " on " << scene;
        }
    }
}

} // namespace
