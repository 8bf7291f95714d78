// bdpt's multiple-importance weights (integrators/bdpt/mis_weight.cpp) sum to one over the
// strategies that can produce a path (Veach 1997, section 10.2.1): random paths x_0 .. x_k
// through a box of diffuse walls, from a point on its area light (x_0) to the lens (x_k), are
// split every way into a light subpath x_0 .. x_{s-1} and a camera subpath x_k .. x_s, with each
// vertex's densities set as bdpt's random walks set them, and the weights of all k + 1
// strategies (s = 0: the camera path hits the light; s = 1: light sampling; t = 1: light
// tracing; the others: connections) must add up to one within 1e-4. The negative control: with
// the light's emission density doubled where the light subpath holds it (as a walk whose
// densities disagree with its sampling would have it), the sums are not one.
//
// With two lights, next-event estimation chooses between them by the receiving point's position
// (BVHLightSampler) and the light subpaths by power, so x_0 has one density in the s = 1
// strategy and another in those with s >= 2; mis_weight takes each strategy's own. The negative
// control gives the light subpath's origin next-event estimation's choice instead.
//
// The same holds when the light subpath starts inside an emissive medium (BdptMediumMis): x_0 is
// then a point of a homogeneous glowing fog that fills the box and surrounds the camera, which
// the camera subpath reaches by a free flight (s = 0 collects the emission there) and the light
// subpath draws per unit volume; s = 1 joins the camera vertex to it. Negative control: the
// light subpath's copy of x_0 with another extinction, so that the free-flight density that the
// camera side's density at x_0 includes differs between the strategies.
#include "core/error.h"
#include "core/scratch_buffer.h"
#include "integrators/bdpt/mis_weight.h"
#include "integrators/common/path_vertex.h"
#include "lights/light.h"
#include "materials/material.h"
#include "parser/scene_description.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace caustica {
namespace {

const char *kBox = R"(LookAt 0 1 3.2  0 1 0  0 1 0
Camera "perspective" "float fov" [ 45 ]
Film "rgb" "integer xresolution" [ 64 ] "integer yresolution" [ 64 ]
WorldBegin
AttributeBegin
  Material "diffuse" "rgb reflectance" [ 0.6 0.6 0.6 ]
  Shape "bilinearmesh" "point3 P" [ -1 0 -1   1 0 -1   -1 0 1   1 0 1 ]
  Shape "bilinearmesh" "point3 P" [ -1 2 -1   1 2 -1   -1 2 1   1 2 1 ]
  Shape "bilinearmesh" "point3 P" [ -1 0 -1   1 0 -1   -1 2 -1   1 2 -1 ]
  Shape "bilinearmesh" "point3 P" [ -1 0 -1   -1 0 1   -1 2 -1   -1 2 1 ]
  Shape "bilinearmesh" "point3 P" [ 1 0 -1   1 0 1   1 2 -1   1 2 1 ]
AttributeEnd
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [ 5 5 5 ]
  Material "diffuse" "rgb reflectance" [ 0.2 0.2 0.2 ]
  Shape "bilinearmesh" "point3 P" [ -0.3 1.99 -0.3   0.3 1.99 -0.3   -0.3 1.99 0.3   0.3 1.99 0.3 ]
    "normal N" [ 0 -1 0  0 -1 0  0 -1 0  0 -1 0 ]
AttributeEnd
)";

// The box with a second light, a small bright one low on a wall: next-event estimation's choice
// between the two lights then depends on the receiving point (BVHLightSampler), and differs
// from the light subpaths' choice by power.
const std::string kTwoLightBox = std::string(kBox) + R"(AttributeBegin
  AreaLightSource "diffuse" "rgb L" [ 500 500 500 ]
  Shape "bilinearmesh" "point3 P" [ -0.99 0.2 -0.05   -0.99 0.3 -0.05   -0.99 0.2 0.05   -0.99 0.3 0.05 ]
    "normal N" [ 1 0 0  1 0 0  1 0 0  1 0 0 ]
AttributeEnd
)";

// The box filled with a glowing fog that the camera sits in.
const std::string kGlowBox = std::string(R"(MakeNamedMedium "glow" "string type" "homogeneous"
  "rgb sigma_a" [ 0.3 0.3 0.3 ] "rgb sigma_s" [ 0.6 0.6 0.6 ] "rgb Le" [ 1 1 1 ]
MediumInterface "" "glow"
)") + kBox;

// The points of one path: x[0] on the light, x[k] the lens; surfaces carry their intersection
// and BSDF (the light's too, for the strategy that hits it).
struct PathPoints {
    std::vector<SurfaceInteraction> si;
    std::vector<BSDF> bsdf;
    Vec3f lens;
    int k() const { return int(si.size()); } // si[0 .. k-1] are x_0 .. x_{k-1}
};

class BdptMis : public ::testing::Test {
  protected:
    void SetUp() override {
        set_warnings_enabled(false);
        scene_ = build_scene(parse_scene_string(kBox), RenderOverrides{});
        ASSERT_FALSE(scene_->lights.empty());
    }

