// Heterogeneous media (media/heterogeneous_medium.h, grid_media.h): the majorant grid's DDA, the
// voxel grid's interpolation, and delta and ratio tracking against closed forms.
//
// The closed forms come from a density that is linear along x (a + b x at the voxel centres,
// which trilinear interpolation reproduces exactly between the first and last centre): along a
// ray through the grid's middle in +x the optical depth is sigma_t (a x + b x^2 / 2) between its
// ends. Monte Carlo checks use fixed seeds and a bound of 4.5 standard errors (estimated from the
// samples themselves), exceeded by a correct implementation with probability below 1e-5 per
// check. Negative control (run once, then undone): majorants 0.6 times the grid's (no longer an
// upper bound of the density, so collisions are sampled too rarely) fail the transmittance and
// free-flight checks by 7 to 80 standard errors. (0.95 times still passes: the cells' bounds,
// the largest of the voxel values that influence them, exceed this density by more than 5%.) A
// null collision's contribution computed with the lane's majorant for every wavelength fails
// the free-flight check 22 times.
#include "medium_test_support.h"
#include "param_helpers.h"

#include "core/error.h"
#include "core/rng.h"
#include "media/cloud_medium.h"
#include "media/grid_media.h"
#include "media/medium_factory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace caustica {
namespace {

using namespace caustica::testing;


TEST(MajorantGrid, TheDdaVisitsTheCellsAlongARayInOrderWithoutGaps) {
    MajorantGrid grid(5, 3, 7);
    for (int z = 0; z < 7; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x) grid.set(x, y, z, float((z * 3 + y) * 5 + x));
    Rng rng(1, 1);
    for (int n = 0; n < 2000; ++n) {
        const Vec3f o{3 * rng.uniform() - 1, 3 * rng.uniform() - 1, 3 * rng.uniform() - 1};
        const Vec3f d = normalize(Vec3f{2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1});
        float t0, t1;
        const bool hits = clip_to_unit_cube(o, d, 0, 10, &t0, &t1);
        float expected_t = t0, covered = 0;
        int segments = 0;
        grid.traverse(o, d, 0, 10, [&](const MajorantGrid::Segment &s) {
            EXPECT_NEAR(s.t0, expected_t, 1e-5f) << "segments follow each other";
            EXPECT_GT(s.t1, s.t0);
            // The segment's midpoint lies in the cell whose bound it carries.
            const Vec3f m = o + d * (0.5f * (s.t0 + s.t1));
            const int x = std::clamp(int(m.x * 5), 0, 4), y = std::clamp(int(m.y * 3), 0, 2), z = std::clamp(int(m.z * 7), 0, 6);
            EXPECT_EQ(s.bound, grid.at(x, y, z));
            expected_t = s.t1;
            covered += s.t1 - s.t0;
            ++segments;
            return true;
        });
        if (hits) EXPECT_NEAR(covered, t1 - t0, 1e-5f);
        else EXPECT_EQ(segments, 0);
    }
}

TEST(VoxelGrid, InterpolatesTrilinearlyBetweenVoxelCentresAndFallsToZeroOutside) {
    // 2 x 2 x 2 values: pbrt-v4's layout, x fastest.
    VoxelGrid<float> grid({1, 2, 3, 4, 5, 6, 7, 8}, 2, 2, 2);
    auto value = [&](Vec3f u) { return grid.lookup(u, [](float v) { return v; }); };
    EXPECT_FLOAT_EQ(value({0.25f, 0.25f, 0.25f}), 1);
    EXPECT_FLOAT_EQ(value({0.75f, 0.25f, 0.25f}), 2);
    EXPECT_FLOAT_EQ(value({0.25f, 0.75f, 0.25f}), 3);
    EXPECT_FLOAT_EQ(value({0.25f, 0.25f, 0.75f}), 5);
    EXPECT_FLOAT_EQ(value({0.5f, 0.5f, 0.5f}), 4.5f);
    // At the box's face, half way from the outer centres to the zero samples beyond them.
    EXPECT_FLOAT_EQ(value({0.f, 0.25f, 0.25f}), 0.5f);
    // A majorant cell's bound covers every sample that influences it.
    MajorantGrid m = grid.majorants(4, [](float v) { return v; });
    EXPECT_EQ(m.at(0, 0, 0), 8) << "the corner cell is influenced by all eight samples";
    Rng rng(2, 2);
    for (int n = 0; n < 5000; ++n) {
        const Vec3f u{rng.uniform(), rng.uniform(), rng.uniform()};
        EXPECT_LE(value(u), m.at(int(u.x * 4), int(u.y * 4), int(u.z * 4)) + 1e-5f);
    }
}

// A grid whose density is a + b x at its voxel centres, in the unit cube (identity transform),
// with three equal layers in y and z, so that it is the same for every y and z in [1/6, 5/6].
constexpr int kVoxels = 10;
constexpr float kA = 0.4f, kB = 2.6f;
VoxelGrid<float> linear_density() {
    std::vector<float> values;
    for (int k = 0; k < 9; ++k)
        for (int i = 0; i < kVoxels; ++i) values.push_back(kA + kB * (i + 0.5f) / kVoxels);
    return VoxelGrid<float>(std::move(values), kVoxels, 3, 3);
}

// Integral of the density from x0 to x1.
double optical_length(double x0, double x1) { return kA * (x1 - x0) + kB * (x1 * x1 - x0 * x0) / 2; }


struct LinearGrid {
    SpectrumPtr sigma_a = std::make_shared<LinearSpectrum>(0.1f, 1.2f);
    SpectrumPtr sigma_s = std::make_shared<LinearSpectrum>(2.5f, 0.4f);
    float scale = 1.3f;
    UniformGridMedium medium{Transform(), Bounds3f{{0, 0, 0}, {1, 1, 1}}, sigma_a, sigma_s, scale, 0.f,
                             linear_density()};
    // The ray along the middle of the grid, between the first and last voxel centres.
    static constexpr float x0 = 0.5f / kVoxels, x1 = 1 - 0.5f / kVoxels;
};

TEST(UniformGridMedium, RatioTrackingEstimatesTheTransmittanceOfEachWavelength) {
    LinearGrid g;
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.35f);
    const SampledSpectrum sigma_t = (g.sigma_a->sample(lambda) + g.sigma_s->sample(lambda)) * g.scale;
    for (float length : {0.1f, 0.45f, LinearGrid::x1 - LinearGrid::x0}) {
        std::vector<RunningMean> T(NumWavelengths);
        Rng rng(3, 3);
        for (int n = 0; n < 100000; ++n) {
            // Every sample a different ray (the tracking's random numbers come from the ray): the
            // same segment in x, at a y and z where the density is the same.
            const Ray ray{{LinearGrid::x0, 0.3f + 0.4f * rng.uniform(), 0.3f + 0.4f * rng.uniform()}, {1, 0, 0}};
            const SampledSpectrum t = g.medium.transmittance(ray, length, lambda);
            for (int i = 0; i < NumWavelengths; ++i) T[i].add(t[i]);
        }
        const double tau = optical_length(LinearGrid::x0, LinearGrid::x0 + length);
        for (int i = 0; i < NumWavelengths; ++i)
            expect_mean(T[i], std::exp(-sigma_t[i] * tau), "transmittance, wavelength " + std::to_string(i), 1e-6);
    }
}

