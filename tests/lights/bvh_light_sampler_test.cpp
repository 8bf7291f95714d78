// The light samplers that choose by importance ("bvh", "exhaustive") over a few hundred lights of
// every kind of orientation: their choice must be a probability distribution, sample() must
// report the probability that pmf() gives (MIS weighs each strategy with the other's), and no
// light that could light a receiver may have probability zero there (next-event estimation
// would then miss its light, a bias that no other strategy repays in the path tracer's MIS).
#include "lights/bvh_light_sampler.h"

#include "core/rng.h"
#include "geometry/disk.h"
#include "geometry/triangle.h"
#include "lights/diffuse_area_light.h"
#include "lights/point_light.h"
#include "lights/projection_light.h"
#include "lights/spot_light.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace caustica {
namespace {

Vec3f uniform_direction(Rng &rng) {
    const float z = 1 - 2 * rng.uniform(), phi = 2 * Pi * rng.uniform();
    const float r = std::sqrt(std::max(0.f, 1 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

struct ManyLights {
    std::vector<LightPtr> lights;
    std::vector<std::shared_ptr<const Triangle>> triangles; // of the first lights
    std::vector<bool> two_sided;
    // Lights with bounded directions besides the triangles: disks and spot lights, each with its
    // index in lights.
    std::vector<std::pair<size_t, std::shared_ptr<const Disk>>> disks;
    std::vector<std::pair<size_t, std::shared_ptr<const PointSourceLight>>> spots; // and projectors

    // Triangles of random size, place and facing (a fifth two-sided, some meshes with vertex
    // normals, which can turn a triangle's emitting side), point lamps, spot lights and disks of
    // random facing (some under mirroring transforms, some reversed).
    explicit ManyLights(int count) {
        Rng rng(7, 11);
        for (int i = 0; i < count; ++i) {
            const Vec3f c{20 * rng.uniform() - 10, 20 * rng.uniform() - 10, 20 * rng.uniform() - 10};
            const float size = 0.05f + 0.5f * rng.uniform();
            std::vector<Vec3f> p = {c + uniform_direction(rng) * size, c + uniform_direction(rng) * size,
                                    c + uniform_direction(rng) * size};
            std::vector<Vec3f> n;
            if (i % 7 == 0) n = {uniform_direction(rng), uniform_direction(rng), uniform_direction(rng)};
            auto mesh = std::make_shared<TriangleMesh>(Transform(), i % 3 == 0, std::vector<int>{0, 1, 2}, p, n,
                                                       std::vector<Vec2f>{});
            auto triangle = std::make_shared<const Triangle>(mesh, 0);
            const bool both = i % 5 == 0;
            lights.push_back(std::make_shared<DiffuseAreaLight>(
                triangle, std::make_shared<ConstantSpectrum>(0.5f + rng.uniform()), 1.f, both));
            triangles.push_back(triangle);
            two_sided.push_back(both);
        }
        for (int i = 0; i < count / 10; ++i) {
            const Vec3f c{20 * rng.uniform() - 10, 20 * rng.uniform() - 10, 20 * rng.uniform() - 10};
            lights.push_back(std::make_shared<PointLight>(Transform::translate(c),
                                                          std::make_shared<ConstantSpectrum>(1 + rng.uniform()), 1.f));
            const Transform turn = Transform::rotate(360 * rng.uniform(), uniform_direction(rng));
            auto spot = std::make_shared<SpotLight>(Transform::translate(c) * turn,
                                                    std::make_shared<ConstantSpectrum>(1.f), 1.f,
                                                    10 + 50 * rng.uniform(), 5 * rng.uniform());
            spots.emplace_back(lights.size(), spot);
            lights.push_back(spot);
            RGBImage slide;
            slide.width = 3 + i % 3;
            slide.height = 2 + i % 2;
            slide.pixels.assign(size_t(slide.width) * slide.height * 3, 0.5f);
            const Transform aim = Transform::rotate(360 * rng.uniform(), uniform_direction(rng)) *
                                  Transform::scale(1, 1 + rng.uniform(), 1);
            auto projector = std::make_shared<ProjectionLight>(Transform::translate(c) * aim, slide, 1.f,
                                                               20 + 60 * rng.uniform());
            spots.emplace_back(lights.size(), projector);
            lights.push_back(projector);
            const Vec3f d{20 * rng.uniform() - 10, 20 * rng.uniform() - 10, 20 * rng.uniform() - 10};
            const Transform mirror = i % 2 ? Transform::scale(-1, 1, 1) : Transform();
            auto disk = std::make_shared<const Disk>(
                Transform::translate(d) * Transform::rotate(360 * rng.uniform(), uniform_direction(rng)) * mirror,
                i % 3 == 0, 0.f, 0.1f + 0.4f * rng.uniform(), 0.f, 360.f);
            disks.emplace_back(lights.size(), disk);
            lights.push_back(std::make_shared<DiffuseAreaLight>(disk, std::make_shared<ConstantSpectrum>(1.f), 1.f,
                                                                i % 4 == 0));
        }
    }
};

// Receivers in and around the lights' box, a fifth of them in a medium (no normal).
std::vector<LightSampleContext> receivers(int count) {
    Rng rng(3, 5);
    std::vector<LightSampleContext> r;
    for (int i = 0; i < count; ++i) {
        const Vec3f p{24 * rng.uniform() - 12, 24 * rng.uniform() - 12, 24 * rng.uniform() - 12};
        const Vec3f n = i % 5 == 0 ? Vec3f{} : uniform_direction(rng);
        r.push_back({p, n, n});
    }
    return r;
}

// The exhaustive sampler's choice is a distribution over the lights. The tree's may fall short
// of one: a node whose bounds may face the receiver can hold only lights that do not, and a
// descent into it chooses nothing. Either way, sample() must choose each light as often as pmf()
// says, and nothing as often as the shortfall.
template <class Sampler>
void expect_a_consistent_distribution(const std::vector<LightPtr> &lights, bool may_choose_nothing, int receiver_count,
                                      int n) {
    const Sampler sampler(lights);
    double shortfall = 0;
    for (const LightSampleContext &ctx : receivers(receiver_count)) {
        double sum = 0;
        std::vector<double> pmf;
        for (const LightPtr &l : lights) {
            pmf.push_back(sampler.pmf(ctx, l.get()));
            sum += pmf.back();
        }
        if (may_choose_nothing) ASSERT_LE(sum, 1 + 1e-4);
        else ASSERT_NEAR(sum, 1, 1e-4);
        shortfall += 1 - sum;
        // Stratified u: every light gets a run of u as long as its probability (the descent maps
        // u onto consecutive intervals), so its count is n pmf within a couple of samples, and
        // each sample reports the light's pmf().
        std::vector<int> counts(lights.size());
        int nothing = 0;
        for (int i = 0; i < n; ++i) {
            const std::optional<SampledLight> s = sampler.sample(ctx, (i + 0.5f) / n);
            if (!s) {
                ++nothing;
                continue;
            }
            size_t k = 0;
            while (lights[k].get() != s->light) ++k;
            ASSERT_NEAR(s->pmf, pmf[k], 1e-5 * pmf[k]) << "light " << k;
            ++counts[k];
        }
        for (size_t k = 0; k < counts.size(); ++k)
            ASSERT_NEAR(counts[k], n * pmf[k], 2.5 + 1e-3 * n * pmf[k]) << "light " << k;
        ASSERT_NEAR(nothing, n * (1 - sum), 2.5 + 1e-3 * n);
    }
    std::printf("mean probability of choosing nothing: %.4f\n", shortfall / receiver_count);
}
template <class Sampler> void expect_a_consistent_distribution(bool may_choose_nothing, int receiver_count, int n) {
    expect_a_consistent_distribution<Sampler>(ManyLights(300).lights, may_choose_nothing, receiver_count, n);
}

TEST(BVHLightSampler, SampleAndPmfAgree) { expect_a_consistent_distribution<BVHLightSampler>(true, 60, 20000); }
TEST(ExhaustiveLightSampler, IsADistributionThatSampleAndPmfAgreeOn) {
    expect_a_consistent_distribution<ExhaustiveLightSampler>(false, 12, 4000);
}

// A rectangle of two triangles, as scene files write quad lights: a light for each triangle.
struct Rectangle {
    std::shared_ptr<const Triangle> triangles[2];
    LightPtr lights[2];
    Rectangle(const Transform &placed, std::vector<LightPtr> &all) {
        auto mesh = std::make_shared<TriangleMesh>(
            placed, false, std::vector<int>{0, 1, 2, 0, 2, 3},
            std::vector<Vec3f>{{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}},
            std::vector<Vec3f>{}, std::vector<Vec2f>{});
        for (int i = 0; i < 2; ++i) {
            triangles[i] = std::make_shared<const Triangle>(mesh, i);
            lights[i] = std::make_shared<DiffuseAreaLight>(triangles[i], std::make_shared<ConstantSpectrum>(1.f), 1.f,
                                                           false);
            all.push_back(lights[i]);
        }
    }
};

// The two triangles of an axis-aligned rectangle have the same bounds, so the tree takes one
// importance for both and chooses between them evenly; that shortcut must give the probabilities
// that evaluating both would: exactly equal, zero together where the rectangle cannot light the
// receiver, and sample() agreeing with pmf() among other lights, twins and not.
TEST(BVHLightSampler, ChoosesEvenlyBetweenTrianglesWithTheSameBounds) {
    std::vector<LightPtr> lights;
    const Rectangle level(Transform::translate({0, 0, 2}), lights);
    const Rectangle tilted(Transform::translate({3, 1, 0}) * Transform::rotate(30, {1, 1, 0}), lights);
    ASSERT_TRUE(same_bounds(*light_bounds(*level.lights[0]), *light_bounds(*level.lights[1])));
    ASSERT_FALSE(same_bounds(*light_bounds(*tilted.lights[0]), *light_bounds(*tilted.lights[1])));
    for (const LightPtr &l : ManyLights(40).lights) lights.push_back(l);
    const BVHLightSampler sampler(lights);
    int lit = 0, below = 0;
    for (const LightSampleContext &ctx : receivers(2000)) {
        const float p0 = sampler.pmf(ctx, level.lights[0].get()), p1 = sampler.pmf(ctx, level.lights[1].get());
        ASSERT_EQ(p0, p1);
        // The rectangle emits towards +z from z = 2: nothing well below it (the importance is
        // conservative near its plane), most receivers above.
        if (2 - ctx.p.z > 2 * std::hypot(ctx.p.x, ctx.p.y) + 2) {
            ASSERT_EQ(p0, 0.f);
            ++below;
        }
        lit += p0 > 0;
    }
    EXPECT_GT(lit, 500);
    EXPECT_GT(below, 50);
    expect_a_consistent_distribution<BVHLightSampler>(lights, true, 30, 20000);
}

// Wherever some point of a triangle light emits towards a receiver from outside its tangent
// plane, the light's probability there is positive: the importance bounds (cones of normals,
// their unions up the tree, the receiver's cosine) are conservative.
template <class Sampler> void expect_no_light_left_out() {
    const ManyLights scene(300);
    const Sampler sampler(scene.lights);
    Rng rng(9, 1);
    int checked = 0, checked_disks = 0, checked_spots = 0;
    for (const LightSampleContext &ctx : receivers(200)) {
        for (size_t k = 0; k < scene.triangles.size(); ++k) {
            bool can_light = false;
            for (int j = 0; j < 16 && !can_light; ++j) {
                float b[3];
                sample_uniform_triangle(rng.uniform2(), b);
                const Triangle &t = *scene.triangles[k];
                const Vec3f x = t.mesh().point(0, b), n = t.mesh().normal(0, b);
                const Vec3f to_receiver = normalize(ctx.p - x);
                const bool emits = scene.two_sided[k] ? dot(n, to_receiver) != 0 : dot(n, to_receiver) > 0;
                const bool received = ctx.ns == Vec3f{} || std::abs(dot(ctx.ns, to_receiver)) > 1e-3f;
                can_light = emits && received;
            }
            if (!can_light) continue;
            ++checked;
            ASSERT_GT(sampler.pmf(ctx, scene.lights[k].get()), 0.f) << "light " << k;
        }
        const auto received = [&](Vec3f to_receiver) {
            return ctx.ns == Vec3f{} || std::abs(dot(ctx.ns, to_receiver)) > 1e-3f;
        };
        const SampledWavelengths lambda = SampledWavelengths::fixed(550);
        // A disk lights the receiver where the light itself says some point of it emits that way.
        for (const auto &[k, disk] : scene.disks) {
            bool can_light = false;
            for (int j = 0; j < 16 && !can_light; ++j) {
                const std::optional<ShapeSample> ss = disk->sample(rng.uniform2());
                if (!ss) continue;
                const Vec3f to_receiver = normalize(ctx.p - ss->p);
                can_light = !scene.lights[k]->L(ss->p, ss->n, ss->uv, to_receiver, lambda).is_black() &&
                            received(to_receiver);
            }
            if (!can_light) continue;
            ++checked_disks;
            ASSERT_GT(sampler.pmf(ctx, scene.lights[k].get()), 0.f) << "disk light " << k;
        }
        for (const auto &[k, spot] : scene.spots) {
            const Vec3f to_receiver = normalize(ctx.p - spot->position());
            if (spot->intensity_towards(to_receiver, lambda).is_black() || !received(to_receiver)) continue;
            ++checked_spots;
            ASSERT_GT(sampler.pmf(ctx, scene.lights[k].get()), 0.f) << "spot or projection light " << k;
        }
    }
    EXPECT_GT(checked, 20000);
    EXPECT_GT(checked_disks, 500);
    EXPECT_GT(checked_spots, 100);
}

TEST(BVHLightSampler, NeverLeavesOutALightThatCanLightTheReceiver) { expect_no_light_left_out<BVHLightSampler>(); }
TEST(ExhaustiveLightSampler, NeverLeavesOutALightThatCanLightTheReceiver) {
    expect_no_light_left_out<ExhaustiveLightSampler>();
}

// A union of cones holds every direction of both, and is not much wider than it must be: random
// cones of every width, each direction drawn within one of them.
TEST(DirectionCone, UnionHoldsBothCones) {
    Rng rng(5, 8);
    int narrow_enough = 0;
    for (int i = 0; i < 20000; ++i) {
        DirectionCone c[2];
        for (DirectionCone &k : c) k = {uniform_direction(rng), std::cos(Pi * rng.uniform() * rng.uniform())};
        const DirectionCone u = cone_union(c[0], c[1]);
        for (int j = 0; j < 8; ++j) {
            // A direction at angle theta <= theta_k from axis k.
            const DirectionCone &k = c[j % 2];
            const float theta = std::acos(std::clamp(k.cos_theta, -1.f, 1.f)) * rng.uniform();
            Vec3f t, b;
            coordinate_system(k.w, &t, &b);
            const float phi = 2 * Pi * rng.uniform();
            const Vec3f w = k.w * std::cos(theta) + (t * std::cos(phi) + b * std::sin(phi)) * std::sin(theta);
            ASSERT_GE(dot(u.w, w), u.cos_theta - 1e-6f) << "cone " << i;
        }
        // The union's half-angle is at most half the spread of the two cones, plus the margin.
        const float spread = std::acos(std::clamp(c[0].cos_theta, -1.f, 1.f)) +
                             std::acos(std::clamp(c[1].cos_theta, -1.f, 1.f)) +
                             std::acos(std::clamp(dot(c[0].w, c[1].w), -1.f, 1.f));
        narrow_enough += u.cos_theta == -1 || std::acos(u.cos_theta) <= std::max(
            {spread / 2 + 2e-3f, std::acos(std::clamp(c[0].cos_theta, -1.f, 1.f)),
             std::acos(std::clamp(c[1].cos_theta, -1.f, 1.f))});
    }
    EXPECT_EQ(narrow_enough, 20000);
}

// The point of the orientation bounds: a floor under a cluster of lamps that face it, with as
// many above them facing up and as many under the floor facing down, gives all its samples to
// the cluster that lights it.
TEST(BVHLightSampler, FavoursTheLightsThatFaceTheReceiver) {
    std::vector<LightPtr> lights;
    auto quad = [&](Vec3f c, float facing) {
        // A small square at c, in the plane z = c.z, emitting towards +z (facing 1) or -z.
        std::vector<Vec3f> p = {c + Vec3f{-0.1f, -0.1f, 0}, c + Vec3f{0.1f, -0.1f, 0}, c + Vec3f{0.1f, 0.1f, 0}};
        if (facing < 0) std::swap(p[1], p[2]);
        auto mesh = std::make_shared<TriangleMesh>(Transform(), false, std::vector<int>{0, 1, 2}, p,
                                                   std::vector<Vec3f>{}, std::vector<Vec2f>{});
        lights.push_back(std::make_shared<DiffuseAreaLight>(std::make_shared<const Triangle>(mesh, 0),
                                                            std::make_shared<ConstantSpectrum>(1.f), 1.f, false));
    };
    for (int i = 0; i < 50; ++i) quad({float(i % 10) - 5, float(i / 10) - 2, 5}, -1);  // above, facing down
    for (int i = 0; i < 50; ++i) quad({float(i % 10) - 5, float(i / 10) - 2, 5.5f}, 1); // above, facing up
    for (int i = 0; i < 50; ++i) quad({float(i % 10) - 5, float(i / 10) - 2, -5}, -1);  // below, facing down
    BVHLightSampler sampler(lights);
    const LightSampleContext floor{{0, 0, 0}, {0, 0, 1}, {0, 0, 1}};
    double facing = 0, rest = 0;
    for (size_t i = 0; i < lights.size(); ++i) (i < 50 ? facing : rest) += sampler.pmf(floor, lights[i].get());
    EXPECT_NEAR(facing + rest, 1, 1e-5);
    EXPECT_EQ(rest, 0); // each of them faces away from the receiver
}

} // namespace
} // namespace caustica
