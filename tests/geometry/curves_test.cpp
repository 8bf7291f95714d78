// pbrt-v4's "curve" shape (geometry/curves.h) in GeometryScene: where rays hit flat, cylinder and
// ribbon curves, the (u, v) and normals of the hits as pbrt-v4's Curve gives them, B-spline and
// quadratic control points, rays leaving a curve, and bad parameters as InputErrors at their
// parameter.
#include "geometry/shape_factory.h"
#include "geometry_test_util.h"

#include <cmath>

namespace caustica {
namespace {

using test::create_shape;
using test::dictionary;
using test::numbers;
using test::strings;

const SourceLocation loc{"test.pbrt", 3, 1};

std::shared_ptr<ShapeGroup> curve(std::vector<ParsedParameter> params, const Transform &t = {}) {
    return create_shape("curve", t, false, dictionary(std::move(params)), loc);
}

// A straight curve along x from -1 to 1 at y = 0, z = 0, control points evenly spaced (so that
// u = (x + 1) / 2), of the given type and width.
std::shared_ptr<ShapeGroup> straight(const std::string &type, float width) {
    return curve({numbers("point3", "P", {-1, 0, 0, -1.f / 3, 0, 0, 1.f / 3, 0, 0, 1, 0, 0}),
                  strings("string", "type", {type}), numbers("float", "width", {width}),
                  numbers("normal3", "N", {0, 0, -1, 0, 0, -1})});
}

// A ray from z = -2 towards +z through (x, y).
Ray towards_z(float x, float y) { return Ray{{x, y, -2}, {0, 0, 1}}; }

TEST(Curves, FlatCurveFacesTheRayWithPbrtsUvAndNormal) {
    auto scene = test::scene_of({straight("flat", 0.2f)});
    for (float y : {-0.09f, -0.05f, 0.f, 0.03f, 0.08f}) {
        for (float x : {-0.5f, 0.f, 0.6f}) {
            SurfaceInteraction si;
            ASSERT_TRUE(scene->intersect(towards_z(x, y), &si)) << x << " " << y;
            EXPECT_NEAR(si.t, 2, 1e-4f);
            EXPECT_NEAR(si.uv.x, (x + 1) / 2, 2e-3f);
            // v runs along dp/dv = cross(d, dp/du) = +y, from 0 to 1 over the width.
            EXPECT_NEAR(si.uv.y, 0.5f + y / 0.2f, 1e-3f);
            // n = cross(dp/du, dp/dv): along the ray, as in pbrt-v4.
            test::expect_near_vec(si.n, {0, 0, 1}, 1e-5f);
            test::expect_near_vec(normalize(si.dpdu), {1, 0, 0}, 1e-5f);
        }
    }
    for (float y : {-0.11f, 0.105f, 0.3f}) {
        SurfaceInteraction si;
        EXPECT_FALSE(scene->intersect(towards_z(0, y), &si)) << y;
    }
    // Seen from the side (along y), the flat curve faces that ray too.
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect(Ray{{0.2f, -2, 0.07f}, {0, 1, 0}}, &si));
    test::expect_near_vec(si.n, {0, 1, 0}, 1e-5f);
}

TEST(Curves, CylinderNormalTurnsAcrossTheWidth) {
    auto scene = test::scene_of({straight("cylinder", 0.2f)});
    for (float y : {-0.099f, -0.05f, 0.f, 0.05f, 0.099f}) {
        SurfaceInteraction si;
        ASSERT_TRUE(scene->intersect(towards_z(0.1f, y), &si));
        const float v = 0.5f + y / 0.2f, theta = Pi * (v - 0.5f);
        // pbrt-v4 turns dp/dv (+y) by -theta about dp/du (+x): the normal goes from -y at v = 0
        // through +z to +y at v = 1.
        test::expect_near_vec(si.n, {0, std::sin(theta), std::cos(theta)}, 2e-3f);
    }
}

TEST(Curves, RibbonIsNarrowedByTheCosineOfItsNormal) {
    // Facing the ray: the full width.
    auto facing = test::scene_of({straight("ribbon", 0.2f)});
    SurfaceInteraction si;
    ASSERT_TRUE(facing->intersect(towards_z(0, 0.09f), &si));
    test::expect_near_vec(si.n, {0, 0, -1}, 1e-5f);
    EXPECT_NEAR(si.uv.y, 0.5f - 0.09f / 0.2f, 1e-3f);  // dp/dv = cross(n, dp/du) = -y
    // Turned 60 degrees about the curve: half the width.
    auto turned = test::scene_of({curve({numbers("point3", "P", {-1, 0, 0, -0.3f, 0, 0, 0.3f, 0, 0, 1, 0, 0}),
                                         strings("string", "type", {"ribbon"}), numbers("float", "width", {0.2f}),
                                         numbers("normal3", "N", {0, std::sin(Pi / 3), -0.5f, 0, std::sin(Pi / 3), -0.5f})})});
    EXPECT_TRUE(turned->intersect(towards_z(0, 0.045f), &si));
    EXPECT_FALSE(turned->intersect(towards_z(0, 0.055f), &si));
    EXPECT_FALSE(turned->occluded(towards_z(0, 0.055f)));
}

TEST(Curves, WidthIsLinearAlongTheWholeCurve) {
    // Two Bezier segments sharing a point; width0 0.4 at x = -1, width1 0 at x = 1.
    auto scene = test::scene_of({curve({numbers("point3", "P", {-1, 0, 0, -0.67f, 0, 0, -0.33f, 0, 0, 0, 0, 0,
                                                              0.33f, 0, 0, 0.67f, 0, 0, 1, 0, 0}),
                                        numbers("float", "width0", {0.4f}), numbers("float", "width1", {0})})});
    for (float x : {-0.8f, -0.4f, 0.2f, 0.6f}) {
        const float half_width = 0.5f * 0.4f * (1 - x) / 2;
        EXPECT_TRUE(scene->occluded(towards_z(x, 0.95f * half_width))) << x;
        EXPECT_FALSE(scene->occluded(towards_z(x, 1.05f * half_width))) << x;
    }
}

// A curve narrowing to width 0 has a finite surface record everywhere it is met, its tip too.
TEST(Curves, ZeroWidthTipsHaveFiniteRecords) {
    for (const char *type : {"flat", "cylinder"}) {
        auto group = curve({numbers("point3", "P", {-1, 0, 0, -1.f / 3, 0, 0, 1.f / 3, 0, 0, 1, 0, 0}),
                            strings("string", "type", {type}), numbers("float", "width0", {0.2f}),
                            numbers("float", "width1", {0})});
        SurfaceInteraction si;
        group->curves->interaction(0, 1, towards_z(1, 0), 2, &si);
        EXPECT_TRUE(std::isfinite(si.n.x) && std::isfinite(si.n.y) && std::isfinite(si.n.z)) << type;
        EXPECT_NEAR(length(si.n), 1, 1e-5f) << type;
        EXPECT_EQ(si.uv.y, 0.5f) << type;
    }
}

TEST(Curves, BSplinesAndQuadraticsAreTheirBezierSegments) {
    // A cubic uniform B-spline's segment runs from (p0 + 4 p1 + p2) / 6 to (p1 + 4 p2 + p3) / 6
    // through (p0 + 23 p1 + 23 p2 + p3) / 48; a quadratic one's from midpoint to midpoint of its
    // control polygon.
    auto cubic = test::scene_of({curve({numbers("point3", "P", {-1, 0.6f, 0, -0.5f, 0, 0, 0.5f, 0, 0, 1, 0.6f, 0}),
                                        strings("string", "basis", {"bspline"}), numbers("float", "width", {0.02f})})});
    EXPECT_TRUE(cubic->occluded(towards_z(0, 0.025f)));
    EXPECT_FALSE(cubic->occluded(towards_z(0, 0.05f)));     // a Bezier of the same points: y 0.15
    EXPECT_FALSE(cubic->occluded(towards_z(0, 0.15f)));
    EXPECT_FALSE(cubic->occluded(towards_z(-0.45f, 0.1f)));  // before its start at x = -5 / 12
    EXPECT_FALSE(cubic->occluded(towards_z(0.45f, 0.1f)));
    auto quadratic = test::scene_of({curve({numbers("point3", "P", {-1, 0, 0, 0, 1, 0, 1, 0, 0}),
                                            numbers("integer", "degree", {2}), numbers("float", "width", {0.02f})})});
    EXPECT_TRUE(quadratic->occluded(towards_z(0, 0.5f)));   // the top of the parabola
    EXPECT_FALSE(quadratic->occluded(towards_z(0, 0.55f)));
    auto quadratic_bspline = test::scene_of({curve({numbers("point3", "P", {-1, 0, 0, 0, 1, 0, 1, 0, 0}),
                                                    strings("string", "basis", {"bspline"}),
                                                    numbers("integer", "degree", {2}), numbers("float", "width", {0.02f})})});
    EXPECT_TRUE(quadratic_bspline->occluded(towards_z(-0.5f, 0.5f)));
    EXPECT_TRUE(quadratic_bspline->occluded(towards_z(0, 0.75f)));
}

TEST(Curves, TransformedCurvesScaleTheirWidth) {
    auto scene = test::scene_of({curve({numbers("point3", "P", {-1, 0, 0, -0.3f, 0, 0, 0.3f, 0, 0, 1, 0, 0}),
                                        numbers("float", "width", {0.1f})},
                                       Transform::scale(2, 2, 2))});
    EXPECT_TRUE(scene->occluded(towards_z(1.5f, 0.095f)));
    EXPECT_FALSE(scene->occluded(towards_z(1.5f, 0.105f)));
}

// Rays that leave a point of a curve, in every direction, do not meet the same curve again, as
// they would not a thin tube (GeometryScene's curve filter).
TEST(Curves, RaysLeavingACurveDoNotHitItAgain) {
    auto scene = test::scene_of({straight("cylinder", 0.2f)});
    Rng rng(7, 2);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        SurfaceInteraction si;
        ASSERT_TRUE(scene->intersect(towards_z(1.6f * rng.uniform() - 0.8f, 0.18f * rng.uniform() - 0.09f), &si));
        const Vec2f u = rng.uniform2();
        const float z = 1 - 2 * u.x, r = std::sqrt(std::max(0.f, 1 - z * z)), phi = 2 * Pi * u.y;
        const Ray leaving = si.spawn_ray({r * std::cos(phi), r * std::sin(phi), z});
        SurfaceInteraction again;
        hits += scene->intersect(leaving, &again) && again.t < 0.5f;
        hits += scene->occluded(Ray{leaving.o, leaving.d, 0.5f});
    }
    EXPECT_EQ(hits, 0);
    // Rays that start a little more than a width from the curve still meet it, and a ray that
    // ends on the curve is not stopped by it.
    EXPECT_TRUE(scene->occluded(Ray{{0.3f, 0.02f, -0.25f}, {0, 0, 1}, 1}));
    EXPECT_TRUE(scene->occluded(Ray{{0.3f, 0.25f, 0.01f}, {0, -1, 0}, 1}));
    SurfaceInteraction si;
    ASSERT_TRUE(scene->intersect(towards_z(0.3f, 0.05f), &si));
    for (Vec3f from : {Vec3f{2, 1, -1}, Vec3f{-1.5f, 0.05f, 0.1f}, Vec3f{0.3f, -1, 1}}) {
        const Ray to_curve = caustica::spawn_ray_to(from, {}, 0, si.p, si.n, si.error_scale, 0);
        EXPECT_FALSE(scene->occluded(to_curve)) << from.x;
    }
}