// As for the homogeneous media (medium_test.cpp): with the lane drawn uniformly and the balance
// heuristic over the lanes, f / mean_k density_k is unbiased per wavelength: E[weight; passed] =
// T(t_max) and E[weight; scattered] = integral of sigma_s T = albedo (1 - T(t_max)), the albedo
// being the same everywhere in a uniformgrid.
TEST(UniformGridMedium, DeltaTrackingIsUnbiasedPerWavelength) {
    LinearGrid g;
    for (float u : {0.1f, 0.6f}) {
        const SampledWavelengths lambda = SampledWavelengths::sample_visible(u);
        const SampledSpectrum sigma_a = g.sigma_a->sample(lambda), sigma_s = g.sigma_s->sample(lambda);
        const SampledSpectrum sigma_t = (sigma_a + sigma_s) * g.scale;
        for (float length : {0.1f, LinearGrid::x1 - LinearGrid::x0}) {
            std::vector<RunningMean> passed(NumWavelengths), scattered(NumWavelengths);
            Rng rng(4, 4);
            for (int n = 0; n < 200000; ++n) {
                const int lane = std::min(int(rng.uniform() * NumWavelengths), NumWavelengths - 1);
                const Ray ray{{LinearGrid::x0, 0.5f, 0.5f}, {1, 0, 0}};
                const MediumEvent e = g.medium.sample_distance(ray, length, lambda, lane, rng.uniform());
                const SampledSpectrum weight = e.f / e.density.average();
                ASSERT_FALSE(weight.has_non_finite());
                ASSERT_LE(e.t, length);
                for (int i = 0; i < NumWavelengths; ++i) {
                    passed[i].add(e.scattered ? 0 : weight[i]);
                    scattered[i].add(e.scattered ? weight[i] : 0);
                }
            }
            const double tau = optical_length(LinearGrid::x0, LinearGrid::x0 + length);
            for (int i = 0; i < NumWavelengths; ++i) {
                const double T = std::exp(-sigma_t[i] * tau), albedo = sigma_s[i] / (sigma_a[i] + sigma_s[i]);
                expect_mean(passed[i], T, "passed, wavelength " + std::to_string(i), 1e-6);
                expect_mean(scattered[i], albedo * (1 - T), "scattered, wavelength " + std::to_string(i), 1e-6);
            }
        }
    }
}

