// Exact bilinear patches (geometry/bilinear_patch.h) against closed forms: the saddle
// P(u, v) = (u, v, u v) of the corners (0,0,0), (1,0,0), (0,1,0), (1,1,1), its hits, normals and
// texture derivatives, and the density that area lights sample it with.
#include "geometry/bilinear_mesh.h"
#include "geometry/bilinear_patch.h"
#include "geometry_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

namespace caustica {
namespace {

const std::vector<Vec3f> kSaddle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}};

std::shared_ptr<BilinearPatchMesh> saddle(const Transform &render_from_object = {}, bool reverse = false,
                                          std::vector<Vec3f> n = {}, std::vector<Vec2f> uv = {}) {
    return std::make_shared<BilinearPatchMesh>(render_from_object, reverse, std::vector<int>{0, 1, 2, 3}, kSaddle,
                                               std::move(n), std::move(uv));
}

std::shared_ptr<ShapeGroup> patch_group(std::shared_ptr<BilinearPatchMesh> mesh) {
    auto group = std::make_shared<ShapeGroup>();
    group->type = "bilinearmesh";
    group->patches = std::move(mesh);
    return group;
}

// Rays straight down meet the saddle at z = x y, with (u, v) = (x, y) and the normal of
// dp/du x dp/dv = (1, 0, v) x (0, 1, u) = (-v, -u, 1). The same patch split into its two
// triangles (the negative control) is off by up to a quarter of its height.
TEST(BilinearPatch, RaysMeetTheSaddleWhereItsHeightIsUTimesV) {
    auto scene = test::scene_of({patch_group(saddle())});
    auto triangles = test::scene_of({test::mesh_group({}, false, {0, 1, 2, 1, 3, 2}, kSaddle)});
    Rng rng(7, 1);
    float worst_triangle_error = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec2f xy = rng.uniform2();
        const Ray ray{{xy.x, xy.y, 2}, {0, 0, -1}};
        SurfaceInteraction si;
        ASSERT_TRUE(scene->intersect(ray, &si));
        EXPECT_NEAR(si.p.z, xy.x * xy.y, 1e-6f);
        EXPECT_NEAR(si.t, 2 - xy.x * xy.y, 1e-6f);
        EXPECT_NEAR(si.uv.x, xy.x, 1e-5f);
        EXPECT_NEAR(si.uv.y, xy.y, 1e-5f);
        const Vec3f n = normalize(Vec3f{-xy.y, -xy.x, 1});
        EXPECT_GT(dot(si.n, n), 1 - 1e-6f);
        EXPECT_NEAR(si.error_scale, 1, 0);
        SurfaceInteraction flat;
        ASSERT_TRUE(triangles->intersect(ray, &flat));
        worst_triangle_error = std::max(worst_triangle_error, std::abs(flat.p.z - xy.x * xy.y));
    }
    EXPECT_GT(worst_triangle_error, 0.2f);
}

// The line (s, 1 - s, 0.16) meets the saddle where s (1 - s) = 0.16: at s = 0.2 and 0.8. Both
// hits are reported, nearest first; a t_max between them leaves the near one.
TEST(BilinearPatch, ARayThroughTheSaddleTwiceMeetsItTwice) {
    auto mesh = saddle();
    BilinearPatchMesh::Hit hits[2];
    const Vec3f o{-0.5f, 1.5f, 0.16f}, d{1, -1, 0};
    ASSERT_EQ(mesh->hits(0, o, d, Infinity, hits), 2);
    EXPECT_NEAR(hits[0].t, 0.7f, 1e-5f);
    EXPECT_NEAR(hits[1].t, 1.3f, 1e-5f);
    EXPECT_NEAR(hits[0].uv.x, 0.2f, 1e-5f);
    EXPECT_NEAR(hits[1].uv.y, 0.2f, 1e-5f);
    ASSERT_EQ(mesh->hits(0, o, d, 1.f, hits), 1);
    EXPECT_NEAR(hits[0].t, 0.7f, 1e-5f);
    // Rays that pass beside the patch, or start beyond it, meet nothing.
    EXPECT_EQ(mesh->hits(0, {2, 2, 2}, {0, 0, -1}, Infinity, hits), 0);
    EXPECT_EQ(mesh->hits(0, {0.5f, 0.5f, 0.3f}, {0, 0, 1}, Infinity, hits), 0); // above z = 0.25
}

