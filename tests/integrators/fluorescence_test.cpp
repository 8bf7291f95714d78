// Fluorescence (materials/fluorophore.h) in the integrators that render it, against closed forms.
//
// The scene: a fluorescent square lit straight from above by a distant light that emits only a
// 10-nm line at 365 nm (a blacklight), seen from above on a spectral film. The square covers the
// view and the reach of its pixel filter, and little more: a distant light's rays cover the
// scene's bounds, so most light paths then land in view. Its dye absorbs 90%
// below 420 nm and nothing above 450, emits a triangle from 450 to 600 nm peaking at 520, with
// quantum yield 0.8, over a substrate of reflectance 0.5. The light's "scale" cancels pbrt-v4's
// photometric normalisation, so the irradiance is the line E(lambda) itself, and the radiance
// leaving the plane is, in closed form (one bounce, Lambertian),
//
//     L(lambda) = Q e(lambda) / (pi lambda) int a(l) l E(l) dl  +  E(lambda) rho (1 - a(lambda)) / pi,
//
// the glow where the emission spectrum puts it and the line's elastic reflection at 365 nm. Each
// film bucket holds that radiance averaged over the bucket times CIE_Y_integral. pt reaches the
// glow by light sampling at wavelengths drawn from the dye's absorption, lt by re-emitting at
// wavelengths drawn from its emission: two different estimators of one closed form.
//
// The check, per bucket: the image mean over 16 independent renders against the closed form,
// z = difference / (standard error from the spread of the 16 renders' means) below 5, and the
// glow's total within 1%. Independent renders, not blocks of one image, set the standard error,
// because the photon integrators' wavelength groups share their wavelengths across the image
// (wavelength_groups.h). With 15 degrees of freedom, |t| > 5 has odds of 1.6e-4 per bucket, about
// 1% over the suite's 60 non-empty bucket checks. Power: the same check against a closed form
// 3% too bright fails.
#include "render_test_support.h"

#include "spectral/cie.h"
#include "spectral/photometric.h"
#include "spectral/spectrum.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

using namespace caustica::testing;

