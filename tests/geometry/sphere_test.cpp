#include "core/rng.h"
#include "geometry/sphere.h"
#include "geometry_test_util.h"

namespace caustica {
namespace {

using test::expect_near_vec;

std::shared_ptr<Sphere> sphere(float radius, const Transform &t = {}, bool reverse = false,
                               float z_min = -1e30f, float z_max = 1e30f, float phi_max = 360) {
    return std::make_shared<Sphere>(t, reverse, radius, z_min, z_max, phi_max);
}

TEST(Sphere, HitsOnAxisAndOffAxisAgainstClosedForm) {
    auto scene = test::scene_of({test::analytic_group(sphere(2))});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{0, 0, -5}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.t, 3, 1e-6);
    expect_near_vec(si.p, {0, 0, -2}, 1e-6f);
    expect_near_vec(si.n, {0, 0, -1}, 1e-6f);
    expect_near_vec(si.wo, {0, 0, -1}, 1e-7f);

    // x = 1: the chord starts at z = -sqrt(r^2 - x^2).
    ASSERT_TRUE(scene->intersect({{1, 0, -5}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.t, 5 - std::sqrt(3.f), 1e-5);
    expect_near_vec(si.p, {1, 0, -std::sqrt(3.f)}, 1e-6f);
    expect_near_vec(si.n, {0.5f, 0, -std::sqrt(3.f) / 2}, 1e-6f);
    EXPECT_NEAR(length(si.p), 2, 2e-7);
}

TEST(Sphere, MissesAndTangentRays) {
    auto scene = test::scene_of({test::analytic_group(sphere(2))});
    SurfaceInteraction si;
    EXPECT_FALSE(scene->intersect({{2.0001f, 0, -5}, {0, 0, 1}}, &si));
    EXPECT_FALSE(scene->intersect({{0, 0, -5}, {0, 0, -1}}, &si));  // pointing away
    EXPECT_FALSE(scene->intersect({{0, 0, -5}, {0, 0, 1}, 2.9f}, &si)); // t_max short of it
    EXPECT_FALSE(scene->occluded({{0, 0, -5}, {0, 0, 1}, 2.9f}));
    EXPECT_TRUE(scene->occluded({{0, 0, -5}, {0, 0, 1}, 3.1f}));
    // Nearly tangent: x = 1.9999 gives half-chord sqrt(4 - x^2) ~ 0.02.
    ASSERT_TRUE(scene->intersect({{1.9999f, 0, -5}, {0, 0, 1}}, &si));
    double x = 1.9999f;
    EXPECT_NEAR(si.t, 5 - std::sqrt(4 - x * x), 1e-4);
}

TEST(Sphere, FromInsideHitsFarSideWithOutwardNormal) {
    auto scene = test::scene_of({test::analytic_group(sphere(2))});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{0, 0, 0}, {0, 1, 0}}, &si));
    EXPECT_NEAR(si.t, 2, 1e-6);
    expect_near_vec(si.n, {0, 1, 0}, 1e-6f);
    ASSERT_TRUE(scene->intersect({{0.5f, 0, 0}, {-1, 0, 0}}, &si));
    EXPECT_NEAR(si.t, 2.5, 1e-6);
}

