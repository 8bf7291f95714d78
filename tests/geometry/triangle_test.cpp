#include "geometry/triangle.h"
#include "geometry_test_util.h"

namespace caustica {
namespace {

using test::expect_near_vec;

TEST(Triangle, HitPointUVAndDerivatives) {
    // uv = (x / 2, y / 2) over the triangle, so dp/du = (2, 0, 0) and dp/dv = (0, 2, 0).
    auto group = test::mesh_group({}, false, {0, 1, 2}, {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, {},
                                  {{0, 0}, {1, 0}, {0, 1}});
    auto scene = test::scene_of({group});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{0.5f, 0.3f, 1}, {0, 0, -1}}, &si));
    EXPECT_NEAR(si.t, 1, 1e-6);
    expect_near_vec(si.p, {0.5f, 0.3f, 0}, 1e-6f);
    EXPECT_NEAR(si.uv.x, 0.25f, 1e-6);
    EXPECT_NEAR(si.uv.y, 0.15f, 1e-6);
    expect_near_vec(si.dpdu, {2, 0, 0}, 1e-6f);
    expect_near_vec(si.dpdv, {0, 2, 0}, 1e-6f);
    expect_near_vec(si.n, {0, 0, 1}, 1e-6f);
    EXPECT_EQ(si.face_index, 0);
    EXPECT_FALSE(scene->intersect({{1.5f, 1.5f, 1}, {0, 0, -1}}, &si)); // beyond the hypotenuse
}

TEST(Triangle, BarycentricInterpolationOfRandomHits) {
    // A tilted triangle with per-vertex uv and normals; rays aimed at points with known
    // barycentrics must report those points and the matching interpolated attributes.
    std::vector<Vec3f> p = {{1, 0.2f, -0.5f}, {3, 1, 0.5f}, {0.5f, 2.5f, 1.5f}};
    std::vector<Vec2f> uv = {{0.1f, 0.9f}, {0.7f, 0.2f}, {0.4f, 0.6f}};
    std::vector<Vec3f> n = {normalize(Vec3f{0, 0.2f, 1}), normalize(Vec3f{0.3f, 0, 1}),
                            normalize(Vec3f{-0.2f, 0.1f, 1})};
    auto group = test::mesh_group({}, false, {0, 1, 2}, p, n, uv);
    auto scene = test::scene_of({group});
    Vec3f ng = normalize(cross(p[0] - p[2], p[1] - p[2]));
    Rng rng(7, 1);
    for (int i = 0; i < 1000; ++i) {
        float b1 = rng.uniform(), b2 = rng.uniform();
        if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
        float b0 = 1 - b1 - b2;
        Vec3f target = p[0] * b0 + p[1] * b1 + p[2] * b2;
        Vec3f origin = target + Vec3f{0.3f, -0.2f, 4};
        SurfaceInteraction si;
        ASSERT_TRUE(scene->intersect({origin, target - origin}, &si));
        expect_near_vec(si.p, target, 2e-6f);
        EXPECT_NEAR(si.t, 1, 1e-5);
        Vec2f expected_uv = uv[0] * b0 + uv[1] * b1 + uv[2] * b2;
        EXPECT_NEAR(si.uv.x, expected_uv.x, 2e-5);
        EXPECT_NEAR(si.uv.y, expected_uv.y, 2e-5);
        Vec3f ns = normalize(n[0] * b0 + n[1] * b1 + n[2] * b2);
        expect_near_vec(si.shading.n, ns, 2e-5f);
        // The vertex normals all face +z, so the geometric normal follows them.
        expect_near_vec(si.n, face_forward(ng, ns), 1e-6f);
        // dp = dp/du du + dp/dv dv along both edges.
        Vec2f duv02 = uv[0] - uv[2], duv12 = uv[1] - uv[2];
        expect_near_vec(si.dpdu * duv02.x + si.dpdv * duv02.y, p[0] - p[2], 1e-4f);
        expect_near_vec(si.dpdu * duv12.x + si.dpdv * duv12.y, p[1] - p[2], 1e-4f);
        EXPECT_NEAR(dot(si.shading.n, si.shading.dpdu), 0, 1e-5);
    }
}

