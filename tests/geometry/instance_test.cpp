#include "geometry/sphere.h"
#include "geometry_test_util.h"

namespace caustica {
namespace {

using test::expect_near_vec;

// A unit square in z = 0 (two triangles, normal +z) as a prototype.
std::shared_ptr<ShapeGroup> unit_square() {
    return test::mesh_group({}, false, {0, 1, 2, 0, 2, 3},
                            {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {},
                            {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
}

TEST(Instances, HitAtTransformedLocationWithTransformedNormal) {
    GeometryScene scene;
    const Material *material = reinterpret_cast<const Material *>(0x1234);
    PrimitiveAttributes attributes;
    attributes.material = material;
    int prototype = scene.add_prototype({{unit_square(), attributes}});
    Transform t1 = Transform::translate({10, 0, 0}) * Transform::rotate(90, {1, 0, 0}) *
                   Transform::scale(2, 3, 2);
    Transform t2 = Transform::translate({0, -20, 5}) * Transform::rotate(30, {0, 0, 1});
    scene.add_instance(prototype, t1);
    scene.add_instance(prototype, t2);
    scene.commit();
    EXPECT_EQ(scene.instance_count(), 2u);
    EXPECT_EQ(scene.triangle_count(), 2u);

    for (const Transform &t : {t1, t2}) {
        Vec3f object_point{0.25f, 0.75f, 0};
        Vec3f expected_p = t.apply_point(object_point);
        Vec3f expected_n = normalize(t.apply_normal({0, 0, 1}));
        Vec3f origin = expected_p + expected_n * 5;
        SurfaceInteraction si;
        ASSERT_TRUE(scene.intersect({origin, -expected_n}, &si));
        expect_near_vec(si.p, expected_p, 2e-5f);
        expect_near_vec(si.n, expected_n, 1e-6f);
        EXPECT_NEAR(si.t, 5, 1e-5);
        EXPECT_NEAR(si.uv.x, 0.25f, 1e-5);
        EXPECT_NEAR(si.uv.y, 0.75f, 1e-5);
        // Tangents are mapped as vectors: dp/du is the image of (1, 0, 0).
        expect_near_vec(si.dpdu, t.apply_vector({1, 0, 0}), 1e-5f);
        expect_near_vec(si.wo, expected_n, 1e-6f);
        EXPECT_EQ(si.material, material);
        EXPECT_TRUE(scene.occluded({origin, -expected_n, 6}));
        EXPECT_FALSE(scene.occluded({origin, -expected_n, 4}));
    }
}

TEST(Instances, AnalyticShapesAndMirroredInstances) {
    GeometryScene scene;
    auto s = std::make_shared<Sphere>(Transform{}, false, 1, -1, 1, 360);
    int prototype = scene.add_prototype({{test::analytic_group(s), {}}});
    // A mirror keeps an instance's surface where it is mapped; the normal is mapped as a normal
    // (pbrt does not re-flip instanced normals), so it stays outward here.
    Transform t = Transform::translate({0, 0, 10}) * Transform::scale(-2, 2, 2);
    scene.add_instance(prototype, t);
    scene.commit();
    SurfaceInteraction si;
    ASSERT_TRUE(scene.intersect({{0, 0, 0}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.t, 8, 1e-5);
    expect_near_vec(si.p, {0, 0, 8}, 1e-5f);
    expect_near_vec(si.n, {0, 0, -1}, 1e-6f);
    EXPECT_TRUE(scene.occluded({{0, 0, 0}, {0, 0, 1}, 8.5f}));
    EXPECT_FALSE(scene.occluded({{0, 0, 0}, {0, 0, 1}, 7.5f}));
    EXPECT_FALSE(scene.occluded({{3, 0, 0}, {0, 0, 1}}));
    Bounds3f b = scene.bounds();
    EXPECT_LE(b.lo.z, 8);
    EXPECT_GE(b.hi.z, 12);
}

TEST(Instances, AreaLightsAndCountsForDirectShapes) {
    GeometryScene scene;
    PrimitiveAttributes attributes;
    const Light *l0 = reinterpret_cast<const Light *>(0x10);
    const Light *l1 = reinterpret_cast<const Light *>(0x20);
    attributes.area_lights = {l0, l1};
    scene.add(unit_square(), attributes);
    scene.commit();
    EXPECT_EQ(scene.shape_count(), 1u);
    EXPECT_EQ(scene.triangle_count(), 2u);
    SurfaceInteraction si;
    // Triangle 0 is (0,0)-(1,0)-(1,1): below the diagonal; triangle 1 above it.
    ASSERT_TRUE(scene.intersect({{0.7f, 0.2f, 1}, {0, 0, -1}}, &si));
    EXPECT_EQ(si.area_light, l0);
    ASSERT_TRUE(scene.intersect({{0.2f, 0.7f, 1}, {0, 0, -1}}, &si));
    EXPECT_EQ(si.area_light, l1);
    EXPECT_EQ(si.face_index, 1);
}

} // namespace
} // namespace caustica
