// Alpha cut-outs (geometry/alpha_mask.h) in GeometryScene: rays pass a mesh where its alpha is 0
// and stop where it is 1, also in an object instance; an analytic shape's cut-out lets rays on to
// its far side; partial alpha stops rays with its probability, the same way for a ray each time
// it is traced, and intersection and occlusion queries agree.
#include "geometry/alpha_mask.h"
#include "geometry/sphere.h"
#include "geometry_test_util.h"
#include "params/constant_textures.h"

#include <cmath>

namespace caustica {
namespace {

// Alpha 0 where u < 0.5, 1 elsewhere.
class LeftHalfCut final : public FloatTexture {
  public:
    float evaluate(const TextureEvalContext &ctx) const override { return ctx.uv.x < 0.5f ? 0.f : 1.f; }
};

std::shared_ptr<const AlphaMask> left_half_cut() {
    return make_alpha_mask(std::make_shared<LeftHalfCut>());
}

std::shared_ptr<const AlphaMask> constant_alpha(float a) {
    return make_alpha_mask(std::make_shared<ConstantFloatTexture>(a));
}

// The unit square [0, 1]^2 at height z, uv = (x, y).
std::shared_ptr<ShapeGroup> square_at(float z) {
    return test::mesh_group({}, false, {0, 1, 2, 0, 2, 3}, {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}}, {},
                            {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
}

PrimitiveAttributes with_alpha(std::shared_ptr<const AlphaMask> alpha) {
    PrimitiveAttributes attributes;
    attributes.alpha = std::move(alpha);
    return attributes;
}

Ray downwards(float x, float y, float t_max = Infinity) { return Ray{{x, y, 1}, {0, 0, -1}, t_max}; }

// A cut square at z = 0 above an opaque one at z = -1: rays through the cut half reach the
// lower square, the others stop on the upper one, and only those are occluded before z = -0.5.
void expect_left_half_cut(const GeometryScene &scene, Vec3f offset) {
    Rng rng(3, 1);
    for (int i = 0; i < 400; ++i) {
        const float x = rng.uniform(), y = rng.uniform();
        if (std::abs(x - 0.5f) < 1e-3f) continue;
        const bool cut = x < 0.5f;
        Ray ray = downwards(x + offset.x, y + offset.y);
        ray.o.z += offset.z;
        SurfaceInteraction si;
        ASSERT_TRUE(scene.intersect(ray, &si));
        EXPECT_NEAR(si.p.z - offset.z, cut ? -1.f : 0.f, 1e-5f) << x << " " << y;
        EXPECT_EQ(si.coverage, 1.f);
        ray.t_max = 1.5f;
        EXPECT_EQ(scene.occluded(ray), !cut) << x << " " << y;
    }
}

TEST(AlphaMask, MeshPassesRaysWhereAlphaIsZero) {
    GeometryScene scene;
    scene.add(square_at(0), with_alpha(left_half_cut()));
    scene.add(square_at(-1), {});
    scene.commit();
    expect_left_half_cut(scene, {});
}

TEST(AlphaMask, InstancedMeshPassesRaysWhereAlphaIsZero) {
    GeometryScene scene;
    std::vector<std::pair<std::shared_ptr<const ShapeGroup>, PrimitiveAttributes>> shapes;
    shapes.emplace_back(square_at(0), with_alpha(left_half_cut()));
    shapes.emplace_back(square_at(-1), PrimitiveAttributes{});
    const Vec3f offset{2, -3, 0.5f};
    scene.add_instance(scene.add_prototype(std::move(shapes)), AnimatedTransform(Transform::translate(offset)));
    scene.commit();
    expect_left_half_cut(scene, offset);
}

// A unit sphere with alpha 0.5, aimed at through its centre from outside: a ray stops on the near
// side with probability 1/2, on the far side with 1/4, and leaves with 1/4. With 20000 rays the
// binomial standard deviations are 0.0035 and 0.0031, so the 0.015 bounds are over 4 sigma.
TEST(AlphaMask, PartialAlphaStopsRaysWithItsProbability) {
    GeometryScene scene;
    scene.add(test::analytic_group(std::make_shared<Sphere>(Transform(), false, 1.f, -1.f, 1.f, 360.f)),
              with_alpha(constant_alpha(0.5f)));
    scene.commit();
    Rng rng(5, 2);
    const int n = 20000;
    int near = 0, far = 0;
    for (int i = 0; i < n; ++i) {
        const Vec3f o = normalize(Vec3f{rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f}) * 3.f;
        const Ray ray{o, -o / 3.f, Infinity};
        SurfaceInteraction si;
        const bool hit = scene.intersect(ray, &si);
        // The same ray meets the same surfaces every time it is traced, in either query.
        SurfaceInteraction again;
        ASSERT_EQ(scene.intersect(ray, &again), hit);
        ASSERT_EQ(scene.occluded(ray), hit);
        if (!hit) continue;
        EXPECT_EQ(again.t, si.t);
        EXPECT_FLOAT_EQ(si.coverage, 0.5f);
        (si.t < 3 ? near : far) += 1;
    }
    EXPECT_NEAR(near / double(n), 0.5, 0.015);
    EXPECT_NEAR(far / double(n), 0.25, 0.015);
}

// The coverage of a hit is its own, not left over from an earlier hit on a cut-out.
TEST(AlphaMask, CoverageIsResetOnOpaqueSurfaces) {
    GeometryScene scene;
    scene.add(square_at(0), with_alpha(constant_alpha(0.25f)));
    scene.add(square_at(-1), {});
    scene.commit();
    SurfaceInteraction si;
    bool met_cut_out = false;
    for (int i = 0; i < 64 && !met_cut_out; ++i) {
        ASSERT_TRUE(scene.intersect(downwards(0.3f + i * 1e-3f, 0.5f), &si));
        met_cut_out = si.p.z > -0.5f;
    }
    ASSERT_TRUE(met_cut_out);
    EXPECT_FLOAT_EQ(si.coverage, 0.25f);
    ASSERT_TRUE(scene.intersect(Ray{{0.5f, 0.5f, -0.5f}, {0, 0, -1}, Infinity}, &si));
    EXPECT_EQ(si.coverage, 1.f);
}

TEST(AlphaMask, OpaqueAlphaMakesNoMask) {
    EXPECT_EQ(make_alpha_mask(nullptr), nullptr);
    EXPECT_EQ(constant_alpha(1), nullptr);
    EXPECT_NE(constant_alpha(0.3f), nullptr);
    EXPECT_NE(constant_alpha(0), nullptr);
    EXPECT_NE(left_half_cut(), nullptr);
}

} // namespace
} // namespace caustica
