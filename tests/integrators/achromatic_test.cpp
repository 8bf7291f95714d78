// The achromatic fast path (SceneFeatures::achromatic): which scenes qualify, and that rendering
// them at one wavelength gives the image that sampling wavelengths converges to, with no colour
// noise at all.
#include "render_test_support.h"

#include "core/error.h"
#include "parser/scene_description.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

using namespace caustica;
using namespace caustica::testing;

namespace {

const std::string Header = R"(LookAt 0 1 0.95  0 1 0  0 1 0
Camera "perspective" "float fov" [ 70 ]
Film "rgb" "integer xresolution" [ 32 ] "integer yresolution" [ 32 ]
WorldBegin
)";

// A closed grey room with a ceiling lamp, then `extra` (lights, objects).
std::string room(const std::string &extra, const std::string &walls = "\"rgb reflectance\" [ 0.8 0.8 0.8 ]") {
    return Header + R"(AttributeBegin
  AreaLightSource "diffuse" "rgb L" [ 10 10 10 ]
  Shape "trianglemesh" "integer indices" [ 0 1 2 0 2 3 ]
    "point3 P" [ -0.25 1.98 -0.25  0.25 1.98 -0.25  0.25 1.98 0.25  -0.25 1.98 0.25 ]
AttributeEnd
)" + extra + "Material \"diffuse\" " + walls + R"(
Shape "trianglemesh"
  "integer indices" [ 0 1 2 0 2 3  4 5 6 4 6 7  8 9 10 8 10 11  12 13 14 12 14 15  16 17 18 16 18 19  20 21 22 20 22 23 ]
  "point3 P" [ -1 0 -1  -1 0 1  1 0 1  1 0 -1   -1 2 -1  1 2 -1  1 2 1  -1 2 1
               -1 0 -1  1 0 -1  1 2 -1  -1 2 -1  -1 0 1  -1 2 1  1 2 1  1 0 1
               -1 0 -1  -1 2 -1  -1 2 1  -1 0 1  1 0 -1  1 0 1  1 2 1  1 2 -1 ]
)";
}

std::unique_ptr<Scene> build(const std::string &text, RenderOverrides overrides = {}) {
    set_warnings_enabled(false);
    return build_scene(parse_scene_string(text), overrides);
}

const std::string GlassBall = R"(AttributeBegin
  Material "dielectric" "float eta" [ 1.5 ]
  Translate 0.3 0.35 -0.3
  Shape "sphere" "float radius" [ 0.3 ]
AttributeEnd
)";

TEST(AchromaticScene, GreyMaterialsUnderLightsOfOneColourQualify) {
    // Two lights of the colour space's white at different strengths, a clear glass ball, a grey
    // fog: every spectrum is flat but the lights', which are multiples of one another.
    auto scene = build(room(GlassBall + "LightSource \"point\" \"rgb I\" [ 0.3 0.3 0.3 ] \"point3 from\" [ 0 1 0 ]\n"));
    EXPECT_TRUE(scene->features.achromatic);
    // Traced where the lights' colour (the D65 illuminant) peaks.
    EXPECT_GT(scene->achromatic_wavelength, 400.f);
    EXPECT_LT(scene->achromatic_wavelength, 500.f);
    auto blackbodies = build(Header + R"(LightSource "point" "blackbody I" [ 3000 ] "point3 from" [ 0 1 0 ]
LightSource "spot" "blackbody I" [ 3000 ] "float scale" [ 4 ] "point3 from" [ 0 2 0 ] "point3 to" [ 0 0 0 ]
Material "diffuse" "rgb reflectance" [ 0.5 0.5 0.5 ]
Shape "sphere"
)");
    EXPECT_TRUE(blackbodies->features.achromatic);
    // A light that emits nothing has no colour to disagree with, but gives none either.
    EXPECT_TRUE(build(room("LightSource \"point\" \"rgb I\" [ 0 0 0 ]"
                           " \"point3 from\" [ 0 1 0 ]\n"))
                    ->features.achromatic);
    auto dark = build(Header + R"(LightSource "point" "rgb I" [ 0 0 0 ] "point3 from" [ 0 1 0 ]
Material "diffuse" "rgb reflectance" [ 0.5 0.5 0.5 ]
Shape "sphere"
)");
    EXPECT_FALSE(dark->features.achromatic);
}

