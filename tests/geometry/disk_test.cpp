#include "geometry/disk.h"
#include "geometry_test_util.h"

namespace caustica {
namespace {

using test::expect_near_vec;

TEST(Disk, AnnulusHitsAndMisses) {
    auto disk = std::make_shared<Disk>(Transform{}, false, 1, 2, 0.5f, 360);
    auto scene = test::scene_of({test::analytic_group(disk)});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{1, 0, 5}, {0, 0, -1}}, &si));
    EXPECT_NEAR(si.t, 4, 1e-6);
    expect_near_vec(si.p, {1, 0, 1}, 0);
    expect_near_vec(si.n, {0, 0, 1}, 0);
    // u = phi / phi_max, v = (radius - r) / (radius - inner radius).
    EXPECT_NEAR(si.uv.x, 0, 1e-6);
    EXPECT_NEAR(si.uv.y, 1.f / 1.5f, 1e-6);
    ASSERT_TRUE(scene->intersect({{0, -1, -5}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.uv.x, 0.75f, 1e-6);
    EXPECT_FALSE(scene->intersect({{0.3f, 0, 5}, {0, 0, -1}}, &si)); // in the hole
    EXPECT_FALSE(scene->intersect({{2.1f, 0, 5}, {0, 0, -1}}, &si)); // outside
    EXPECT_FALSE(scene->intersect({{1, 0, 5}, {1, 0, 0}}, &si));     // parallel
    EXPECT_NEAR(disk->area(), Pi * (4 - 0.25f), 1e-5);
}

TEST(Disk, PartialDiskAndTransform) {
    auto quarter = std::make_shared<Disk>(Transform{}, false, 0, 1, 0, 90);
    auto scene = test::scene_of({test::analytic_group(quarter)});
    SurfaceInteraction si;
    EXPECT_TRUE(scene->intersect({{0.5f, 0.5f, 1}, {0, 0, -1}}, &si));
    EXPECT_FALSE(scene->intersect({{-0.5f, 0.5f, 1}, {0, 0, -1}}, &si));
    EXPECT_NEAR(quarter->area(), Pi / 4, 1e-6);

    // Rotated to face +x and moved: the plane x = 3, normal +x; scaled by 2 in-plane.
    Transform t = Transform::translate({3, 0, 0}) * Transform::rotate(90, {0, 1, 0}) *
                  Transform::scale(2, 2, 2);
    auto moved = std::make_shared<Disk>(t, false, 0, 1, 0, 360);
    auto moved_scene = test::scene_of({test::analytic_group(moved)});
    ASSERT_TRUE(moved_scene->intersect({{10, 1.5f, 0.5f}, {-1, 0, 0}}, &si));
    EXPECT_NEAR(si.t, 7, 1e-5);
    expect_near_vec(si.p, {3, 1.5f, 0.5f}, 1e-6f);
    expect_near_vec(si.n, {1, 0, 0}, 1e-6f);
    EXPECT_FALSE(moved_scene->intersect({{10, 1.5f, 1.5f}, {-1, 0, 0}}, &si)); // r = 2.12 > 2
    EXPECT_NEAR(moved->area(), 4 * Pi, 1e-5);
}

// Disk normals follow the same rule as spheres: dp/du x dp/dv (object +z) in render space,
// reversed by ReverseOrientation.
TEST(Disk, NormalOrientationRules) {
    Transform mirror = Transform::scale(1, -1, 1);
    struct Case {
        Transform t;
        bool reverse;
        float expected_z;
    } cases[] = {{{}, false, 1}, {{}, true, -1}, {mirror, false, -1}, {mirror, true, 1}};
    for (const Case &c : cases) {
        auto disk = std::make_shared<Disk>(c.t, c.reverse, 0, 1, 0, 360);
        auto scene = test::scene_of({test::analytic_group(disk)});
        SurfaceInteraction si;
        ASSERT_TRUE(scene->intersect({{0.2f, 0.3f, 1}, {0, 0, -1}}, &si));
        EXPECT_EQ(si.n.z, c.expected_z);
        Vec3f cross_n = normalize(cross(si.dpdu, si.dpdv));
        expect_near_vec(si.n, c.reverse ? -cross_n : cross_n, 1e-5f);
        auto ss = disk->sample(Vec2f{0.3f, 0.6f});
        ASSERT_TRUE(ss);
        EXPECT_EQ(ss->n.z, c.expected_z);
    }
}

} // namespace
} // namespace caustica