TEST(Triangle, DefaultUVParameterization) {
    // Without "uv", pbrt assigns (0,0), (1,0), (1,1) to the vertices.
    auto group = test::mesh_group({}, false, {0, 1, 2}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    auto scene = test::scene_of({group});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{0.2f, 0.3f, 1}, {0, 0, -1}}, &si));
    // Barycentrics (0.5, 0.2, 0.3): uv = 0.2 (1, 0) + 0.3 (1, 1).
    EXPECT_NEAR(si.uv.x, 0.5f, 1e-6);
    EXPECT_NEAR(si.uv.y, 0.3f, 1e-6);
}

// pbrt-v4: n = normalize(cross(p0 - p2, p1 - p2)), flipped by ReverseOrientation XOR a
// handedness-swapping transform; with "N", flipped to the side of the interpolated normal, and
// ReverseOrientation reverses "N" itself.
TEST(Triangle, NormalOrientationRules) {
    std::vector<Vec3f> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}; // cross(p0-p2, p1-p2) = +z
    Transform mirror_z = Transform::scale(1, 1, -1);          // keeps the z = 0 plane
    struct Case {
        Transform t;
        bool reverse;
        std::vector<Vec3f> n;
        float expected_z;
    } cases[] = {
        {{}, false, {}, 1},
        {{}, true, {}, -1},
        {mirror_z, false, {}, -1},
        {mirror_z, true, {}, 1},
        {{}, false, {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}}, -1},
        {{}, true, {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}}, 1},
        // The mirror maps the given normals to +z.
        {mirror_z, false, {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}}, 1},
    };
    for (const Case &c : cases) {
        auto group = test::mesh_group(c.t, c.reverse, {0, 1, 2}, p, c.n);
        auto scene = test::scene_of({group});
        SurfaceInteraction si;
        ASSERT_TRUE(scene->intersect({{0.2f, 0.2f, 1}, {0, 0, -1}}, &si));
        EXPECT_EQ(si.n.z, c.expected_z);
        EXPECT_GT(dot(si.shading.n, si.n), 0);
        // Sampling reports the same orientation (area lights emit on that side).
        Triangle tri(group->mesh, 0);
        auto ss = tri.sample(Vec2f{0.3f, 0.4f});
        ASSERT_TRUE(ss);
        EXPECT_EQ(ss->n.z, c.expected_z);
    }
}

TEST(TriangleMesh, ValidatesIndicesAndDropsDegenerateTriangles) {
    test::QuietWarnings quiet;
    std::vector<Vec3f> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    EXPECT_THROW(TriangleMesh({}, false, {0, 1, 4}, p, {}, {}), InputError);
    EXPECT_THROW(TriangleMesh({}, false, {0, 1, -1}, p, {}, {}), InputError);
    EXPECT_THROW(TriangleMesh({}, false, {0, 1}, p, {}, {}), InputError);
    EXPECT_THROW(TriangleMesh({}, false, {0, 1, 2}, p, {{0, 0, 1}}, {}), InputError);
    // 0-1-3 is collinear and 1-1-2 repeats a vertex: both have zero area.
    TriangleMesh mesh({}, false, {0, 1, 2, 0, 1, 3, 1, 1, 2, 1, 3, 2}, p, {}, {});
    ASSERT_EQ(mesh.triangle_count(), 2);
    EXPECT_EQ(mesh.vertices(0), (std::array<int, 3>{0, 1, 2}));
    EXPECT_EQ(mesh.vertices(1), (std::array<int, 3>{1, 3, 2}));
    EXPECT_FLOAT_EQ(mesh.area(0) + mesh.area(1), 1.0f);
}

TEST(TriangleMesh, RenderSpacePositionsAndNormals) {
    Transform t = Transform::translate({1, 2, 3}) * Transform::scale(2, 1, 1);
    TriangleMesh mesh(t, false, {0, 1, 2}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                      {{1, 0, 1}, {1, 0, 1}, {1, 0, 1}}, {});
    expect_near_vec(mesh.positions()[1], {3, 2, 3}, 0);
    // Normals transform by the inverse transpose: (1, 0, 1) -> (1/2, 0, 1).
    expect_near_vec(mesh.normals()[0], {0.5f, 0, 1}, 1e-7f);
    EXPECT_FLOAT_EQ(mesh.area(0), 1.0f);
}

} // namespace
} // namespace caustica