// pbrt-v4's orientation rule: dp/du x dp/dv, flipped by ReverseOrientation, or turned to the side
// of the interpolated normals "N", which also give the shading normal.
TEST(BilinearPatch, NormalsFollowPbrtV4sOrientationRule) {
    SurfaceInteraction si;
    saddle()->interaction(0, {0.5f, 0.5f}, &si);
    EXPECT_GT(si.n.z, 0.8f);
    saddle({}, true)->interaction(0, {0.5f, 0.5f}, &si);
    EXPECT_LT(si.n.z, -0.8f);
    const std::vector<Vec3f> down = {{0.2f, 0, -1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}};
    saddle({}, false, down)->interaction(0, {0, 0}, &si);
    EXPECT_LT(si.n.z, 0);
    EXPECT_GT(dot(si.shading.n, normalize(down[0])), 1 - 1e-6f);
    saddle({}, false, down)->interaction(0, {0.5f, 0.5f}, &si);
    EXPECT_GT(dot(si.shading.n, normalize(Vec3f{0.05f, 0, -1})), 1 - 1e-6f);
    // A patch whose p10-p11 edge has collapsed (a triangle) has a normal along that edge too:
    // dP/du x dP/dv vanishes there, and the diagonals give the plane's.
    const BilinearPatchMesh triangle({}, false, {0, 1, 2, 3}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}}, {}, {});
    for (Vec2f uv : {Vec2f{1, 0.5f}, Vec2f{0.3f, 0.4f}}) {
        const Vec3f n = triangle.normal(0, uv);
        EXPECT_EQ(n.z, 1) << uv.x << " " << uv.y;
    }
}

// With "uv", dp/du and dp/dv are the derivatives along the texture coordinates (s, t): here a
// rotated and scaled copy of the patch parameters, so that a small step in (u, v) moves the
// point by dp/ds ds + dp/dt dt.
TEST(BilinearPatch, TextureDerivativesFollowTheUvMap) {
    const float c = std::cos(0.5f), s = std::sin(0.5f);
    std::vector<Vec2f> uv;
    for (Vec2f q : {Vec2f{0, 0}, Vec2f{1, 0}, Vec2f{0, 1}, Vec2f{1, 1}})
        uv.push_back(Vec2f{c * q.x - s * q.y, s * q.x + c * q.y} * 2);
    auto mesh = saddle({}, false, {}, uv);
    const Vec2f at{0.3f, 0.6f}, step{1e-3f, -2e-3f};
    SurfaceInteraction si;
    mesh->interaction(0, at, &si);
    const Vec2f d_st = mesh->texture_uv(0, at + step) - mesh->texture_uv(0, at);
    const Vec3f predicted = si.dpdu * d_st.x + si.dpdv * d_st.y;
    const Vec3f actual = mesh->point(0, at + step) - mesh->point(0, at);
    EXPECT_LT(length(predicted - actual), 2e-2f * length(actual));
    // pbrt-v4's entrywise inverse of the uv Jacobian (the control) is off by far more here.
    const Vec2f st_u = uv[1] - uv[0], st_v = uv[2] - uv[0];
    SurfaceInteraction plain;
    saddle()->interaction(0, at, &plain);
    const Vec3f entrywise = (plain.dpdu / st_u.x + plain.dpdv / st_v.x) * d_st.x +
                            (plain.dpdu / st_u.y + plain.dpdv / st_v.y) * d_st.y;
    EXPECT_GT(length(entrywise - actual), 0.5f * length(actual));
}

