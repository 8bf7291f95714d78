// Rough dispersive refraction under the subpath's spectral MIS (integrators/common/spectral_mis.h,
// BxDF::has_lane_lobes): a furnace of a rough diamond ball, walked by the SubpathWalk that every
// integrator uses.
//
// Camera paths aim at a ball of gem-diamond (Sellmeier dispersion, index 2.40-2.47 over the
// visible range) at GGX alphas 0.003 to 0.3, and walk up to 64 vertices (with the walk's Russian
// roulette) until they escape into a uniform white environment. The escaping throughput, weighed
// per wavelength as the film weighs it, estimates the ball's spectral furnace albedo averaged
// with the visible-wavelength density. With hero sampling every lane is kept through each rough
// refraction, weighted by f_i / mean_k p_k; with one wavelength per path (--single-wavelength,
// SampledWavelengths::sample_single) the hero is alone and carries no lane weights. Both estimate
// the same albedo: single-scattering microfacets lose energy at high alpha, and paths are cut at
// 64 vertices, in both alike.
//
// Bound for the means: |difference| <= 0.5% of the albedo (the issue's figure), and within 5
// standard errors of the difference (each side's standard error from the sample variance of its
// independent paths; at low alpha that is far tighter than 0.5%). Power: the test asserts that
// the standard error of the difference is below 0.125% of the albedo, so that a bias of 1% puts
// the difference at least 4 standard errors beyond the 0.5% bound, and checks that the hero
// estimate scaled by 1.01 fails. 10^6 paths per side meet that at every alpha (the roughest ball,
// which loses the most energy, is the noisiest: 0.11%).
//
// Bound for the weights: no path's throughput at any wavelength the film counts exceeds 50 (the
// issue's figure) in 10^6 paths per alpha. Over the lanes' mean density with each lane's own
// Fresnel term choosing the lobe, the bound is NumWavelengths G / G1 <= 4 (dielectric_bxdf.h), and
// one wavelength per path has G / G1 <= 1.
//
// Negative controls (the code changed for one run each, not kept):
//   - each lane over the sampling lane's density alone, f_i / p_lane: unbiased, but the largest
//     weights were 20605 (alpha 0.003), 253 (0.01) and 42 (0.03), and at alpha 0.003 the
//     standard error of the mean was 0.95%: fails the weight bound and the power check;
//   - each lane over the hero's density, f_i / p_0, while sampling with the subpath's lane:
//     infinite weights (the hero's density is zero where another lane samples), NaN means;
//   - with the lanes' average Fresnel term choosing the lobe for every lane (the smooth
//     interface's choice), the weights reached 57 at alpha 0.003.
// HeroDensityAloneIsUnbounded shows the weighting this replaced, the secondaries over the hero's
// own sampling density, exceeding the weight bound at a single interface.
#include "integrators/common/subpath_walk.h"
#include "core/error.h"
#include "core/scratch_buffer.h"
#include "materials/dielectric_bxdf.h"
#include "parser/scene_description.h"
#include "sampler/independent_sampler.h"
#include "scene/scene.h"
#include "spectral/ior.h"
#include "core/rng.h"

#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace caustica {
namespace {

constexpr int MaxDepth = 64;

std::unique_ptr<Scene> diamond_ball(float alpha) {
    std::ostringstream text;
    text << R"(LookAt 0 0 -4  0 0 0  0 1 0
Camera "perspective" "float fov" [ 30 ]
Film "rgb" "integer xresolution" [ 16 ] "integer yresolution" [ 16 ]
WorldBegin
LightSource "infinite" "rgb L" [ 1 1 1 ]
Material "dielectric" "spectrum eta" "gem-diamond" "bool remaproughness" false "float roughness" [ )"
         << alpha << R"( ]
Shape "sphere" "float radius" [ 1 ]
)";
    set_warnings_enabled(false);
    return build_scene(parse_scene_string(text.str()), RenderOverrides{});
}

struct Moments {
    double sum = 0, sum2 = 0;
    long paths = 0;
    float largest_weight = 0;
    Moments &operator+=(const Moments &o) {
        sum += o.sum, sum2 += o.sum2, paths += o.paths;
        largest_weight = std::max(largest_weight, o.largest_weight);
        return *this;
    }
    double mean() const { return sum / paths; }
    double standard_error() const { return std::sqrt((sum2 / paths - mean() * mean()) / (paths - 1)); }
};

// One camera path from a point of the disc in front of the ball, straight at it: its estimate of
// the albedo (the film's per-lane weighting, p_visible(lambda_i) / lambda.pdf_i, averaged over
// lanes), and its largest per-lane throughput.
std::pair<double, float> walk_path(const Scene &scene, bool single_wavelength, Sampler &sampler, ScratchBuffer &scratch) {
    SampledWavelengths lambda = single_wavelength ? SampledWavelengths::sample_single(sampler.get_1d())
                                                  : SampledWavelengths::sample_visible(sampler.get_1d());
    const Vec2f d = sampler.get_2d();
    const float r = std::sqrt(d.x) * 0.999f, phi = 2 * Pi * d.y;
    uint64_t rays = 0;
    SubpathWalk walk(scene, TransportMode::Radiance, lambda, sampler, scratch, rays, false);
    walk.start(Ray{Vec3f(r * std::cos(phi), r * std::sin(phi), -3), Vec3f(0, 0, 1)}, nullptr, SampledSpectrum(1.f));
    for (int depth = 0; depth <= MaxDepth; ++depth) {
        const WalkEvent event = walk.advance();
        if (event == WalkEvent::Ended) break;
        if (event == WalkEvent::Escaped) {
            double estimate = 0;
            for (int i = 0; i < NumWavelengths; ++i)
                if (lambda.pdf()[i] > 0)
                    estimate += walk.beta[i] * visible_wavelengths_pdf(lambda[i]) / lambda.pdf()[i];
            // Lanes of a terminated set carry nothing to the film, whatever their throughput.
            float weight = 0;
            for (int i = 0; i < NumWavelengths; ++i)
                if (lambda.pdf()[i] > 0) weight = std::max(weight, walk.beta[i]);
            return {estimate / NumWavelengths, weight};
        }
        if (depth == MaxDepth || !walk.scatter() || !walk.russian_roulette(depth + 1)) break;
    }
    return {0, 0};
}

