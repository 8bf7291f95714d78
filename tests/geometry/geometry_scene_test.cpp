#include "core/sampling.h"
#include "geometry/disk.h"
#include "geometry/sphere.h"
#include "geometry_test_util.h"

#include <thread>

namespace caustica {
namespace {

TEST(GeometryScene, EmptySceneMissesEverything) {
    GeometryScene scene;
    scene.commit();
    SurfaceInteraction si;
    EXPECT_FALSE(scene.intersect({{0, 0, 0}, {0, 0, 1}}, &si));
    EXPECT_FALSE(scene.occluded({{0, 0, 0}, {0, 0, 1}}));
    EXPECT_TRUE(scene.bounds().empty());
}

TEST(GeometryScene, ClosestOfMixedShapesAndBounds) {
    // A disk at z = 1 in front of a sphere at z = 5 in front of a box wall at z = 10.
    auto disk = std::make_shared<Disk>(Transform{}, false, 1, 1, 0, 360);
    auto sphere = std::make_shared<Sphere>(Transform::translate({0, 0, 5}), false, 1, -1, 1, 360);
    auto box = test::box_group({}, {-20, -20, 10}, {20, 20, 11});
    auto scene = test::scene_of({test::analytic_group(disk), test::analytic_group(sphere), box});
    EXPECT_EQ(scene->shape_count(), 3u);
    EXPECT_EQ(scene->triangle_count(), 12u);
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{0.5f, 0, 0}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.t, 1, 1e-6);
    ASSERT_TRUE(scene->intersect({{0, 0.9f, 2}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.t, 3 - std::sqrt(1 - 0.81), 1e-5);
    ASSERT_TRUE(scene->intersect({{3, 0, 0}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.t, 10, 1e-5);
    Bounds3f b = scene->bounds();
    EXPECT_LE(b.lo.x, -20);
    EXPECT_GE(b.hi.z, 11);
    EXPECT_LE(b.lo.z, 1);
}

TEST(GeometryScene, ConcurrentQueriesAgreeWithSerialOnes) {
    auto sphere = std::make_shared<Sphere>(Transform{}, false, 1, -1, 1, 360);
    GeometryScene scene;
    scene.add(test::analytic_group(sphere), {});
    int prototype = scene.add_prototype({{test::box_group({}, {-1, -1, -1}, {1, 1, 1}), {}}});
    for (int i = 0; i < 8; ++i)
        scene.add_instance(prototype, Transform::translate({3.f * (i - 4), 0, 4}));
    scene.commit();

    const int n = 20000;
    std::vector<Ray> rays(n);
    Rng rng(2, 2);
    for (Ray &r : rays) r = {{0, 0, -3}, sample_uniform_sphere(rng.uniform2())};
    std::vector<float> serial(n), parallel(n);
    for (int i = 0; i < n; ++i) {
        SurfaceInteraction si;
        serial[i] = scene.intersect(rays[i], &si) ? si.t : -1;
    }
    std::vector<std::thread> threads;
    for (int k = 0; k < 4; ++k)
        threads.emplace_back([&, k] {
            for (int i = k; i < n; i += 4) {
                SurfaceInteraction si;
                parallel[i] = scene.intersect(rays[i], &si) ? si.t : -1;
                if (scene.occluded(rays[i]) != (parallel[i] >= 0)) parallel[i] = -2;
            }
        });
    for (auto &t : threads) t.join();
    EXPECT_EQ(serial, parallel);
}

} // namespace
} // namespace caustica