TEST(AchromaticScene, AnythingColouredOrDispersiveDisqualifies) {
    EXPECT_FALSE(build(room("", "\"rgb reflectance\" [ 0.8 0.2 0.2 ]"))->features.achromatic);
    // Lights of two colours.
    EXPECT_FALSE(build(room("LightSource \"point\" \"blackbody I\" [ 3000 ] \"point3 from\" [ 0 1 0 ]\n"))
                     ->features.achromatic);
    // A dispersive glass, a metal's spectral indices, a coloured medium.
    EXPECT_FALSE(build(room("AttributeBegin\nMaterial \"dielectric\" \"spectrum eta\" \"glass-BK7\"\n"
                            "Shape \"sphere\" \"float radius\" [ 0.2 ]\nAttributeEnd\n"))
                     ->features.achromatic);
    EXPECT_FALSE(build(room("AttributeBegin\nMaterial \"conductor\"\nShape \"sphere\" \"float radius\" [ 0.2 ]\n"
                            "AttributeEnd\n"))
                     ->features.achromatic);
    EXPECT_FALSE(build(room("MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [ 0.1 0.2 0.3 ]"
                            " \"rgb sigma_s\" [ 1 1 1 ]\nMediumInterface \"\" \"fog\"\n"
                            "AttributeBegin\nShape \"sphere\" \"float radius\" [ 0.2 ]\nAttributeEnd\n"
                            "MediumInterface \"\" \"\"\n"))
                     ->features.achromatic);
    // A grey medium keeps the scene achromatic.
    EXPECT_TRUE(build(room("MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [ 0.1 0.1 0.1 ]"
                           " \"rgb sigma_s\" [ 1 1 1 ]\nMediumInterface \"\" \"fog\"\n"
                           "AttributeBegin\nShape \"sphere\" \"float radius\" [ 0.2 ]\nAttributeEnd\n"
                           "MediumInterface \"\" \"\"\n"))
                    ->features.achromatic);
}

TEST(AchromaticScene, OverridesThatAskForWavelengthsComeFirst) {
    const std::string text = room(GlassBall);
    for (auto set : {+[](RenderOverrides &o) { o.spectral = true; }, +[](RenderOverrides &o) { o.single_wavelength = true; },
                     +[](RenderOverrides &o) { o.wavelength = 600; }}) {
        RenderOverrides overrides;
        set(overrides);
        auto scene = build(text, overrides);
        EXPECT_TRUE(scene->features.achromatic);
        EXPECT_EQ(scene->achromatic_wavelength, 0.f);
    }
}

// K renders of the room with the glass ball, per channel the sums of the image means and of
// their squares.
struct ImageMeans {
    static constexpr int K = 6;
    double sum[3] = {}, sum2[3] = {};
    RgbImage last;

    ImageMeans(const std::string &scene, const std::string &options, const std::string &out) {
        for (int k = 0; k < K; ++k) {
            EXPECT_EQ(run_caustica("render " + scene + " " + options + " --seed " + std::to_string(k + 1) +
                                   " --quiet -o " + out),
                      0);
            last = read_rgb(out);
            for (int c = 0; c < 3; ++c) {
                double mean = 0;
                for (int y = 0; y < last.height; ++y)
                    for (int x = 0; x < last.width; ++x) mean += last.at(x, y, c);
                mean /= last.width * last.height;
                sum[c] += mean;
                sum2[c] += mean * mean;
            }
        }
    }
    double mean(int c) const { return sum[c] / K; }
    double standard_error(int c) const {
        const double m = mean(c);
        return std::sqrt(std::max(0.0, (sum2[c] - K * m * m) / (K - 1)) / K);
    }
};

// The largest relative deviation of a pixel's colour (r/g and b/g) from the image's first.
double colour_spread(const RgbImage &img) {
    const double r0 = img.at(0, 0, 0) / img.at(0, 0, 1), b0 = img.at(0, 0, 2) / img.at(0, 0, 1);
    double spread = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const double g = img.at(x, y, 1);
            if (!(g > 0)) continue;
            spread = std::max({spread, std::abs(img.at(x, y, 0) / g / r0 - 1), std::abs(img.at(x, y, 2) / g / b0 - 1)});
        }
    return spread;
}

// Every integrator's image of the grey room at one wavelength must agree with its image from
// sampled wavelengths: per channel, image means over K = 6 seeds within 7 combined standard
// errors, estimated from the spread of the renders (Student's t with 5 degrees of freedom
// exceeds 7 with probability 9e-4, so a false failure among the 12 comparisons has probability
// about 1%). A film that got the colour's sensor value 3% wrong fails 9 of the 12 (checked by
// hand), and a path traced at one wavelength but weighted as four would fail all. And at
// one wavelength every pixel has the same colour (to float rounding), while sampled wavelengths
// leave per-pixel colour noise of several percent.
TEST(AchromaticRender, OneWavelengthGivesTheSampledWavelengthsImageWithoutColourNoise) {
    const std::string dir = scratch_dir("achromatic");
    const std::string scene = dir + "/room.pbrt";
    std::ofstream(scene) << room(GlassBall);
    for (const char *integrator : {"pt", "bdpt", "vcm", "sppm"}) {
        const std::string options = std::string("--integrator ") + integrator + " --spp 32";
        ImageMeans fast(scene, options, dir + "/fast.exr"), sampled(scene, options + " --spectral", dir + "/sampled.exr");
        for (int c = 0; c < 3; ++c) {
            EXPECT_GT(fast.mean(c), 0.1) << integrator;
            EXPECT_NEAR(fast.mean(c), sampled.mean(c), 7 * std::hypot(fast.standard_error(c), sampled.standard_error(c)))
                << integrator << " channel " << c;
        }
        EXPECT_LT(colour_spread(fast.last), 1e-4) << integrator;
        EXPECT_GT(colour_spread(sampled.last), 0.01) << integrator;
    }
}

} // namespace