TEST(Sphere, TransformedSphere) {
    // Radius 1 scaled by 2 and moved to (3, 4, 5).
    Transform t = Transform::translate({3, 4, 5}) * Transform::scale(2, 2, 2);
    auto scene = test::scene_of({test::analytic_group(sphere(1, t))});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{3, 4, -5}, {0, 0, 1}}, &si));
    EXPECT_NEAR(si.t, 8, 1e-5);
    expect_near_vec(si.p, {3, 4, 3}, 1e-5f);
    expect_near_vec(si.n, {0, 0, -1}, 1e-6f);

    // An ellipsoid x^2 + (y/2)^2 + (z/3)^2 = 1 against the quadratic solved here.
    Transform e = Transform::scale(1, 2, 3);
    auto ellipsoid = test::scene_of({test::analytic_group(sphere(1, e))});
    Vec3f o{-3, -1, 0.5f}, d = normalize(Vec3f{1, 0.3f, 0.1f});
    double a = sqr(d.x) + sqr(d.y / 2.) + sqr(d.z / 3.);
    double b = 2 * (o.x * d.x + o.y * d.y / 4. + o.z * d.z / 9.);
    double c = sqr(o.x) + sqr(o.y / 2.) + sqr(o.z / 3.) - 1;
    double t0 = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
    ASSERT_TRUE(ellipsoid->intersect({o, d}, &si));
    EXPECT_NEAR(si.t, t0, 1e-5);
    Vec3f p = si.p;
    // Normal of the implicit surface: gradient (x, y/4, z/9).
    Vec3f gradient = normalize(Vec3f{p.x, p.y / 4, p.z / 9});
    expect_near_vec(si.n, gradient, 1e-5f);
}

TEST(Sphere, UVAndDerivatives) {
    auto s = sphere(2);
    auto scene = test::scene_of({test::analytic_group(s)});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{0, 5, 0}, {0, -1, 0}}, &si));
    // phi = pi/2 of 2 pi; theta = pi/2, v runs from 0 at z = -r to 1 at z = r.
    EXPECT_NEAR(si.uv.x, 0.25f, 1e-6);
    EXPECT_NEAR(si.uv.y, 0.5f, 1e-6);
    // Derivatives: p(u, v) = r (sin theta cos phi, sin theta sin phi, cos theta) with
    // phi = 2 pi u, theta = pi (1 - v): at this point dp/du = 2 pi r (-1, 0, 0),
    // dp/dv = -pi * dp/dtheta = -pi r (0, 0, -1).
    expect_near_vec(si.dpdu, {-2 * Pi * 2, 0, 0}, 1e-4f);
    expect_near_vec(si.dpdv, {0, 0, Pi * 2}, 1e-4f);
    // The normal is the direction of dp/du x dp/dv.
    expect_near_vec(si.n, normalize(cross(si.dpdu, si.dpdv)), 1e-6f);
}

TEST(Sphere, PartialSphereSkipsCutAwayParts) {
    // Lower hemisphere only (zmax = 0): a ray from above passes the missing top.
    auto s = sphere(2, {}, false, -2, 0, 360);
    auto scene = test::scene_of({test::analytic_group(s)});
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect({{0.5f, 0, 5}, {0, 0, -1}}, &si));
    EXPECT_NEAR(si.t, 5 + std::sqrt(3.75), 1e-5);
    // phi_max = 90 degrees: only the quadrant x, y >= 0.
    auto quadrant = test::scene_of({test::analytic_group(sphere(2, {}, false, -2, 2, 90))});
    EXPECT_TRUE(quadrant->intersect({{1, 1, -5}, {0, 0, 1}}, &si));
    EXPECT_FALSE(quadrant->intersect({{-1, 1, -5}, {0, 0, 1}}, &si));
    EXPECT_NEAR(s->area(), 2 * Pi * 2 * 2, 1e-4); // half of 4 pi r^2
}

// pbrt's rule: the normal is dp/du x dp/dv in render space, reversed by ReverseOrientation.
// For a sphere dp/du x dp/dv points outwards in object space, so under a mirroring transform
// (which reverses the cross product of transformed tangents) the normal points inwards.
TEST(Sphere, NormalOrientationRules) {
    Transform mirror = Transform::scale(-1, 1, 1);
    struct Case {
        Transform t;
        bool reverse;
        float expected_z; // normal at the hit point (0, 0, -2) seen from below
    } cases[] = {{{}, false, -1}, {{}, true, 1}, {mirror, false, 1}, {mirror, true, -1}};
    for (const Case &c : cases) {
        auto scene = test::scene_of({test::analytic_group(sphere(2, c.t, c.reverse))});
        SurfaceInteraction si;
        ASSERT_TRUE(scene->intersect({{0.3f, 0.2f, -5}, {0, 0, 1}}, &si));
        EXPECT_NEAR(si.n.z, c.expected_z * std::abs(si.n.z), 1e-6);
        Vec3f cross_n = normalize(cross(si.dpdu, si.dpdv));
        expect_near_vec(si.n, c.reverse ? -cross_n : cross_n, 1e-5f);
        expect_near_vec(si.shading.n, si.n, 1e-6f);
    }
}