// Area lights sample the patch by the bilinear warp of its corner area elements. The density
// they report must be the true one: the mean of 1 / pdf over N samples estimates the area, and
// of x / pdf the first moment, which a fine midpoint rule gives independently. 1 / pdf has a
// relative standard deviation of 4% here (the warp nearly follows the area element), so with
// N = 2^18 the estimates' standard errors are 8e-5 of the values: the 1e-3 tolerance is twelve
// of them, and a density 3% off fails by thirty.
TEST(BilinearPatch, SamplesHaveTheAreaDensityTheyReport) {
    // The saddle stretched and turned, so that its area element varies by a factor of 2.
    const Transform placement = Transform::rotate(30, {1, 2, 3}) * Transform::scale(2, 1, 1.5f);
    auto mesh = saddle(placement);
    BilinearPatch patch(mesh, 0);
    double area = 0, moment = 0;
    constexpr int grid = 1000;
    for (int i = 0; i < grid; ++i)
        for (int j = 0; j < grid; ++j) {
            const Vec2f uv{(i + 0.5f) / grid, (j + 0.5f) / grid};
            const double element = mesh->area_element(0, uv) / double(grid * grid);
            area += element;
            moment += mesh->point(0, uv).x * element;
        }
    EXPECT_NEAR(patch.area(), area, 1e-3 * area);
    Rng rng(11, 1);
    double area_estimate = 0, moment_estimate = 0;
    constexpr int n = 1 << 18;
    for (int i = 0; i < n; ++i) {
        const std::optional<ShapeSample> s = patch.sample(rng.uniform2());
        ASSERT_TRUE(s && s->pdf > 0);
        if (i % 4096 == 0) {
            EXPECT_NEAR(patch.pdf_area(s->p), s->pdf, 1e-4f * s->pdf);
        }
        area_estimate += 1 / (double(s->pdf) * n);
        moment_estimate += s->p.x / (double(s->pdf) * n);
    }
    EXPECT_NEAR(area_estimate, area, 1e-3 * area);
    EXPECT_NEAR(moment_estimate, moment, 1e-3 * std::abs(area));
}

// The solid-angle density of a sample seen from a point is what pdf(ref, wi) reports for its
// direction.
TEST(BilinearPatch, SolidAngleDensityMatchesSampling) {
    auto mesh = saddle(Transform::scale(2, 2, 2));
    BilinearPatch patch(mesh, 0);
    Rng rng(3, 1);
    const Vec3f ref{0.7f, 1.1f, 3};
    for (int i = 0; i < 200; ++i) {
        const std::optional<ShapeSample> s = patch.sample(ref, rng.uniform2());
        ASSERT_TRUE(s);
        EXPECT_NEAR(patch.pdf(ref, normalize(s->p - ref)), s->pdf, 1e-3f * s->pdf);
    }
    EXPECT_EQ(patch.pdf(ref, {0, 0, 1}), 0);
}

// Meshes of parallelograms with affine uv stay triangles; curved patches do not.
TEST(BilinearPatch, OnlyAffinePatchesBecomeTriangles) {
    const std::vector<int> one = {0, 1, 2, 3};
    const std::vector<Vec3f> parallelogram = {{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {3, 1, 0}};
    EXPECT_TRUE(bilinear_patches_are_affine(one, parallelogram, {}, {}));
    EXPECT_FALSE(bilinear_patches_are_affine(one, kSaddle, {}, {}));
    EXPECT_FALSE(bilinear_patches_are_affine(one, parallelogram, {}, {{0, 0}, {1, 0}, {0, 1}, {2, 2}}));
    EXPECT_FALSE(bilinear_patches_are_affine(one, parallelogram, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {1, 0, 1}}, {}));
    test::QuietWarnings quiet;
    EXPECT_THROW(validate_bilinear_patches(one, {{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}, {1, 1, 0}}, {}, {}, {}),
                 InputError);
}

} // namespace
} // namespace caustica
