// Creating lights from parameters: pbrt-v4's photometric normalisation, "power" and
// "illuminance", placement parameters and user errors.
#include "lights/light_factory.h"

#include "core/rng.h"
#include "light_test_util.h"
#include "spectral/photometric.h"
#include "spectral/color_space.h"
#include "spectral/rgb_spectrum.h"
#include "test_disk.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

using namespace caustica::testing;

struct QuietWarnings {
    QuietWarnings() { set_warnings_enabled(false); }
    ~QuietWarnings() { set_warnings_enabled(true); }
};

// The value a light's sample_li delivers at one wavelength, for a receiver at p.
float incident_at(const Light &light, Vec3f p, float lambda_nm) {
    LightSampleContext ctx{p, {}, {}};
    auto s = light.sample_li(ctx, {0.5f, 0.5f}, SampledWavelengths::fixed(lambda_nm));
    return s ? s->L[0] : 0.f;
}

// Luminance of the radiance leaving an area light towards its normal side.
double area_light_luminance(const Light &light) {
    return luminance_of([&](float l) {
        return light.L({0, 0, 0}, {0, 0, 1}, {}, {0, 0, 1}, SampledWavelengths::fixed(l))[0];
    });
}

TEST(LightFactory, WhiteRgbLightHasUnitLuminance) {
    // A point light with "rgb I [1 1 1]" at distance 1: its intensity is the sRGB illuminant
    // normalised to luminance exactly 1 (pbrt-v4: 1 cd, recorded by the sensor as Y = 1).
    auto light =
        create_light("point", Transform(), dictionary({numbers("rgb", "I", {1, 1, 1})}), {});
    ASSERT_TRUE(light);
    double Y = luminance_of([&](float l) { return incident_at(*light, {0, 0, 1}, l); });
    EXPECT_NEAR(Y, 1.0, 1e-4);

    // Default intensity: the colour space's illuminant, also luminance 1; "scale" multiplies.
    auto scaled =
        create_light("point", Transform(), dictionary({numbers("float", "scale", {3})}), {});
    EXPECT_NEAR(luminance_of([&](float l) {
                    return incident_at(*scaled, {0, 0, 1}, l);
                }),
                3.0, 1e-3);
}

TEST(LightFactory, RgbColourKeepsItsLuminanceRelativeToWhite) {
    // pbrt-v4 normalises by the illuminant only, so "rgb L [r g b]" has the luminance of that
    // RGB in sRGB: 0.2126 r + 0.7152 g + 0.0722 b (IEC 61966-2-1). The RGB-to-spectrum fit
    // reproduces colours to well under 2%.
    auto light = create_light("distant", Transform(),
                              dictionary({numbers("rgb", "L", {0.2, 0.5, 0.9})}), {});
    double expected = 0.2126 * 0.2 + 0.7152 * 0.5 + 0.0722 * 0.9;
    double Y = luminance_of([&](float l) { return incident_at(*light, {0, 0, 0}, l); });
    EXPECT_NEAR(Y, expected, 0.02 * expected);
}

TEST(LightFactory, AnySpectrumIsNormalisedToUnitLuminance) {
    for (ParsedParameter p : {numbers("blackbody", "L", {3000}), numbers("spectrum", "L", {4.5}),
                              numbers("spectrum", "L", {400, 1, 500, 3, 700, 0.5})}) {
        auto disk = std::make_shared<TestDisk>(Vec3f(), Vec3f(0, 0, 1), 1.f);
        auto lights = create_area_lights("diffuse", dictionary({p}), {disk}, {});
        ASSERT_EQ(lights.size(), 1u);
        EXPECT_NEAR(area_light_luminance(*lights[0]), 1.0, 1e-3) << p.type;
    }
}

// "power": the luminance integral of phi equals the given value (pbrt-v4's k_e factors). For an
// RGB spectrum pbrt-v4 normalises by the illuminant alone, so the power is the given value times
// the RGB's luminance (0.4997 for the colour below, within the 2% of the spectral fit).
TEST(LightFactory, PowerSetsTheEmittedPower) {
    auto phi_luminance = [](const Light &light) {
        return luminance_of([&](float l) { return light.phi(SampledWavelengths::fixed(l))[0]; });
    };
    auto point = create_light(
        "point", Transform(),
        dictionary({numbers("blackbody", "I", {2700}), numbers("float", "power", {250})}), {});
    EXPECT_NEAR(phi_luminance(*point), 250, 0.25);
    auto rgb_point = create_light(
        "point", Transform(),
        dictionary({numbers("rgb", "I", {0.3, 0.6, 0.1}), numbers("float", "power", {250})}), {});
    double rgb_luminance = 0.2126 * 0.3 + 0.7152 * 0.6 + 0.0722 * 0.1;
    EXPECT_NEAR(phi_luminance(*rgb_point), 250 * rgb_luminance, 0.02 * 250 * rgb_luminance);
    auto spot = create_light(
        "spot", Transform(),
        dictionary({numbers("float", "power", {80}), numbers("float", "coneangle", {40}),
                    numbers("float", "conedeltaangle", {10})}),
        {});
    EXPECT_NEAR(phi_luminance(*spot), 80, 0.08);
    for (bool two_sided : {false, true}) {
        std::vector<std::shared_ptr<Shape>> disks = {
            std::make_shared<TestDisk>(Vec3f(), Vec3f(0, 0, 1), 0.5f),
            std::make_shared<TestDisk>(Vec3f(3, 0, 0), Vec3f(0, 0, 1), 2.f)};
        auto lights = create_area_lights(
            "diffuse",
            dictionary({numbers("blackbody", "L", {5000}), numbers("float", "power", {40}),
                        boolean("twosided", two_sided)}),
            disks, {});
        ASSERT_EQ(lights.size(), 2u);
        // As in pbrt-v4, each shape emits the given power.
        for (const LightPtr &l : lights) EXPECT_NEAR(phi_luminance(*l), 40, 0.04);
    }
}

