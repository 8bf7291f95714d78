// The realistic camera's lens system against closed forms (a thick lens's back focal length, the
// plane of focus of paraxial rays), its exit-pupil bounds and ray weights against a brute-force
// integral over the rear element, its aperture masks, and its bad input. Its images are checked
// against pbrt-v4's in tests/integrators/camera_witness_test.cpp.
#include "camera/camera_factory.h"
#include "camera/realistic_camera.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace caustica;

namespace {

// scenes/cameras/lenses/triplet-60mm.dat.
const std::vector<float> kTriplet = {22.0f, 3.5f, 1.62f, 20, -400.0f, 4.0f, 1, 20, -30.0f, 1.2f, 1.62f, 15,
                                     20.0f,  3.0f, 1,     15, 0,        3.0f, 0, 12, 80.0f,   3.0f, 1.62f, 16,
                                     -25.0f, 0,    1,     16};

LensSystem lens_from(const std::vector<float> &values, double stop_mm = 1e3) {
    bool clamped = false;
    return LensSystem::from_description(values, stop_mm, &clamped);
}

// Where a ray in the x-z plane crosses the optical axis.
double axis_crossing(const LensRay &ray) { return ray.o.z - ray.o.x / ray.d.x * ray.d.z; }

TEST(LensSystem, ThickLensFocusedAtInfinityPutsTheFilmAtItsBackFocalLength) {
    // A biconvex lens, R1 = 50 mm, R2 = -50 mm, 5 mm thick, n = 1.5: the thick lensmaker's
    // equation gives 1/f = (n - 1) (1/R1 - 1/R2 + (n - 1) d / (n R1 R2)), and the back focal
    // length is f (1 - (n - 1) d / (n R1)).
    LensSystem lens = lens_from({50, 5, 1.5f, 20, -50, 0, 1, 20});
    lens.focus(1e6, 0.035);
    const double n = 1.5, r1 = 0.05, r2 = -0.05, d = 0.005;
    const double f = 1 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * d / (n * r1 * r2)));
    const double back_focal_length = f * (1 - (n - 1) * d / (n * r1));
    EXPECT_NEAR(lens.rear_z() / back_focal_length, 1, 1e-4);
}

TEST(LensSystem, ParaxialRaysFromTheFilmCentreMeetInThePlaneOfFocus) {
    for (double focus : {0.25, 0.4, 2.0}) {
        LensSystem lens = lens_from(kTriplet);
        lens.focus(focus, 0.035);
        for (double height : {2e-5, 5e-5, 1e-4}) {
            const Vec3d film{0, 0, 0}, rear{height, 0, lens.rear_z()};
            std::optional<LensRay> out = lens.trace_from_film({film, rear - film});
            ASSERT_TRUE(out) << focus;
            EXPECT_NEAR(axis_crossing(*out) / focus, 1, 2e-3) << "focus " << focus << ", height " << height;
        }
    }
}

TEST(LensSystem, TracingBackFromTheSceneRetracesTheRayFromTheFilm) {
    LensSystem lens = lens_from(kTriplet, 8);
    lens.focus(0.4, 0.035);
    const Vec3d film{0.004, -0.003, 0}, rear{0.001, 0.0015, lens.rear_z()};
    std::optional<LensRay> out = lens.trace_from_film({film, rear - film});
    ASSERT_TRUE(out);
    std::optional<LensRay> back = lens.trace_from_scene({out->o + out->d * 0.1, -out->d});
    ASSERT_TRUE(back);
    // The returning ray leaves the rear element along the reversed first segment.
    const Vec3d d0 = normalize(rear - film), d1 = normalize(back->d);
    EXPECT_NEAR(dot(d0, d1), -1, 1e-9);
    const double t = (0 - back->o.z) / back->d.z;
    const Vec3d hit = back->o + back->d * t;
    EXPECT_NEAR(hit.x, film.x, 1e-9);
    EXPECT_NEAR(hit.y, film.y, 1e-9);
}

TEST(LensSystem, ApertureDiameterAboveTheStopsIsClamped) {
    bool clamped = false;
    LensSystem lens = LensSystem::from_description(kTriplet, 20, &clamped);
    EXPECT_TRUE(clamped);
    EXPECT_DOUBLE_EQ(lens.interfaces()[4].aperture_radius, 0.006);
    lens = LensSystem::from_description(kTriplet, 4, &clamped);
    EXPECT_FALSE(clamped);
    EXPECT_DOUBLE_EQ(lens.interfaces()[4].aperture_radius, 0.002);
}