// Emission: at a real collision the event carries T sigma_a Le, so E[emitted / mean density] is
// the integral of T sigma_a Le along the segment. With the albedo the same everywhere and Le
// constant (a "Lescale" grid of ones, constant over the ray), that integral is
// Le sigma_a / sigma_t (1 - T(t_max)), since d(optical depth) = sigma_t dt. Negative control (run
// once, then undone): counting sigma_s instead of sigma_a fails every wavelength by over 2000
// standard errors.
TEST(UniformGridMedium, DeltaTrackingCountsTheEmissionAlongTheRay) {
    LinearGrid g;
    UniformGridEmission emission;
    emission.Le = std::make_shared<ConstantSpectrum>(2.f);
    emission.Le_scale = VoxelGrid<float>(std::vector<float>(kVoxels * 3 * 3, 1.f), kVoxels, 3, 3);
    const UniformGridMedium medium(Transform(), Bounds3f{{0, 0, 0}, {1, 1, 1}}, g.sigma_a, g.sigma_s, g.scale, 0.f,
                                   linear_density(), emission);
    ASSERT_TRUE(medium.is_emissive());
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f);
    const SampledSpectrum sigma_a = g.sigma_a->sample(lambda), sigma_t = (sigma_a + g.sigma_s->sample(lambda)) * g.scale;
    const float length = LinearGrid::x1 - LinearGrid::x0;
    std::vector<RunningMean> emitted(NumWavelengths);
    Rng rng(6, 6);
    for (int n = 0; n < 200000; ++n) {
        const int lane = std::min(int(rng.uniform() * NumWavelengths), NumWavelengths - 1);
        const Ray ray{{LinearGrid::x0, 0.5f, 0.5f}, {1, 0, 0}};
        const MediumEvent e = medium.sample_distance(ray, length, lambda, lane, rng.uniform());
        for (int i = 0; i < NumWavelengths; ++i) emitted[i].add(e.emitted[i] / e.density.average());
    }
    const double tau = optical_length(LinearGrid::x0, LinearGrid::x1);
    for (int i = 0; i < NumWavelengths; ++i) {
        const double T = std::exp(-sigma_t[i] * tau);
        expect_mean(emitted[i], 2 * sigma_a[i] * g.scale / sigma_t[i] * (1 - T), "emitted, wavelength " + std::to_string(i),
                    1e-6);
    }
}