int error_line(std::vector<ParsedParameter> params) {
    try {
        curve(std::move(params));
    } catch (const InputError &e) {
        return e.location().line;
    }
    return -1;
}

ParsedParameter at_line(ParsedParameter p, int line) {
    p.loc.line = line;
    return p;
}

TEST(Curves, BadParametersAreInputErrorsAtTheParameter) {
    const ParsedParameter four = numbers("point3", "P", {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0});
    // A cubic Bezier needs 4 + 3 n points.
    EXPECT_EQ(error_line({at_line(numbers("point3", "P", {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 0}), 7)}), 7);
    EXPECT_EQ(error_line({at_line(numbers("point3", "P", {0, 0, 0, 1, 0, 0}), 7)}), 7);
    EXPECT_EQ(error_line({at_line(numbers("point3", "P", {0, 0, 0, 1, 0, 0}), 7),
                          strings("string", "basis", {"bspline"})}), 7);
    EXPECT_EQ(error_line({four, at_line(numbers("integer", "degree", {4}), 8)}), 8);
    EXPECT_EQ(error_line({four, at_line(strings("string", "basis", {"hermite"}), 9)}), 9);
    EXPECT_EQ(error_line({four, at_line(strings("string", "type", {"tube"}), 10)}), 10);
    EXPECT_EQ(error_line({four, at_line(numbers("float", "width", {-1}), 11)}), 11);
    // A ribbon needs one normal per segment end.
    EXPECT_EQ(error_line({four, strings("string", "type", {"ribbon"})}), 1);  // the Shape's line
    EXPECT_EQ(error_line({four, strings("string", "type", {"ribbon"}), at_line(numbers("normal3", "N", {0, 0, 1}), 12)}), 12);
    EXPECT_EQ(error_line({four, strings("string", "type", {"ribbon"}),
                          at_line(numbers("normal3", "N", {0, 0, 1, 0, 0, 0}), 13)}), 13);
    EXPECT_EQ(error_line({four}), -1);
}

} // namespace
} // namespace caustica
