// Moving shapes and instances (motion blur): Embree's quaternion motion reproduces the start and
// end placements exactly, interpolates rotations by slerp, and hits are reported on the surface
// as it is at the ray's time.
#include "core/rng.h"
#include "geometry/sphere.h"
#include "geometry_test_util.h"

namespace caustica {
namespace {

using test::expect_near_vec;

// A unit square in z = 0 (two triangles, normal +z).
std::shared_ptr<ShapeGroup> unit_square() {
    return test::mesh_group({}, false, {0, 1, 2, 0, 2, 3}, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {},
                            {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
}

// A scene with the square placed by `placement`; times run from 0 to 1.
void build(GeometryScene &scene, const AnimatedTransform &placement) {
    scene.add_moving(unit_square(), {}, placement);
    scene.commit();
}

Ray ray_at(Vec3f o, Vec3f d, float time) {
    Ray r{o, d};
    r.time = time;
    return r;
}

// At the start and end times a moving square is exactly where a still one placed by the start or
// end transform is, for placements that rotate, scale unevenly, shear and mirror (the
// decomposition is exact, not approximate).
TEST(MotionBlur, EndPlacementsAreExact) {
    const Transform placements[] = {
        Transform::translate({1, 2, 3}) * Transform::rotate(70, {1, 2, 0.5f}) * Transform::scale(2, 0.5f, 3),
        Transform::rotate(-120, {0, 1, 1}) * Transform::scale(-1, 2, 1),
        Transform::translate({-3, 0, 1}) * Transform::scale(1, 1, 4) * Transform::rotate(30, {1, 0, 0}),
    };
    Rng rng(7, 0);
    for (const Transform &start : placements)
        for (const Transform &end : placements) {
            if (start == end) continue;
            GeometryScene moving, still;
            build(moving, {start, end});
            build(still, AnimatedTransform(end)); // a placement that does not change is still
            EXPECT_TRUE(moving.moves());
            EXPECT_FALSE(still.moves());
            for (const auto &[time, placement] : {std::pair{0.f, start}, std::pair{1.f, end}})
                for (int i = 0; i < 50; ++i) {
                    const Vec3f object_point{rng.uniform(), rng.uniform(), 0};
                    const Vec3f p = placement.apply_point(object_point);
                    const Vec3f n = normalize(placement.apply_normal({0, 0, 1}));
                    SurfaceInteraction si;
                    ASSERT_TRUE(moving.intersect(ray_at(p + n * 3, -n, time), &si));
                    expect_near_vec(si.p, p, 2e-4f);
                    EXPECT_NEAR(si.uv.x, object_point.x, 1e-4f);
                    EXPECT_NEAR(si.uv.y, object_point.y, 1e-4f);
                    EXPECT_NEAR(std::abs(dot(si.n, n)), 1.f, 1e-5f);
                    EXPECT_FLOAT_EQ(si.time, time);
                }
        }
}

// A stick of length 4 from the origin, swung about z by 90 degrees, points along 45 degrees
// half-way, at full length (slerp of the rotation, as in pbrt-v4), where interpolated matrices
// would shrink it to 4 cos 45; the placements' translations are interpolated linearly.
TEST(MotionBlur, RotationsSlerpAndTranslationsLerp) {
    GeometryScene scene;
    const Transform stick = Transform::scale(4, 0.1f, 1) * Transform::translate({0, -0.5f, 0});
    scene.add_moving(unit_square(), {}, {stick, Transform::rotate(90, {0, 0, 1}) * stick});
    scene.commit();
    const Vec3f diagonal = normalize(Vec3f{1, 1, 0});
    auto hits = [&](float radius, Vec3f direction, float time) {
        return scene.occluded(ray_at(direction * radius + Vec3f{0, 0, 1}, {0, 0, -1}, time));
    };
    EXPECT_TRUE(hits(3.9f, diagonal, 0.5f));
    EXPECT_TRUE(hits(3.9f, {1, 0, 0}, 0));
    EXPECT_TRUE(hits(3.9f, {0, 1, 0}, 1));
    EXPECT_FALSE(hits(3.9f, diagonal, 0));
    EXPECT_FALSE(hits(3.9f, diagonal, 1));
    EXPECT_FALSE(hits(4.1f, diagonal, 0.5f));
    SurfaceInteraction si;
    ASSERT_TRUE(scene.intersect(ray_at(diagonal * 2 + Vec3f{0, 0, 1}, {0, 0, -1}, 0.5f), &si));
    expect_near_vec(si.p, diagonal * 2, 2e-3f); // the stick's axis, up to the lerped offsets
    EXPECT_NEAR(si.uv.x, 0.5f, 1e-3f);

    GeometryScene sliding;
    auto sphere = std::make_shared<Sphere>(Transform{}, false, 1, -1, 1, 360);
    sliding.add_moving(test::analytic_group(sphere), {}, {Transform(), Transform::translate({8, 0, 0})});
    sliding.commit();
    ASSERT_TRUE(sliding.intersect(ray_at({2, 0, -5}, {0, 0, 1}, 0.25f), &si));
    EXPECT_NEAR(si.t, 4, 1e-4f);
    expect_near_vec(si.n, {0, 0, -1}, 1e-5f);
    EXPECT_FALSE(sliding.occluded(ray_at({2, 0, -5}, {0, 0, 1}, 0.5f)));
}

// Scene times map onto the TransformTimes; outside them the geometry rests at an end.
TEST(MotionBlur, TransformTimesMapRayTimes) {
    GeometryScene scene;
    auto sphere = std::make_shared<Sphere>(Transform{}, false, 1, -1, 1, 360);
    scene.add_moving(test::analytic_group(sphere), {}, {Transform(), Transform::translate({8, 0, 0})});
    scene.set_transform_times({2, 4});
    scene.commit();
    auto hit_x = [&](float x, float time) { return scene.occluded(ray_at({x, 0, -5}, {0, 0, 1}, time)); };
    EXPECT_TRUE(hit_x(0, 1));  // before the start: at the start
    EXPECT_TRUE(hit_x(4, 3));  // half-way
    EXPECT_FALSE(hit_x(4, 2.5f));
    EXPECT_TRUE(hit_x(8, 7));  // after the end: at the end
}

} // namespace
} // namespace caustica