    void add_a_second_light() {
        scene_ = build_scene(parse_scene_string(kTwoLightBox), RenderOverrides{});
        ASSERT_GE(scene_->lights.size(), 2u);
    }

    // The light subpaths start in the glowing fog (kGlowBox) rather than on the area light.
    void start_in_the_fog() {
        scene_ = build_scene(parse_scene_string(kGlowBox), RenderOverrides{});
        ASSERT_EQ(scene_->medium_emitters.size(), 1u);
        fog_emitter_ = scene_->medium_emitters[0].get();
    }

    // A random path of k segments, or empty when a ray leaves the box or lands on the light
    // before the end.
    std::optional<PathPoints> random_path(std::mt19937 &rng, int k) {
        std::uniform_real_distribution<float> unit(0.f, 1.f);
        PathPoints path;
        path.si.resize(k);
        path.bsdf.resize(k);
        const Vec2i resolution = scene_->film->resolution();
        CameraSample cs;
        cs.p_film = {unit(rng) * resolution.x, unit(rng) * resolution.y};
        cs.p_lens = {0.5f, 0.5f};
        std::optional<CameraRay> camera_ray = scene_->camera->generate_ray(cs, lambda_);
        if (!camera_ray) return std::nullopt;
        path.lens = camera_ray->ray.o;
        Ray ray = camera_ray->ray;
        for (int i = k - 1; i >= 1; --i) {
            SurfaceInteraction &si = path.si[i];
            if (!scene_->intersect(ray, &si) || si.area_light) return std::nullopt;
            path.bsdf[i] = shade(si, lambda_, scratch_);
            if (!path.bsdf[i]) return std::nullopt;
            // A uniformly random direction on the side of the surface facing the box.
            Vec3f d;
            do d = Vec3f{2 * unit(rng) - 1, 2 * unit(rng) - 1, 2 * unit(rng) - 1};
            while (length_squared(d) > 1 || length_squared(d) < 1e-4f);
            d = normalize(d);
            if (dot(d, si.n) * dot(si.wo, si.n) < 0) d = -d;
            ray = si.spawn_ray(d);
        }
        if (fog_emitter_) {
            // x_0: a point of the fog inside the box.
            path.si[0].p = {2 * unit(rng) - 1, 2 * unit(rng), 2 * unit(rng) - 1};
            return path;
        }
        // x_0: a point on the light, reached from x_1 by a ray so that its intersection (with the
        // area light) is known for the strategy that hits it.
        const Light &light = *scene_->lights[rng() % scene_->lights.size()];
        std::optional<LightLiSample> ls =
            light.sample_li(LightSampleContext{path.si[1].p, path.si[1].n, path.si[1].shading.n},
                            Vec2f{unit(rng), unit(rng)}, lambda_);
        if (!ls || !(ls->pdf > 0)) return std::nullopt;
        SurfaceInteraction &x0 = path.si[0];
        if (!scene_->intersect(path.si[1].spawn_ray(ls->wi), &x0) || !x0.area_light) return std::nullopt;
        path.bsdf[0] = shade(x0, lambda_, scratch_);
        return path;
    }

    // Path vertex i (0: the light, k: the lens), as the subpath going the given way holds it.
    PathVertex vertex(const PathPoints &path, int i, bool on_light_subpath) const {
        PathVertex v;
        if (i == path.k()) {
            v.type = PathVertexType::Camera;
            v.si.p = path.lens;
            v.medium = scene_->camera_medium;
            return v;
        }
        if (i == 0 && fog_emitter_) {
            // Where the light subpath starts, or where the camera subpath collects the emission.
            v.type = PathVertexType::Light;
            v.light = fog_emitter_;
            v.medium = scene_->camera_medium;
            v.si.p = path.si[0].p;
            const MediumProperties mp = v.medium->properties(v.si.p, lambda_);
            v.collision_sigma = (mp.sigma_a + mp.sigma_s).average() * (on_light_subpath ? fog_sigma_error_ : 1.f);
            return v;
        }
        v.si = path.si[i];
        if (i == 0 && on_light_subpath) {
            v.type = PathVertexType::Light;
            v.light = path.si[0].area_light;
            v.bsdf = BSDF();
            return v;
        }
        v.type = PathVertexType::Surface;
        v.bsdf = path.bsdf[i];
        return v;
    }