// Sphere::nth_hit first rejects, in float, the rays that certainly miss a ball around the
// sphere. Rays through the rim, where that rejection is closest to being wrong, must still hit
// exactly when the line passes inside: checked against the line's distance from the centre in
// double, for spheres far from the origin (where float rounds coarsest), stretched ones, and
// ray directions of any length.
TEST(Sphere, FloatRejectionNeverDropsAHitAtTheRim) {
    struct Case {
        Transform t;
        double radius; // along every axis: the stretched case is tested through its x axis
    } cases[] = {{Transform::translate({3e4f, -2e4f, 1e4f}) * Transform::scale(0.01f, 0.01f, 0.01f), 0.01},
                 {Transform::translate({-1, 2, 3}) * Transform::scale(5, 5, 5), 5},
                 {Transform::translate({1e3f, 0, 0}) * Transform::scale(1, 4, 9), 1}};
    Rng rng(7, 0);
    for (const Case &c : cases) {
        auto s = sphere(1, c.t);
        const Vec3d center(c.t.apply_point({0, 0, 0}));
        int hits = 0, misses = 0;
        for (int i = 0; i < 20000; ++i) {
            // A line along y or z (so a stretched sphere's section through x is a circle of the
            // given radius), at distance (1 + e) radius from the centre along x, e in +-1e-3 or
            // +-4 float spacings of the centre's coordinates, whichever is wider.
            const double spacing = std::ldexp(1.0, std::ilogb(std::max({std::abs(center.x), std::abs(center.y), std::abs(center.z), 1.0})) - 23);
            const double e = (rng.uniform() * 2 - 1) * std::max(1e-3, 4 * spacing / c.radius);
            const Vec3f along = rng.uniform() < 0.5f ? Vec3f{0, 1, 0} : Vec3f{0, 0, 1};
            const float length = std::ldexp(1.f, int(rng.uniform() * 8) - 4);
            const Vec3f o = (Vec3d{center.x + (1 + e) * c.radius, center.y, center.z} -
                             Vec3d(along) * (50.0 * c.radius))
                                .to_float();
            // The float ray as it is: its true distance from the centre, in double.
            const Vec3d od = Vec3d(o) - center;
            const double distance = std::sqrt(od.x * od.x + (along.y ? od.z * od.z : od.y * od.y));
            if (std::abs(distance / c.radius - 1) < 1e-6) continue; // too close to call in double
            const bool expected = distance < c.radius;
            EXPECT_EQ(s->intersect_t(o, along * length, Infinity).has_value(), expected)
                << "distance / radius - 1 = " << distance / c.radius - 1;
            (expected ? hits : misses)++;
        }
        EXPECT_GT(hits, 1000);
        EXPECT_GT(misses, 1000);
    }
}

TEST(Sphere, SpheroidAreaMatchesClosedForm) {
    // Oblate spheroid with semi-axes a = 2 (x, y) and c = 1 (z):
    // S = 2 pi a^2 + pi c^2 / e ln((1 + e) / (1 - e)), e^2 = 1 - c^2 / a^2.
    auto s = sphere(1, Transform::scale(2, 2, 1));
    double a = 2, c = 1, e = std::sqrt(1 - c * c / (a * a));
    double expected = 2 * M_PI * a * a + M_PI * c * c / e * std::log((1 + e) / (1 - e));
    EXPECT_NEAR(s->area(), expected, 1e-4 * expected);
    // Uniform scale: 4 pi (s r)^2.
    EXPECT_NEAR(sphere(1.5f, Transform::scale(2, 2, 2))->area(), 4 * Pi * 9, 1e-3);
}

} // namespace
} // namespace caustica