Moments furnace(const Scene &scene, bool single_wavelength, int paths, int seed) {
    constexpr int Block = 4096;
    tbb::combinable<Moments> moments;
    tbb::parallel_for(tbb::blocked_range<int>(0, (paths + Block - 1) / Block), [&](const tbb::blocked_range<int> &blocks) {
        IndependentSampler sampler(Block, seed);
        ScratchBuffer scratch;
        Moments &m = moments.local();
        for (int b = blocks.begin(); b < blocks.end(); ++b)
            for (int i = b * Block; i < std::min(paths, (b + 1) * Block); ++i) {
                sampler.start_pixel_sample({b, 0}, i - b * Block);
                const auto [estimate, weight] = walk_path(scene, single_wavelength, sampler, scratch);
                scratch.reset();
                m.sum += estimate, m.sum2 += estimate * estimate, ++m.paths;
                m.largest_weight = std::max(m.largest_weight, weight);
            }
    });
    Moments total;
    moments.combine_each([&](const Moments &m) { total += m; });
    return total;
}

TEST(RoughDispersion, FurnaceMatchesOneWavelengthPerPathWithBoundedWeights) {
    int seed = 1;
    for (float alpha : {0.003f, 0.01f, 0.03f, 0.1f, 0.3f}) {
        const std::unique_ptr<Scene> scene = diamond_ball(alpha);
        constexpr int Paths = 1000000;
        const Moments hero = furnace(*scene, false, Paths, seed++);
        const Moments single = furnace(*scene, true, Paths, seed++);
        const double difference = hero.mean() - single.mean();
        const double se = std::hypot(hero.standard_error(), single.standard_error());
        std::printf("alpha %.3f: hero %.5f (se %.5f), one wavelength %.5f (se %.5f), difference %+.3f%% (z %+.2f), "
                    "largest weight %.2f and %.2f\n",
                    alpha, hero.mean(), hero.standard_error(), single.mean(), single.standard_error(),
                    100 * difference / single.mean(), difference / se, hero.largest_weight, single.largest_weight);
        EXPECT_LT(4 * se, 0.005 * single.mean()) << "alpha " << alpha << ": too few paths for the bound";
        EXPECT_LT(std::abs(difference), 0.005 * single.mean()) << "alpha " << alpha;
        EXPECT_LT(std::abs(difference), 5 * se) << "alpha " << alpha;
        // Power: a 1% bias of the hero estimate fails.
        EXPECT_GT(std::abs(hero.mean() * 1.01 - single.mean()), 0.005 * single.mean()) << "alpha " << alpha;
        EXPECT_LE(hero.largest_weight, 50.f) << "alpha " << alpha;
        EXPECT_LE(single.largest_weight, 50.f) << "alpha " << alpha;
    }
}

TEST(RoughDispersion, HeroDensityAloneIsUnbounded) {
    // The weighting that the spectral MIS replaces: the secondaries kept on rough refraction,
    // each over the hero's density, f_i |cos| / p_0. At the edge of the hero's lobe that ratio
    // diverges; over the lanes' mean it stays within NumWavelengths^2 / eta'^2.
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f);
    const SampledSpectrum eta = named_ior("gem-diamond")->sample(lambda);
    Rng rng(0x5eed, 3);
    float hero_alone = 0, mixture = 0;
    for (float alpha : {0.003f, 0.03f, 0.3f}) {
        const DielectricBxDF b(eta, TrowbridgeReitzDistribution(alpha, alpha));
        for (int n = 0; n < 200000; ++n) {
            // Grazing directions, where the lanes' lobes part furthest.
            const float cos_o = 0.2f * rng.uniform(), phi = 2 * Pi * rng.uniform();
            const float sin_o = std::sqrt(1 - cos_o * cos_o);
            const Vec3f wo(sin_o * std::cos(phi), sin_o * std::sin(phi), cos_o);
            const auto s = b.sample_f_as(0, wo, rng.uniform(), rng.uniform2(), TransportMode::Importance);
            if (!s || !s->lane_pdf) continue;
            const float cos_i = std::abs(s->wi.z);
            hero_alone = std::max(hero_alone, s->f.max_value() * cos_i / s->pdf);
            mixture = std::max(mixture, s->f.max_value() * cos_i / s->lane_pdf->average());
        }
    }
    std::printf("largest weight over the hero's density %.3g, over the lanes' mean %.3g\n", hero_alone, mixture);
    EXPECT_GT(hero_alone, 50.f);
    EXPECT_LE(mixture, NumWavelengths * NumWavelengths * 1.0001f);
}

} // namespace
} // namespace caustica