    // The weights of every strategy (s, t = k + 1 - s) for the path; emission_error scales the
    // light subpath's density of its second vertex (1: as bdpt has it).
    std::vector<float> weights(const PathPoints &path, float emission_error = 1) {
        const int k = path.k();
        std::vector<float> w;
        for (int s = 0; s <= k; ++s) {
            const int t = k + 1 - s;
            std::vector<PathVertex> light(std::max(s, 1)), camera(t);
            for (int j = 0; j < s; ++j) light[j] = vertex(path, j, true);
            for (int i = 0; i < t; ++i) camera[i] = vertex(path, k - i, false);
            // Forward densities along each subpath, and reverse ones (the other subpath's
            // direction) as the walks set them; mis_weight sets those of the joined ends.
            for (int j = 0; j < s; ++j) {
                if (j == 0) {
                    const auto choice = origin_by_next_event_ && s >= 2 ? PathVertex::LightChoice::NextEvent
                                                                        : PathVertex::LightChoice::LightSubpath;
                    light[0].pdf_fwd =
                        light[0].pdf_light_origin(*scene_, j + 1 < s ? light[1] : camera[t - 1], choice);
                    // The ratio of the two choices towards x_1: kept by the light subpath's
                    // origin (s >= 2), or by the point next-event estimation sampled (s = 1, as
                    // connect keeps it).
                    light[0].next_event_ratio_ahead =
                        light[0].next_event_ratio(*scene_, j + 1 < s ? light[1] : camera[t - 1]);
                }
                else if (j == 1) light[1].pdf_fwd = light[0].pdf_light(*scene_, light[1]) * emission_error;
                else light[j].pdf_fwd = light[j - 1].pdf(*scene_, &light[j - 2], light[j]);
                if (j + 2 < s) light[j].pdf_rev = light[j + 1].pdf(*scene_, &light[j + 2], light[j]);
            }
            for (int i = 1; i < t; ++i) {
                camera[i].pdf_fwd = camera[i - 1].pdf(*scene_, i >= 2 ? &camera[i - 2] : nullptr, camera[i]);
                if (i + 2 < t) camera[i].pdf_rev = camera[i + 1].pdf(*scene_, &camera[i + 2], camera[i]);
            }
            const PathVertex sampled = t == 1 ? camera[0] : light[0];
            w.push_back(bdpt_mis_weight(*scene_, light.data(), camera.data(), sampled, s, t));
        }
        return w;
    }

    // Every strategy's weight for up to `count` random paths; the sum over the strategies of
    // each path and the number of strategies that carry more than 1% of it are handed to
    // `check`. Returns the number of paths.
    template <typename Check>
    int for_random_paths(uint32_t seed, int count, float emission_error, Check check) {
        std::mt19937 rng(seed);
        int paths = 0;
        for (int trial = 0; trial < 3000 && paths < count; ++trial) {
            const int k = 2 + trial % 5;
            std::optional<PathPoints> path = random_path(rng, k);
            if (!path) continue;
            ++paths;
            double sum = 0;
            int contributing = 0;
            for (float w : weights(*path, emission_error)) {
                sum += w;
                contributing += w > 0.01f;
            }
            check(sum, contributing, k, trial);
        }
        return paths;
    }

    // The weights sum to one for 500 paths, most of which are shared by two strategies or more
    // (not a trivial partition).
    void expect_partition(uint32_t seed) {
        int shared = 0;
        const int paths = for_random_paths(seed, 500, 1, [&](double sum, int contributing, int k, int trial) {
            shared += contributing >= 2;
            ASSERT_NEAR(sum, 1.0, 1e-4) << "path of " << k << " segments, trial " << trial;
        });
        EXPECT_EQ(paths, 500);
        EXPECT_GT(shared, 250);
    }

    // Paths of 200 whose sum is not one.
    int broken_sums(uint32_t seed, float emission_error) {
        int broken = 0;
        const int paths = for_random_paths(seed, 200, emission_error,
                                           [&](double sum, int, int, int) { broken += std::abs(sum - 1) > 1e-3; });
        EXPECT_EQ(paths, 200);
        return broken;
    }

    std::unique_ptr<Scene> scene_;
    const Light *fog_emitter_ = nullptr;
    // A negative control: the light subpath's origin takes next-event estimation's choice of the
    // light rather than its own.
    bool origin_by_next_event_ = false;
    float fog_sigma_error_ = 1; // scales the light subpath's copy of the fog's extinction at x_0
    SampledWavelengths lambda_ = SampledWavelengths::fixed(550);
    ScratchBuffer scratch_;
};

TEST_F(BdptMis, WeightsOfAllStrategiesSumToOne) { expect_partition(7); }

TEST_F(BdptMis, WrongEmissionDensityBreaksTheSum) { EXPECT_GT(broken_sums(8, 2.f), 100); }

TEST_F(BdptMis, WeightsSumToOneWhenNextEventEstimationChoosesLightsByPosition) {
    add_a_second_light();
    expect_partition(11);
}

TEST_F(BdptMis, NextEventEstimationsChoiceOnTheLightSubpathBreaksTheSum) {
    add_a_second_light();
    origin_by_next_event_ = true;
    // 9 of 200 paths (34 when the choice ignored the lights' facing); none with the right choice.
    EXPECT_GT(broken_sums(12, 1.f), 4);
}

TEST_F(BdptMis, WeightsSumToOneForLightSubpathsFromAnEmissiveMedium) {
    start_in_the_fog();
    expect_partition(9);
}

TEST_F(BdptMis, InconsistentFreeFlightDensityBreaksTheSum) {
    start_in_the_fog();
    fog_sigma_error_ = 2;
    EXPECT_GT(broken_sums(10, 1.f), 100);
}

} // namespace
} // namespace caustica