namespace {

constexpr double kYield = 0.8, kReflectance = 0.5, kPi = 3.14159265358979323846;
constexpr int kBuckets = 16, kSize = 32, kRuns = 16;
constexpr double kLambdaMin = 360, kLambdaMax = 830;

double line(double l) { return l < 360 || l > 370 ? 0 : 1 - std::abs(l - 365) / 5; }
double absorption(double l) { return l <= 420 ? 0.9 : l >= 450 ? 0 : 0.9 * (450 - l) / 30; }
double emission(double l) { return l < 450 || l > 600 ? 0 : l <= 520 ? (l - 450) / 70 : (600 - l) / 80; }

// The closed form above; the emission triangle's area is 75.
double radiance(double l) {
    constexpr double excitation = 0.9 * 5 * 365; // int a l E dl over the line (centroid 365 nm)
    return kYield * emission(l) / 75 / (kPi * l) * excitation + line(l) * kReflectance * (1 - absorption(l)) / kPi;
}

// The closed form of every bucket, as the spectral film scales it.
std::vector<double> expected_buckets() {
    std::vector<double> buckets(kBuckets);
    const double width = (kLambdaMax - kLambdaMin) / kBuckets, step = 0.005;
    for (int b = 0; b < kBuckets; ++b) {
        double sum = 0;
        for (double l = kLambdaMin + b * width + step / 2; l < kLambdaMin + (b + 1) * width; l += step) sum += radiance(l) * step;
        buckets[b] = sum / width * caustica::CIE_Y_integral;
    }
    return buckets;
}

std::string plane_scene(const std::string &dir) {
    const float line_knots[] = {360, 0, 365, 1, 370, 0};
    const auto uv = caustica::PiecewiseLinearSpectrum::from_interleaved(line_knots, false);
    char scale[64];
    std::snprintf(scale, sizeof scale, "%.9g", caustica::spectrum_to_photometric(*uv));
    const std::string path = dir + "/plane.pbrt";
    std::FILE *f = std::fopen(path.c_str(), "w");
    std::fprintf(f,
                 "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 20\n"
                 "Film \"spectral\" \"integer xresolution\" %d \"integer yresolution\" %d \"string filename\" \"p.exr\"\n"
                 "WorldBegin\n"
                 "LightSource \"distant\" \"point3 from\" [0 0 1] \"point3 to\" [0 0 0]\n"
                 "  \"spectrum L\" [360 0 365 1 370 0] \"float scale\" %s\n"
                 "Material \"fluorescent\" \"spectrum reflectance\" [300 0.5 900 0.5]\n"
                 "  \"spectrum absorption\" [300 0.9 420 0.9 450 0 900 0]\n"
                 "  \"spectrum emission\" [450 0 520 1 600 0] \"float quantumyield\" 0.8\n"
                 "Shape \"trianglemesh\" \"point3 P\" [-1 -1 0 1 -1 0 1 1 0 -1 1 0]\n"
                 "  \"integer indices\" [0 1 2 0 2 3]\n",
                 kSize, kSize, scale);
    std::fclose(f);
    return path;
}

// The film's buckets, in wavelength order: per bucket, every pixel's value.
std::vector<std::vector<float>> read_buckets(const std::string &path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    const OIIO::ImageSpec &spec = in->spec();
    std::vector<float> all(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw std::runtime_error("cannot read " + path);
    std::map<double, int> channels; // centre (nm) -> channel
    for (int c = 0; c < spec.nchannels; ++c) {
        const std::string &name = spec.channelnames[c];
        if (name.rfind("S0.", 0) == 0) channels[std::stod(name.substr(3))] = c;
    }
    std::vector<std::vector<float>> buckets;
    for (const auto &[centre, c] : channels) {
        std::vector<float> &values = buckets.emplace_back();
        for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i) values.push_back(all[i * spec.nchannels + c]);
    }
    return buckets;
}

struct BucketCheck {
    double worst_z = 0, glow_error = 0;
};

// The runs' buckets against `expected`, as the file's comment states.
BucketCheck check(const std::vector<std::vector<std::vector<float>>> &runs, const std::vector<double> &expected) {
    BucketCheck result;
    double glow = 0, glow_expected = 0;
    for (int b = 0; b < kBuckets; ++b) {
        std::vector<double> means; // of each run's image
        for (const auto &run : runs) {
            double sum = 0;
            for (float v : run[b]) sum += v;
            means.push_back(sum / run[b].size());
        }
        double mean = 0, variance = 0;
        for (double m : means) mean += m / means.size();
        for (double m : means) variance += (m - mean) * (m - mean) / (means.size() - 1);
        const double z = std::abs(mean - expected[b]) / std::sqrt(variance / means.size() + 1e-30);
        std::printf("bucket %2d: %.6g against %.6g (z %.2f)\n", b, mean, expected[b], z);
        result.worst_z = std::max(result.worst_z, z);
        if (b > 0) { // the glow: every bucket but the ultraviolet line's
            glow += mean;
            glow_expected += expected[b];
        }
    }
    result.glow_error = std::abs(glow - glow_expected) / glow_expected;
    std::printf("glow %.6g against %.6g (error %.2f%%)\n", glow, glow_expected, 100 * result.glow_error);
    return result;
}

class FluorescentPlane : public ::testing::TestWithParam<RenderCase> {};

TEST_P(FluorescentPlane, GlowsAsTheClosedFormPredicts) {
    const RenderCase &c = GetParam();
    const std::string dir = scratch_dir(std::string("fluorescent-plane-") + c.integrator);
    const std::string scene = plane_scene(dir);
    std::vector<std::vector<std::vector<float>>> runs;
    for (int i = 0; i < kRuns; ++i) {
        const std::string out = dir + "/run" + std::to_string(i) + ".exr";
        ASSERT_EQ(run_caustica("render " + scene + " --quiet --integrator " + c.integrator + " --spp " +
                               std::to_string(c.spp) + " --seed " + std::to_string(11 + i) + " -o " + out),
                  0);
        runs.push_back(read_buckets(out));
        ASSERT_EQ(runs.back().size(), size_t(kBuckets));
    }
    const std::vector<double> expected = expected_buckets();
    // The glow lies where the emission does: 450-600 nm holds nearly all of it.
    double inside = 0, total = 0;
    for (int b = 1; b < kBuckets; ++b) {
        const double centre = kLambdaMin + (b + 0.5) * (kLambdaMax - kLambdaMin) / kBuckets;
        (centre > 430 && centre < 620 ? inside : total) += expected[b];
    }
    ASSERT_LT(total, 1e-3 * inside);

    const BucketCheck a = check(runs, expected);
    EXPECT_LT(a.worst_z, 5.0);
    EXPECT_LT(a.glow_error, 0.01);
    std::vector<double> brighter = expected;
    for (double &v : brighter) v *= 1.03;
    const BucketCheck control = check(runs, brighter);
    EXPECT_TRUE(control.worst_z > 5.0 || control.glow_error > 0.01) << "a 3% error would pass";
}

// lt's light paths land at the wavelengths they are re-radiated at, which a film fixed at one
// wavelength does not record: --wavelength with lt is refused, with exit status 2 and a reason.
TEST(Fluorescence, LightTracingRefusesOneFixedWavelength) {
    const std::string dir = scratch_dir("fluorescent-monochromatic");
    const std::string scene = plane_scene(dir), errors = dir + "/stderr.txt";
    EXPECT_EQ(run_caustica("render " + scene + " --quiet --integrator lt --spp 1 --wavelength 520 -o " + dir +
                               "/lt.exr",
                           errors),
              2);
    EXPECT_NE(read_text(errors).find("--wavelength"), std::string::npos);
    EXPECT_EQ(run_caustica("render " + scene + " --quiet --integrator pt --spp 1 --wavelength 520 -o " + dir +
                           "/pt.exr"),
              0);
}

INSTANTIATE_TEST_SUITE_P(Integrators, FluorescentPlane,
                         ::testing::Values(RenderCase{"plane", "pt", 64}, RenderCase{"plane", "lt", 4096},
                                           RenderCase{"plane", "bdpt", 64}, RenderCase{"plane", "sppm", 64},
                                           RenderCase{"plane", "bpm", 64}, RenderCase{"plane", "vcm", 64}),
                         [](const ::testing::TestParamInfo<RenderCase> &info) { return std::string(info.param.integrator); });

} // namespace