TEST(LightFactory, IlluminanceSetsDistantAndUniformSkyLevels) {
    // Distant light: the irradiance on a perpendicular surface, in luminance.
    auto distant = create_light(
        "distant", Transform(),
        dictionary({numbers("blackbody", "L", {6500}), numbers("float", "illuminance", {5})}), {});
    EXPECT_NEAR(luminance_of([&](float l) {
                    return incident_at(*distant, {0, 0, 0}, l);
                }),
                5, 5e-3);

    // Uniform sky: irradiance pi L on an upward surface.
    auto sky = create_light("infinite", Transform(),
                            dictionary({numbers("float", "illuminance", {2})}), {});
    double L = luminance_of([&](float l) {
        return sky->Le({{}, {0, 0, 1}}, SampledWavelengths::fixed(l))[0];
    });
    EXPECT_NEAR(Pi * L, 2, 2e-3);
}

TEST(LightFactory, PlacementFollowsFromToAndTheTransform) {
    // Point: "from" inside the light's transform.
    auto point = create_light("point", Transform::translate({1, 0, 0}),
                              dictionary({numbers("point3", "from", {0, 2, 0})}), {});
    LightSampleContext ctx{{1, 2, -3}, {}, {}};
    auto s = point->sample_li(ctx, {}, SampledWavelengths::fixed(550));
    ASSERT_TRUE(s);
    EXPECT_NEAR(distance(s->p_light, Vec3f(1, 2, 0)), 0.f, 1e-6f);

    // Spot aimed from (0,0,5) at the origin: lit below it on the axis, dark above.
    auto spot = create_light(
        "spot", Transform(),
        dictionary({numbers("point3", "from", {0, 0, 5}), numbers("point3", "to", {0, 0, 0})}), {});
    EXPECT_GT(incident_at(*spot, {0, 0, 0}, 550), 0.f);
    EXPECT_EQ(incident_at(*spot, {0, 0, 6}, 550), 0.f);
    EXPECT_GT(incident_at(*spot, {0.4f, 0, 4}, 550), 0.f);  // about 22 degrees off axis
    EXPECT_EQ(incident_at(*spot, {1.0f, 0, 4}, 550), 0.f);  // 45 degrees, outside the cone

    // Distant: light arrives from "from" - "to"; the default travels along +z.
    auto distant = create_light("distant", Transform::rotate(90, {1, 0, 0}), dictionary({}), {});
    auto d = distant->sample_li({{0, 0, 0}, {}, {}}, {}, SampledWavelengths::fixed(550));
    ASSERT_TRUE(d);
    // Towards the light: -z in light space, rotated 90 degrees about x to +y.
    EXPECT_NEAR(distance(d->wi, Vec3f(0, 1, 0)), 0.f, 1e-6f);
}

TEST(LightFactory, ReportsUserErrors) {
    QuietWarnings quiet;
    EXPECT_THROW(create_light("sun", Transform(), dictionary({}), {}), InputError);
    // The image lights need their image.
    EXPECT_THROW(create_light("goniometric", Transform(), dictionary({}), {}), InputError);
    EXPECT_THROW(create_light("projection", Transform(), dictionary({}), {}), InputError);
    EXPECT_THROW(create_area_lights("glowing", dictionary({}), {}, {}), InputError);
    EXPECT_THROW(create_area_lights("diffuse",
                                    dictionary({numbers("rgb", "L", {1, 1, 1}), text("string", "filename", "glow.png")}),
                                    {}, {}),
                 InputError);
    EXPECT_THROW(create_area_lights("diffuse", dictionary({text("string", "filename", "no-such-image.png")}), {}, {}),
                 InputError);
    EXPECT_THROW(create_light("spot", Transform(),
                              dictionary({numbers("point3", "from", {1, 1, 1}),
                                          numbers("point3", "to", {1, 1, 1})}),
                              {}),
                 InputError);
    EXPECT_THROW(
        create_light("spot", Transform(), dictionary({numbers("float", "coneangle", {-3})}), {}),
        InputError);
    // A missing image is an error at the "filename" parameter.
    try {
        create_light("infinite", Transform(),
                     dictionary({text("string", "filename", "no-such-sky.exr")}, "/nonexistent"),
                     {});
        FAIL() << "expected an InputError";
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 8);
        EXPECT_NE(e.message().find("no-such-sky.exr"), std::string::npos);
    }
}

}  // namespace
}  // namespace caustica