// Where light paths start in an emissive grid: a sampled point's density is what
// emission_point_pdf reports there, and the estimate sigma_a Le / pdf integrates the emission over
// the box in render space (here stretched 2 x 3 x 1, so a unit-cube volume is 6), matching a
// midpoint sum on a fine grid (its error is far below the 4.5 standard errors of the check).
// emitted_power, the mean over 4^3 points per cell, agrees with the same sum to 1%. Negative
// control (run once, then undone): reporting the density 5% too high fails every check.
TEST(UniformGridMedium, EmissionPointsAreDrawnWithTheDensityTheyReport) {
    LinearGrid g;
    UniformGridEmission emission;
    emission.Le = std::make_shared<LinearSpectrum>(0.5f, 2.f);
    emission.Le_scale = VoxelGrid<float>(std::vector<float>(kVoxels * 3 * 3, 1.f), kVoxels, 3, 3);
    const Transform render_from_medium = Transform::translate({1, -2, 0}) * Transform::scale(2, 3, 1);
    const UniformGridMedium medium(render_from_medium, Bounds3f{{0, 0, 0}, {1, 1, 1}}, g.sigma_a, g.sigma_s, g.scale,
                                   0.f, linear_density(), emission);
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.4f);
    auto emitted = [&](Vec3f p) { return medium.properties(p, lambda).sigma_a * medium.Le(p, lambda); };
    std::vector<RunningMean> integral(NumWavelengths);
    Rng rng(7, 7);
    for (int n = 0; n < 200000; ++n) {
        const std::optional<EmissionPoint> e =
            medium.sample_emission_point(rng.uniform(), {rng.uniform(), rng.uniform(), rng.uniform()});
        ASSERT_TRUE(e);
        ASSERT_NEAR(medium.emission_point_pdf(e->p) / e->pdf, 1, 1e-3);
        const SampledSpectrum f = emitted(e->p);
        for (int i = 0; i < NumWavelengths; ++i) integral[i].add(f[i] / e->pdf);
    }
    constexpr int k = 120;
    SampledSpectrum sum(0.f);
    for (int z = 0; z < k; ++z)
        for (int y = 0; y < k; ++y)
            for (int x = 0; x < k; ++x)
                sum += emitted(render_from_medium.apply_point({(x + 0.5f) / k, (y + 0.5f) / k, (z + 0.5f) / k}));
    const SampledSpectrum exact = sum * (6.f / (k * k * k));
    const SampledSpectrum power = medium.emitted_power(lambda);
    for (int i = 0; i < NumWavelengths; ++i) {
        expect_mean(integral[i], exact[i], "emission integral, wavelength " + std::to_string(i), 2e-3 * exact[i]);
        EXPECT_NEAR(power[i] / exact[i], 1, 0.01) << "wavelength " << i;
    }
}

TEST(UniformGridMedium, IsPlacedByItsTransformAndEmptyOutsideItsBox) {
    const Transform render_from_medium = Transform::translate({2, 0, 0}) * Transform::rotate(90, {0, 0, 1});
    UniformGridMedium medium(render_from_medium, Bounds3f{{0, 0, 0}, {1, 2, 1}}, std::make_shared<ConstantSpectrum>(1.f),
                             std::make_shared<ConstantSpectrum>(2.f), 1, 0, linear_density());
    const SampledWavelengths lambda = SampledWavelengths::fixed(550);
    // Medium point (x, 1, 0.5) is render point (2 - 1, x, 0.5); its density is a + b x.
    for (float x : {0.2f, 0.5f, 0.8f}) {
        const MediumProperties mp = medium.properties({1, x, 0.5f}, lambda);
        EXPECT_NEAR(mp.sigma_s[0], 2 * (kA + kB * x), 1e-4f);
        EXPECT_NEAR(mp.sigma_a[0], kA + kB * x, 1e-4f);
    }
    EXPECT_EQ(medium.properties({3, 0.5f, 0.5f}, lambda).sigma_s[0], 0) << "outside the box";
    EXPECT_NEAR(medium.max_sigma_t(lambda)[0], 3 * (kA + kB * (kVoxels - 0.5f) / kVoxels), 1e-4f);
}