// The expected weight of the camera's rays from a film point is the irradiance the pupil sends
// there per unit radiance, the integral over the rear element's plane of cos^4(theta) / d^2 where
// a ray passes. A brute-force Riemann sum over the whole square that the pupil search covers
// must match the camera's estimate over its pupil bounds: bounds that cut off part of the pupil,
// or a weight with the wrong area, would not.
TEST(RealisticCamera, RayWeightsIntegrateThePupilsIrradiance) {
    LensSystem lens = lens_from(kTriplet, 10);
    lens.focus(0.4, 0.035);
    const FilmExtent film = FilmExtent::whole_image({64, 48});
    const RealisticCamera camera(Transform(), film, lens, std::nullopt);
    const SampledWavelengths lambda = SampledWavelengths::fixed(550);
    const int n = 256;
    for (Vec2f raster : {Vec2f{32, 24}, Vec2f{50, 10}, Vec2f{2, 46}}) {
        double camera_sum = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                CameraSample s;
                s.p_film = raster;
                s.p_lens = {(i + 0.5f) / n, (j + 0.5f) / n};
                if (std::optional<CameraRay> r = camera.generate_ray(s, lambda)) camera_sum += r->weight[0];
            }
        const double camera_estimate = camera_sum / (double(n) * n);

        // The same film point in the camera's coordinates (the film is 35 mm across its diagonal).
        const double aspect = 48.0 / 64, width = std::sqrt(0.035 * 0.035 / (1 + aspect * aspect));
        const Vec3d p_film{-(-width / 2 + width * raster.x / 64), -aspect * width / 2 + aspect * width * raster.y / 48, 0};
        const double extent = 1.5 * lens.rear_radius();
        const int m = 1024;
        double brute_sum = 0;
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                const Vec3d rear{-extent + 2 * extent * (i + 0.5) / m, -extent + 2 * extent * (j + 0.5) / m, lens.rear_z()};
                if (!lens.trace_from_film({p_film, rear - p_film})) continue;
                const double c = normalize(rear - p_film).z;
                brute_sum += c * c * c * c;
            }
        const double brute = brute_sum * (2 * extent) * (2 * extent) / (double(m) * m) / (lens.rear_z() * lens.rear_z());
        EXPECT_GT(brute, 0);
        EXPECT_NEAR(camera_estimate / brute, 1, 0.01) << raster.x << ", " << raster.y;
    }
}

TEST(RealisticCamera, CentreRayLooksAlongTheView) {
    LensSystem lens = lens_from(kTriplet, 1);
    lens.focus(0.4, 0.035);
    const RealisticCamera camera(Transform(), FilmExtent::whole_image({64, 48}), lens, std::nullopt);
    CameraSample s;
    s.p_film = {32, 24};
    s.p_lens = {0.5f, 0.5f};
    std::optional<CameraRay> r = camera.generate_ray(s, SampledWavelengths::fixed(550));
    ASSERT_TRUE(r);
    EXPECT_GT(r->ray.d.z, 0.9999f);
    // A film point right of the centre looks left: the lens turns the image over, and raster x
    // runs against camera x, so that the picture is upright (as in pbrt-v4).
    s.p_film = {60, 24};
    r = camera.generate_ray(s, SampledWavelengths::fixed(550));
    ASSERT_TRUE(r);
    EXPECT_GT(r->ray.d.x, 0.05f);
}

TEST(ApertureMask, BuiltinShapesLetThroughAsMuchAsTheRoundStop) {
    for (const char *name : {"gaussian", "square", "pentagon", "star"}) {
        std::optional<ApertureMask> mask = ApertureMask::builtin(name);
        ASSERT_TRUE(mask) << name;
        double sum = 0;
        const int n = 512;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) sum += mask->value({(i + 0.5f) / n, (j + 0.5f) / n});
        EXPECT_NEAR(sum / (n * n), Pi / 4, 2e-3) << name;
    }
    EXPECT_FALSE(ApertureMask::builtin("hexagon"));
    // pbrt-v4's star has its points on the unit circle at odd multiples of 36 degrees (one at
    // -x) and its inner corners at radius cos 72 / cos 36 at even multiples.
    const ApertureMask star = *ApertureMask::builtin("star");
    auto at = [&](float radius, float degrees) {
        const float a = radians(degrees);
        return star.value({0.5f + 0.5f * radius * std::cos(a), 0.5f + 0.5f * radius * std::sin(a)});
    };
    const float inner = std::cos(radians(72)) / std::cos(radians(36));
    for (int i = 0; i < 10; ++i) {
        if (i % 2 == 1) EXPECT_GT(at(0.9f, 36.f * i), 0) << i;
        else EXPECT_EQ(at(inner + 0.08f, 36.f * i), 0) << i;
    }
    // The pentagon's vertex points along -y of the stop (pbrt-v4 flips its aperture images).
    const ApertureMask pentagon = *ApertureMask::builtin("pentagon");
    EXPECT_GT(pentagon.value({0.5f, 0.5f - 0.37f}), 0);
    EXPECT_EQ(pentagon.value({0.5f, 0.5f + 0.37f}), 0);
    EXPECT_EQ(pentagon.value({-0.1f, 0.5f}), 0);
}

