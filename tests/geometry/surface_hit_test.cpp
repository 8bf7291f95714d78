// GeometryScene::interaction rebuilds the surface record of a stored SurfaceHit from the point
// and direction intersect() reported, for every kind of shape, in instances and moving ones.
#include "geometry/bilinear_patch.h"
#include "geometry/cylinder.h"
#include "geometry/disk.h"
#include "geometry/sphere.h"
#include "geometry_test_util.h"

#include <cstring>
#include <algorithm>
#include <map>
#include <set>

namespace caustica {
namespace {

using test::dictionary;
using test::numbers;
using test::strings;

// A distinct fake material per shape, so that the rebuilt record's attributes can be told apart.
PrimitiveAttributes tagged(uintptr_t tag) {
    PrimitiveAttributes attributes;
    attributes.material = reinterpret_cast<const Material *>(tag * 16);
    attributes.medium_interface = reinterpret_cast<const MediumInterface *>(tag * 16 + 8);
    return attributes;
}

std::shared_ptr<ShapeGroup> patch_group(std::shared_ptr<BilinearPatchMesh> mesh) {
    auto group = std::make_shared<ShapeGroup>();
    group->type = "bilinearmesh";
    group->patches = std::move(mesh);
    return group;
}

std::shared_ptr<ShapeGroup> curve_group(const std::string &type, const Transform &t) {
    std::vector<ParsedParameter> params{numbers("point3", "P", {-2, 0, 0, -0.6, 2, 0, 0.6, -2, 1, 2, 0, 0}),
                                        strings("string", "type", {type}), numbers("float", "width", {0.8})};
    if (type == "ribbon") params.push_back(numbers("normal3", "N", {0, 0, 1, 0, 1, 0}));
    return test::create_shape("curve", t, false, dictionary(std::move(params)), {"test.pbrt", 1, 1});
}

// Every kind of shape, some placed by transforms that scale unevenly, an instanced prototype
// and a moving one, inside a box that every ray from the middle meets.
struct MixedScene {
    GeometryScene scene;
    MixedScene() {
        const Transform skew = Transform::rotate(25, {1, 2, 3}) * Transform::scale(1, 1.5f, 0.7f);
        scene.add(test::box_group({}, {-8, -8, -8}, {8, 8, 8}), tagged(1));
        scene.add(test::analytic_group(std::make_shared<Sphere>(Transform::translate({3, 0, 0}) * skew, false, 1,
                                                                -0.8f, 1, 300)),
                  tagged(2));
        scene.add(test::analytic_group(std::make_shared<Cylinder>(Transform::translate({-3, 0, 0}) * skew, true,
                                                                  0.8f, -1, 1, 270)),
                  tagged(3));
        scene.add(test::analytic_group(std::make_shared<Disk>(Transform::translate({0, 3, 0}) * skew, false, 0.2f,
                                                              1.2f, 0.3f, 360)),
                  tagged(4));
        scene.add(patch_group(std::make_shared<BilinearPatchMesh>(
                      Transform::translate({0, -3, 0}) * skew, false, std::vector<int>{0, 1, 2, 3},
                      std::vector<Vec3f>{{-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 1.5f}}, std::vector<Vec3f>{},
                      std::vector<Vec2f>{})),
                  tagged(5));
        scene.add(curve_group("flat", Transform::translate({0, 0, 3}) * skew), tagged(6));
        scene.add(curve_group("cylinder", Transform::translate({0, 0, -3}) * skew), tagged(7));
        scene.add(curve_group("ribbon", Transform::translate({3, 3, 3}) * skew), tagged(8));

        const int prototype = scene.add_prototype(
            {{test::analytic_group(std::make_shared<Sphere>(Transform{}, false, 0.6f, -1, 1, 360)), tagged(9)},
             {test::box_group(Transform::translate({1, 0, 0}), {0, 0, 0}, {0.5f, 0.7f, 0.9f}), tagged(10)}});
        scene.add_instance(prototype, Transform::translate({-3, 3, -3}) * Transform::scale(-1.2f, 1, 0.8f));
        scene.add_instance(prototype, AnimatedTransform(Transform::translate({3, -3, -3}),
                                                        Transform::translate({3, -2, -2}) * Transform::rotate(40, {0, 1, 0})));
        scene.commit();
    }
};

void expect_near(Vec3f a, Vec3f b, float tolerance, const char *what) {
    EXPECT_LE(length(a - b), tolerance * std::max(1.f, length(b))) << what;
}

TEST(SurfaceHit, RebuildsTheRecordIntersectReportedForEveryKindOfShape) {
    MixedScene mixed;
    Rng rng(7, 1);
    std::map<uintptr_t, int> hits_per_shape;
    int exact = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3f o{rng.uniform() * 10 - 5, rng.uniform() * 10 - 5, rng.uniform() * 10 - 5};
        Vec3f d{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f};
        if (length(d) == 0) continue;
        Ray ray{o, d * 3.f}; // not unit: the rebuilt record must not depend on |d|
        ray.time = rng.uniform();
        SurfaceInteraction si;
        ASSERT_TRUE(mixed.scene.intersect(ray, &si));
        const SurfaceHit &hit = si.hit;
        const SurfaceInteraction again = mixed.scene.interaction(hit, si.p, si.wo, ray.time);
        ++hits_per_shape[reinterpret_cast<uintptr_t>(si.material) / 16];

        ASSERT_EQ(again.material, si.material);
        EXPECT_EQ(again.medium_interface, si.medium_interface);
        EXPECT_EQ(again.area_light, si.area_light);
        EXPECT_EQ(again.face_index, si.face_index);
        EXPECT_EQ(again.coverage, si.coverage);
        EXPECT_EQ(again.time, si.time);
        EXPECT_EQ(again.wo, si.wo);
        EXPECT_EQ(std::memcmp(&again.hit, &si.hit, sizeof(SurfaceHit)), 0);
        // The point is kept; from it rather than the ray, analytic shapes and curves may differ
        // by rounding in the rest.
        EXPECT_EQ(again.p, si.p);
        EXPECT_NEAR(again.error_scale, si.error_scale, 1e-4f * std::max(1.f, si.error_scale));
        expect_near(again.n, si.n, 1e-4f, "n");
        expect_near(again.shading.n, si.shading.n, 1e-4f, "shading normal");
        expect_near(again.dpdu, si.dpdu, 1e-3f, "dpdu");
        expect_near(again.dpdv, si.dpdv, 1e-3f, "dpdv");
        EXPECT_NEAR(again.uv.x, si.uv.x, 1e-4f);
        EXPECT_NEAR(again.uv.y, si.uv.y, 1e-3f);
        // Triangles and patches are rebuilt from the same parameters: the same record.
        if (std::memcmp(&again.n, &si.n, sizeof(Vec3f)) == 0 && std::memcmp(&again.uv, &si.uv, sizeof(Vec2f)) == 0) ++exact;
    }
    // Every shape was met often enough for the comparison to mean something.
    for (uintptr_t tag = 1; tag <= 10; ++tag) EXPECT_GE(hits_per_shape[tag], 50) << "shape " << tag;
    EXPECT_GT(exact, 10000);
}

// Packed (GeometryScene::pack), a hit keeps its slot, its instance's shape and its primitive, and
// its (u, v) to half a 16-bit step; every shape, instanced ones included, packs to an index of
// its own.
TEST(SurfaceHit, PackedHitsComeBackWithTheirParametersRounded) {
    MixedScene mixed;
    ASSERT_TRUE(mixed.scene.packs_hits());
    Rng rng(11, 3);
    std::map<uintptr_t, std::set<uint32_t>> packed_shapes;
    const float half_step = 0.5f / 65535 + 1e-7f;
    for (int i = 0; i < 20000; ++i) {
        const Vec3f o{rng.uniform() * 10 - 5, rng.uniform() * 10 - 5, rng.uniform() * 10 - 5};
        const Vec3f d{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f};
        if (length(d) == 0) continue;
        Ray ray{o, d};
        ray.time = rng.uniform();
        SurfaceInteraction si;
        ASSERT_TRUE(mixed.scene.intersect(ray, &si));
        const PackedSurfaceHit packed = mixed.scene.pack(si.hit);
        const SurfaceHit back = mixed.scene.unpack(packed);
        ASSERT_EQ(back.slot, si.hit.slot);
        ASSERT_EQ(back.geometry, si.hit.geometry);
        ASSERT_EQ(back.primitive, si.hit.primitive);
        EXPECT_NEAR(back.uv.x, std::clamp(si.hit.uv.x, 0.f, 1.f), half_step);
        EXPECT_NEAR(back.uv.y, std::clamp(si.hit.uv.y, 0.f, 1.f), half_step);
        EXPECT_EQ(mixed.scene.interaction(back, si.p, si.wo, ray.time).material, si.material);
        packed_shapes[reinterpret_cast<uintptr_t>(si.material) / 16].insert(packed.shape);
    }
    // Ten shapes, the prototype's two placed twice: twelve indices, one per placed shape.
    std::set<uint32_t> all;
    for (uintptr_t tag = 1; tag <= 10; ++tag) {
        EXPECT_EQ(packed_shapes[tag].size(), tag >= 9 ? 2u : 1u) << "shape " << tag;
        all.insert(packed_shapes[tag].begin(), packed_shapes[tag].end());
    }
    EXPECT_EQ(all.size(), 12u);
}

// One 32-bit index names every placed shape, and 2^32 - 1 (SurfaceHit::None) a point in a medium:
// a scene can pack its hits while it places fewer shapes than that. A prototype of 2^16 spheres
// placed 2^16 - 1 times packs them (the last instance's hits come back whole); placed 2^16 times,
// it does not.
TEST(SurfaceHit, HitsPackWhileThePlacedShapesFitIn32Bits) {
    auto scene_placing = [](int instances) {
        auto scene = std::make_unique<GeometryScene>();
        const auto sphere = test::analytic_group(std::make_shared<Sphere>(Transform{}, false, 1, -1, 1, 360));
        std::vector<std::pair<std::shared_ptr<const ShapeGroup>, PrimitiveAttributes>> spheres(1 << 16, {sphere, {}});
        const int prototype = scene->add_prototype(std::move(spheres));
        for (int i = 0; i < instances; ++i) scene->add_instance(prototype, Transform::translate({3.f * i, 0, 0}));
        scene->commit();
        return scene;
    };
    const auto fits = scene_placing((1 << 16) - 1);
    ASSERT_TRUE(fits->packs_hits());
    SurfaceInteraction si;
    ASSERT_TRUE(fits->intersect(Ray{{3.f * ((1 << 16) - 2), 0, 5}, {0, 0, -1}}, &si));
    const PackedSurfaceHit packed = fits->pack(si.hit);
    EXPECT_EQ(packed.shape, uint64_t((1 << 16) - 2) * (1 << 16) + si.hit.geometry);
    const SurfaceHit back = fits->unpack(packed);
    EXPECT_EQ(back.slot, si.hit.slot);
    EXPECT_EQ(back.geometry, si.hit.geometry);
    EXPECT_FALSE(scene_placing(1 << 16)->packs_hits());
}

// A hit of a moving instance is rebuilt where the instance is at the hit's time: rebuilt at
// another time, the point moves with it.
TEST(SurfaceHit, MovingInstancesAreRebuiltAtTheirTime) {
    MixedScene mixed;
    SurfaceInteraction si;
    Ray ray{{3, -2.6f, -1}, {0, 0, -1}};
    ray.time = 0.5f;
    ASSERT_TRUE(mixed.scene.intersect(ray, &si));
    const SurfaceHit hit = si.hit;
    ASSERT_EQ(reinterpret_cast<uintptr_t>(si.material), 9u * 16);
    const SurfaceInteraction same = mixed.scene.interaction(hit, si.p, si.wo, 0.5f);
    expect_near(same.n, si.n, 1e-5f, "n at the same time");
    const SurfaceInteraction later = mixed.scene.interaction(hit, si.p, si.wo, 1.f);
    EXPECT_GT(length(later.n - si.n), 0.05f);
}

} // namespace
} // namespace caustica