TEST(CloudMedium, DensityLiesInZeroToOneSolidAtTheBaseAndClearAtTheTop) {
    // pbrt-v4's cloud: (1 - y) 4.5 density noise, clamped, plus 2 (0.5 - y) below y = 0.5.
    const CloudMedium cloud(Transform(), Bounds3f{{0, 0, 0}, {1, 1, 1}}, std::make_shared<ConstantSpectrum>(1.f),
                            std::make_shared<ConstantSpectrum>(1.f), 0, 1, 1, 5);
    Rng rng(5, 5);
    float largest = 0;
    for (int n = 0; n < 20000; ++n) {
        const Vec3f p{rng.uniform(), rng.uniform(), rng.uniform()};
        const float d = cloud.density(p);
        ASSERT_GE(d, 0);
        ASSERT_LE(d, 1) << "the majorant of a cloud is sigma_t at density 1";
        largest = std::max(largest, d);
    }
    EXPECT_GT(largest, 0.9f);
    EXPECT_EQ(cloud.density({0.3f, 0.f, 0.7f}), 1) << "solid at its base";
    EXPECT_EQ(cloud.density({0.3f, 1.f, 0.7f}), 0) << "clear at y = 1";
}

TEST(MediumFactory, ReadsGridMediaAndRejectsBadGrids) {
    MediumPtr grid = create_medium("uniformgrid",
                                   dictionary({numbers("float", "density", {0, 1, 2, 3, 4, 5}, 2), numbers("integer", "nx", {3}, 3),
                                               numbers("integer", "ny", {2}, 3), numbers("rgb", "sigma_s", {2, 2, 2}, 4),
                                               numbers("point3", "p1", {3, 2, 1}, 5)}),
                                   {});
    const SampledWavelengths lambda = SampledWavelengths::fixed(550);
    // The centre of voxel (2, 1, 0) of a 3 x 2 x 1 grid over [0, 3] x [0, 2] x [0, 1].
    EXPECT_NEAR(grid->properties({2.5f, 1.5f, 0.5f}, lambda).sigma_s[0], 2 * 5, 1e-3f);
    EXPECT_NEAR(grid->properties({2.5f, 1.5f, 0.5f}, lambda).sigma_a[0], 5, 1e-3f) << "pbrt-v4's default sigma_a is 1";

    MediumPtr rgb = create_medium("rgbgrid",
                                  dictionary({numbers("rgb", "sigma_s", {1, 1, 1, 3, 3, 3}, 2), numbers("integer", "nz", {2}, 3),
                                              numbers("float", "scale", {2}, 4)}),
                                  {});
    EXPECT_NEAR(rgb->properties({0.5f, 0.5f, 0.75f}, lambda).sigma_s[0], 6, 0.05f);
    EXPECT_NEAR(rgb->properties({0.5f, 0.5f, 0.75f}, lambda).sigma_a[0], 2, 1e-4f) << "a missing grid is 1, times scale";

    // Emission. pbrt-v4 divides "Le" by its luminance: a white "rgb Le" of luminance 1 is the
    // colour space's illuminant, which is 1 at 560 nm only roughly, so the check is relative to
    // the normalised illuminant itself.
    MediumPtr hot = create_medium("uniformgrid",
                                  dictionary({numbers("float", "density", {1}, 2), numbers("float", "temperature", {2000}, 3),
                                              numbers("float", "temperatureoffset", {500}, 4),
                                              numbers("float", "temperaturescale", {2}, 5)}),
                                  {});
    ASSERT_TRUE(hot->is_emissive());
    // The 1^3 Lescale grid of pbrt-v4's default is 1 at the box's centre; (2000 - 500) 2 = 3000 K.
    EXPECT_NEAR(hot->Le({0.5f, 0.5f, 0.5f}, lambda)[0], BlackbodySpectrum(3000)(550), 1e-4f);
    // At a face both 1^3 grids, Lescale and temperature, fall to half: (1000 - 500) 2 = 1000 K.
    EXPECT_NEAR(hot->Le({0.f, 0.5f, 0.5f}, lambda)[0] / (0.5f * BlackbodySpectrum(1000)(550)), 1, 1e-3f)
        << "pbrt-v4's 1^3 grids fall to half at the faces";
    MediumPtr cold = create_medium("uniformgrid",
                                   dictionary({numbers("float", "density", {1}, 2), numbers("float", "temperature", {90}, 3)}),
                                   {});
    EXPECT_EQ(cold->Le({0.5f, 0.5f, 0.5f}, lambda)[0], 0) << "no emission at or below 100 K";
    EXPECT_FALSE(grid->is_emissive());

    auto error_line = [&](const std::string &type, std::vector<ParsedParameter> params) {
        return input_error_line(
            [&] { create_medium(type, dictionary(std::move(params)), SourceLocation{"test.pbrt", 1, 1}); });
    };
    EXPECT_EQ(error_line("uniformgrid", {numbers("float", "density", {1, 2, 3}, 5), numbers("integer", "nx", {2}, 6)}), 5)
        << "3 values for 2 voxels";
    EXPECT_EQ(error_line("uniformgrid", {numbers("float", "density", {1, -2}, 5), numbers("integer", "nx", {2}, 6)}), 5)
        << "a negative density";
    EXPECT_EQ(error_line("uniformgrid", {numbers("float", "density", {1}, 5), numbers("integer", "ny", {0}, 7)}), 7);
    EXPECT_EQ(error_line("uniformgrid", {numbers("float", "density", {1}, 5), numbers("point3", "p1", {1, 0, 1}, 8)}), 8)
        << "a flat box";
    EXPECT_EQ(error_line("uniformgrid", {numbers("float", "density", {1}, 5), numbers("float", "temperature", {900, 900}, 9)}),
              9)
        << "2 temperatures for 1 voxel";
    EXPECT_EQ(error_line("uniformgrid", {numbers("float", "density", {1}, 5), numbers("float", "temperature", {-1}, 9)}), 9)
        << "a negative temperature";
    EXPECT_EQ(error_line("uniformgrid", {numbers("float", "density", {1}, 5), numbers("float", "temperature", {900}, 9),
                                         numbers("rgb", "Le", {1, 1, 1}, 10)}),
              10)
        << "both Le and temperature";
    EXPECT_EQ(error_line("uniformgrid", {numbers("float", "density", {1, 1}, 5), numbers("integer", "nx", {2}, 6),
                                         numbers("float", "Lescale", {1, 1, 1}, 11)}),
              11)
        << "a Lescale grid of the wrong size";
    EXPECT_EQ(error_line("rgbgrid", {numbers("rgb", "sigma_s", {1, 1, 1}, 2), numbers("rgb", "Le", {1, 1, 1}, 3)}), 3)
        << "emission without sigma_a";
    EXPECT_EQ(error_line("rgbgrid", {numbers("rgb", "sigma_a", {1, 1, 1}, 2), numbers("rgb", "Le", {1, 1, 1, 1, 1, 1}, 3)}), 3)
        << "2 emission values for 1 voxel";
    EXPECT_EQ(error_line("homogeneous", {numbers("float", "Lescale", {-1}, 4), numbers("rgb", "Le", {1, 1, 1}, 3)}), 4)
        << "a negative Lescale";
    EXPECT_EQ(error_line("rgbgrid", {}), 1);
    EXPECT_EQ(error_line("rgbgrid", {numbers("rgb", "sigma_a", {1, 1, 1}, 2), numbers("rgb", "sigma_s", {1, 1, 1, 2, 2, 2}, 3)}), 3);
    EXPECT_EQ(error_line("rgbgrid", {numbers("rgb", "sigma_a", {1, 1, std::nan("")}, 2)}), 2);
    EXPECT_EQ(error_line("cloud", {numbers("float", "wispiness", {std::nan("")}, 4)}), 4);
    EXPECT_EQ(error_line("cloud", {numbers("float", "g", {1}, 5)}), 5);
    EXPECT_EQ(error_line("cloudy", {}), 1) << "an unknown type";
}

} // namespace
} // namespace caustica
