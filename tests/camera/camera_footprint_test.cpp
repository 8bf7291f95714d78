// The texture footprint (src/camera/camera_footprint.h) against closed forms: the screen-space
// derivatives of a point on a plane seen by orthographic and perspective cameras, from a camera
// ray's differentials and from pbrt-v4's approximation, and du/dx ... by least squares.
#include "camera/camera_factory.h"
#include "camera/camera_footprint.h"
#include "geometry/interaction.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace caustica;

namespace {

const SampledWavelengths kLambda = SampledWavelengths::fixed(550);
constexpr int kResolution = 64;

ParameterDictionary no_params() { return ParameterDictionary({}, SourceLocation{"scene.pbrt", 1, 1}, nullptr, "."); }

CameraPtr camera(const std::string &type) {
    return create_camera(type, Transform(), Vec2i{kResolution, kResolution}, no_params(), SourceLocation{});
}

// The point where the ray through film position p_film meets the plane through `on` with normal
// n, as a surface interaction with dp/du = (2, 0, 0) and dp/dv along the plane's other axis, 3
// long, and the camera ray that found it.
struct PlaneHit {
    SurfaceInteraction si;
    CameraRay ray;
};

PlaneHit hit_plane(const Camera &cam, Vec2f p_film, Vec3f on, Vec3f n, float scale) {
    CameraSample s;
    s.p_film = p_film;
    s.p_lens = {0.5f, 0.5f};
    PlaneHit h;
    h.ray = *generate_ray_differential(cam, s, kLambda, scale);
    const float t = dot(n, on - h.ray.ray.o) / dot(n, h.ray.ray.d);
    h.si.p = h.ray.ray.at(t);
    h.si.n = n;
    h.si.dpdu = {2, 0, 0};
    h.si.dpdv = normalize(cross(n, Vec3f{1, 0, 0})) * 3.f;
    return h;
}

TEST(CameraFootprint, DifferentialScaleFollowsPbrtV4) {
    EXPECT_FLOAT_EQ(differential_scale(1), 1.f);
    EXPECT_FLOAT_EQ(differential_scale(16), 0.25f);
    EXPECT_FLOAT_EQ(differential_scale(64), 0.125f);
    EXPECT_FLOAT_EQ(differential_scale(4096), 0.125f);
}

// An orthographic camera's rays are parallel, a pixel (2/64: pbrt-v4's screen window [-1, 1])
// apart. On a plane tilted by angle a about x, a step in x moves the point 2/64 along x, a step
// in y 2/64 / cos(a) along the plane's slope; the ray differentials give exactly that, and
// dp/du = (2, 0, 0), |dp/dv| = 3 give du/dx = (2/64) / 2, dv/dy = (2/64 / cos a) / 3. (pbrt-v4's
// approximation assumes rays from one centre, so it is only near for this camera.)
TEST(CameraFootprint, OrthographicFootprintOnATiltedPlane) {
    const CameraPtr cam = camera("orthographic");
    const float a = radians(50), pixel = 2.f / kResolution;
    const Vec3f n = normalize(Vec3f{0, std::sin(a), -std::cos(a)});
    PlaneHit h = hit_plane(*cam, {20.3f, 41.7f}, {0, 0, 5}, n, 1.f);
    {
        SurfaceInteraction si = h.si;
        compute_differentials(si, &*h.ray.differential, nullptr, 1);
        EXPECT_NEAR(std::abs(si.dpdx.x), pixel, 1e-4f);
        EXPECT_NEAR(si.dpdx.y, 0, 1e-4f);
        EXPECT_NEAR(length(si.dpdy), pixel / std::cos(a), 1e-4f);
        EXPECT_NEAR(std::abs(dot(si.dpdy, n)), 0, 1e-5f);
        EXPECT_NEAR(std::abs(si.dudx), pixel / 2, 1e-4f);
        EXPECT_NEAR(si.dvdx, 0, 1e-4f);
        EXPECT_NEAR(si.dudy, 0, 1e-4f);
        EXPECT_NEAR(std::abs(si.dvdy), pixel / std::cos(a) / 3, 1e-4f);
    }
    // Differentials for 16 samples per pixel: a quarter of a pixel.
    const PlaneHit quarter = hit_plane(*cam, {20.3f, 41.7f}, {0, 0, 5}, n, differential_scale(16));
    SurfaceInteraction si = quarter.si;
    compute_differentials(si, &*quarter.ray.differential, nullptr, 16);
    EXPECT_NEAR(std::abs(si.dpdx.x), pixel / 4, 1e-5f);
}

// A pinhole (perspective, pbrt-v4's default fov of 90 degrees on a square film) at the origin: at the centre of the image a
// plane facing it at distance D sees a pixel 2 D tan(45 deg) / 64 wide. pbrt-v4's approximation
// uses the camera's smallest differentials (at the corners, where the film is seen at an angle),
// so it is smaller there, by the corner's cos^2 at most.
TEST(CameraFootprint, PerspectiveFootprintAtTheImageCentre) {
    const CameraPtr cam = camera("perspective");
    const float D = 7, pixel = 2 * D / kResolution;
    PlaneHit h = hit_plane(*cam, {32, 32}, {0, 0, D}, {0, 0, -1}, 1.f);
    SurfaceInteraction exact = h.si;
    compute_differentials(exact, &*h.ray.differential, nullptr, 1);
    EXPECT_NEAR(length(exact.dpdx), pixel, 1e-3f * pixel);
    EXPECT_NEAR(length(exact.dpdy), pixel, 1e-3f * pixel);
    EXPECT_NEAR(dot(exact.dpdx, exact.dpdy), 0, 1e-6f);

    const CameraFootprint footprint(*cam, Transform(), {kResolution, kResolution});
    SurfaceInteraction approx = h.si;
    compute_differentials(approx, nullptr, &footprint, 1);
    const float corner_cos = std::cos(std::atan(std::sqrt(2.f)));
    for (const Vec3f d : {approx.dpdx, approx.dpdy}) {
        EXPECT_LE(length(d), pixel * 1.001f);
        EXPECT_GE(length(d), pixel * corner_cos * corner_cos * 0.999f);
    }
    // With more samples per pixel, proportionally smaller, down to an eighth of a pixel.
    for (const int spp : {16, 1024}) {
        SurfaceInteraction fewer = h.si;
        compute_differentials(fewer, nullptr, &footprint, spp);
        EXPECT_NEAR(length(fewer.dpdx), length(approx.dpdx) * differential_scale(spp), 1e-6f);
    }
}

// Without a differential or a footprint the derivatives are zero (texture lookups then use the
// finest level); a plane seen edge-on gives none rather than infinities.
TEST(CameraFootprint, NoFootprintGivesZeroDerivatives) {
    const CameraPtr cam = camera("orthographic");
    PlaneHit h = hit_plane(*cam, {10, 10}, {0, 0, 5}, {0, 0, -1}, 1.f);
    compute_differentials(h.si, nullptr, nullptr, 1);
    EXPECT_EQ(h.si.dpdx, Vec3f{});
    EXPECT_EQ(h.si.dudx, 0.f);

    const CameraFootprint footprint(*cam, Transform(), {kResolution, kResolution});
    SurfaceInteraction edge_on = h.si;
    edge_on.n = {1, 0, 0};
    compute_differentials(edge_on, nullptr, &footprint, 1);
    EXPECT_TRUE(is_finite(edge_on.dpdx) && is_finite(edge_on.dpdy));
    EXPECT_TRUE(std::isfinite(edge_on.dudx) && std::isfinite(edge_on.dvdy));
}

} // namespace