// An image's top row is the stop's +y, as pbrt-v4 reads it (it flips every aperture image):
// scenes/cameras/apertures/crescent.png has its bite at x 0.5, y 0.25 of the stop's radius, y up.
TEST(ApertureMask, ImageTopIsTheStopsPlusY) {
    const ApertureMask crescent =
        ApertureMask::from_image(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cameras/apertures/crescent.png");
    auto at = [&](float x, float y) { return crescent.value({(x + 1) / 2, (y + 1) / 2}); };
    EXPECT_EQ(at(0.5f, 0.25f), 0);
    EXPECT_GT(at(0.5f, -0.25f), 0);
    EXPECT_GT(at(-0.5f, 0.25f), 0);
    // An 8-bit image's normalised values are clipped at 1, as in pbrt-v4.
    EXPECT_FLOAT_EQ(at(0, 0), 1);
}

struct TempFile {
    std::string path;
    explicit TempFile(const std::string &name, const std::string &text)
        : path((std::filesystem::temp_directory_path() / name).string()) {
        std::ofstream(path) << text;
    }
    ~TempFile() { std::filesystem::remove(path); }
};

ParsedParameter param(const std::string &type, const std::string &name, std::vector<double> numbers,
                      std::vector<std::string> strings = {}) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.numbers = std::move(numbers);
    p.strings = std::move(strings);
    p.loc = SourceLocation{"scene.pbrt", 5, int(name.size())};
    return p;
}

std::string camera_error(std::vector<ParsedParameter> params) {
    try {
        create_camera("realistic", Transform(), FilmExtent::whole_image({16, 16}),
                      ParameterDictionary(std::move(params), SourceLocation{"scene.pbrt", 5, 1}, nullptr, "."),
                      SourceLocation{"scene.pbrt", 5, 1});
    } catch (const InputError &e) {
        return e.what();
    }
    return "";
}

TEST(CameraFactory, RealisticCameraRejectsBadInputAtItsParameter) {
    const TempFile good("caustica-good-lens.dat", "# a biconvex lens\n50 5 1.5 20\n0 2 0 10\n-50 0 1 20\n");
    const TempFile odd("caustica-odd-lens.dat", "50 5 1.5 20\n-50 0 1\n");
    const TempFile words("caustica-word-lens.dat", "50 5 glass 20\n");
    EXPECT_EQ(camera_error({param("string", "lensfile", {}, {good.path})}), "");
    EXPECT_NE(camera_error({}).find("scene.pbrt:5:1: error: the \"realistic\" camera needs"), std::string::npos);
    EXPECT_NE(camera_error({param("string", "lensfile", {}, {odd.path})}).find("scene.pbrt:5:8: error: a lens description holds four values"),
              std::string::npos);
    EXPECT_NE(camera_error({param("string", "lensfile", {}, {words.path})}).find("\"glass\" is not a finite number"),
              std::string::npos);
    EXPECT_NE(camera_error({param("string", "lensfile", {}, {"/nonexistent/lens.dat"})}).find("cannot open lens file"),
              std::string::npos);
    // A plane of focus nearer than four focal lengths from the film has no real image.
    EXPECT_NE(camera_error({param("string", "lensfile", {}, {good.path}), param("float", "focusdistance", {0.1})})
                  .find("scene.pbrt:5:13: error: the lens cannot focus"),
              std::string::npos);
    EXPECT_NE(camera_error({param("string", "lensfile", {}, {good.path}), param("float", "aperturediameter", {-1})})
                  .find("\"aperturediameter\" must be positive"),
              std::string::npos);
    EXPECT_NE(camera_error({param("string", "lensfile", {}, {good.path}), param("string", "aperture", {}, {"/nonexistent.png"})})
                  .find("\"aperture\" is neither"),
              std::string::npos);
}

} // namespace
