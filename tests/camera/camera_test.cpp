#include "camera/camera_factory.h"
#include "camera/orthographic_camera.h"
#include "camera/perspective_camera.h"
#include "core/rng.h"
#include "core/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace caustica;

namespace {

const SampledWavelengths kLambda = SampledWavelengths::fixed(550);

ParsedParameter float_param(const std::string &name, std::vector<double> v) {
    ParsedParameter p;
    p.type = "float";
    p.name = name;
    p.numbers = std::move(v);
    return p;
}

ParameterDictionary dict(std::vector<ParsedParameter> params) {
    return ParameterDictionary(std::move(params), SourceLocation{"scene.pbrt", 5, 1}, nullptr, ".");
}

// The camera basis of pbrt's LookAt, derived here independently: the camera looks along
// dir, +x is cross(up, dir) ("right" in pbrt's left-handed convention) and +y completes it.
struct Basis {
    Vec3f pos, dir, right, up;
};

Basis look_at_basis(Vec3f pos, Vec3f look, Vec3f up) {
    Basis b;
    b.pos = pos;
    b.dir = normalize(look - pos);
    b.right = normalize(cross(normalize(up), b.dir));
    b.up = cross(b.dir, b.right);
    return b;
}

Transform world_from_camera(Vec3f pos, Vec3f look, Vec3f up) {
    return Transform::look_at(pos, look, up).inverse();
}

float angle_between(Vec3f a, Vec3f b) { return std::acos(clamp(dot(normalize(a), normalize(b)), -1.f, 1.f)); }

CameraRay ray_through(const Camera &camera, Vec2f p_film, Vec2f p_lens = {0.5f, 0.5f}) {
    CameraSample s;
    s.p_film = p_film;
    s.p_lens = p_lens;
    auto r = camera.generate_ray(s, kLambda);
    EXPECT_TRUE(r.has_value());
    return *r;
}

// pbrt-v4's raster position of a camera-space point for a perspective camera with the default
// screen window, from the projection's definition: screen = (x, y) / (z tan(fov/2)); the
// window spans [-aspect, aspect] x [-1, 1] (or [-1, 1] x [-1/aspect, 1/aspect] for portrait);
// raster x grows with screen x, raster y grows downwards from the window's top edge.
Vec2f expected_raster(Vec3f p_cam, float fov_deg, Vec2i res) {
    float t = std::tan(radians(fov_deg) / 2);
    float sx = p_cam.x / (p_cam.z * t), sy = p_cam.y / (p_cam.z * t);
    float aspect = float(res.x) / res.y;
    float hx = aspect > 1 ? aspect : 1, hy = aspect > 1 ? 1 : 1 / aspect;
    return {(sx + hx) / (2 * hx) * res.x, (hy - sy) / (2 * hy) * res.y};
}

} // namespace

TEST(PerspectiveCamera, CentreRayFollowsTheViewDirection) {
    Vec3f pos{1, 2, 3}, look{4, 2, -1};
    Basis b = look_at_basis(pos, look, {0, 1, 0});
    PerspectiveCamera cam(world_from_camera(pos, look, {0, 1, 0}), FilmExtent::whole_image({64, 48}),
                          60, default_screen_window(64.f / 48), 0, 1e6f);
    CameraRay r = ray_through(cam, {32, 24});
    EXPECT_NEAR(distance(r.ray.o, pos), 0, 1e-5f);
    EXPECT_NEAR(length(r.ray.d), 1, 1e-6f);
    EXPECT_NEAR(distance(r.ray.d, b.dir), 0, 1e-5f);
    EXPECT_NEAR(distance(cam.position(), pos), 0, 1e-5f);
    EXPECT_EQ(r.weight, SampledSpectrum(1.f));
}

TEST(PerspectiveCamera, FieldOfViewSpansTheShorterAxis) {
    Vec3f pos{0, 0, 0}, look{0, 0, 1};
    for (Vec2i res : {Vec2i{64, 48}, Vec2i{48, 64}, Vec2i{32, 32}}) {
        float fov = 50;
        PerspectiveCamera cam(world_from_camera(pos, look, {0, 1, 0}), FilmExtent::whole_image(res),
                              fov, default_screen_window(float(res.x) / res.y), 0, 1e6f);
        float half = radians(fov / 2);
        float aspect = float(res.x) / res.y;
        float half_x = aspect >= 1 ? std::atan(aspect * std::tan(half)) : half;
        float half_y = aspect >= 1 ? half : std::atan(std::tan(half) / aspect);
        Vec3f view{0, 0, 1};
        float cx = res.x / 2.f, cy = res.y / 2.f;
        EXPECT_NEAR(angle_between(ray_through(cam, {cx, 0}).ray.d, view), half_y, 1e-5f);
        EXPECT_NEAR(angle_between(ray_through(cam, {cx, float(res.y)}).ray.d, view), half_y, 1e-5f);
        EXPECT_NEAR(angle_between(ray_through(cam, {0, cy}).ray.d, view), half_x, 1e-5f);
        EXPECT_NEAR(angle_between(ray_through(cam, {float(res.x), cy}).ray.d, view), half_x, 1e-5f);
        // The corner ray: both tangents at once.
        Vec3f corner{std::tan(half_x), std::tan(half_y), 1};
        Vec3f d = ray_through(cam, {0, 0}).ray.d;
        EXPECT_NEAR(angle_between(d, view), angle_between(corner, view), 1e-5f);
    }
}

TEST(PerspectiveCamera, OrientationFollowsPbrtsLookAt) {
    // Up-and-left of the view axis (in camera space: -x, +y) must land in the upper-left part
    // of the raster, at the position pbrt-v4's projection gives.
    Vec3f pos{1, 2, 3}, look{4, 2, -1}, up{0, 1, 0};
    Basis b = look_at_basis(pos, look, up);
    Vec2i res{64, 48};
    float fov = 60;
    PerspectiveCamera cam(world_from_camera(pos, look, up), FilmExtent::whole_image(res), fov,
                          default_screen_window(64.f / 48), 0, 1e6f);
    Vec3f p_cam{-1.2f, 0.7f, 5};
    Vec3f p_world = pos + b.right * p_cam.x + b.up * p_cam.y + b.dir * p_cam.z;
    Vec2f raster = expected_raster(p_cam, fov, res);
    EXPECT_LT(raster.x, res.x / 2.f);
    EXPECT_LT(raster.y, res.y / 2.f);
    // The ray through that raster point passes through the world point...
    CameraRay r = ray_through(cam, raster);
    EXPECT_NEAR(angle_between(r.ray.d, p_world - pos), 0, 2e-4f);
    // ...and importance maps the ray back to the same raster point.
    Vec2f p_raster;
    EXPECT_FALSE(cam.We(Ray{pos, normalize(p_world - pos)}, kLambda, &p_raster).is_black());
    EXPECT_NEAR(p_raster.x, raster.x, 1e-3f);
    EXPECT_NEAR(p_raster.y, raster.y, 1e-3f);
    // World "up" is towards raster y = 0 and camera +x (cross(up, dir)) towards larger raster x.
    Vec3f top = ray_through(cam, {32, 0}).ray.d, bottom = ray_through(cam, {32, 48}).ray.d;
    EXPECT_GT(dot(top, up), dot(bottom, up));
    Vec3f left = ray_through(cam, {0, 24}).ray.d, right = ray_through(cam, {64, 24}).ray.d;
    EXPECT_GT(dot(right, b.right), dot(left, b.right));
}

TEST(PerspectiveCamera, ThinLensFocusesThePlaneOfFocus) {
    Vec3f pos{0, 1, 0}, look{0, 1, 10}, up{0, 1, 0};
    const float focal = 4;
    PerspectiveCamera cam(world_from_camera(pos, look, up), FilmExtent::whole_image({40, 30}), 45,
                          default_screen_window(40.f / 30), 0.3f, focal);
    Basis b = look_at_basis(pos, look, up);
    for (Vec2f p_film : {Vec2f{20, 15}, Vec2f{3.5f, 27.25f}, Vec2f{39, 1}}) {
        // Where the pinhole ray through this film point meets the plane of focus.
        PerspectiveCamera pinhole(world_from_camera(pos, look, up), FilmExtent::whole_image({40, 30}),
                                  45, default_screen_window(40.f / 30), 0, focal);
        Ray c = ray_through(pinhole, p_film).ray;
        Vec3f focus = c.at(focal / dot(c.d, b.dir));
        float spread_near = 0;
        for (Vec2f u : {Vec2f{0.1f, 0.2f}, Vec2f{0.9f, 0.5f}, Vec2f{0.5f, 0.95f}, Vec2f{0.3f, 0.6f}}) {
            Ray r = ray_through(cam, p_film, u).ray;
            EXPECT_NEAR(length(r.d), 1, 1e-6f);
            EXPECT_LE(distance(r.o, pos), 0.3f + 1e-5f);  // starts on the lens
            Vec3f on_plane = r.at((focal - dot(r.o - pos, b.dir)) / dot(r.d, b.dir));
            EXPECT_NEAR(distance(on_plane, focus), 0, 1e-4f);
            Vec3f near_plane = r.at((focal / 2 - dot(r.o - pos, b.dir)) / dot(r.d, b.dir));
            spread_near = std::max(spread_near, distance(near_plane, c.at((focal / 2) / dot(c.d, b.dir))));
        }
        EXPECT_GT(spread_near, 0.05f);  // away from the plane of focus, the lens blurs
    }
}

TEST(PerspectiveCamera, ImportanceIsNormalisedAndConsistentWithItsDensities) {
    for (float lens : {0.f, 0.25f}) {
        PerspectiveCamera cam(world_from_camera({0, 0, 0}, {0, 0, 1}, {0, 1, 0}),
                              FilmExtent::whole_image({32, 24}), 55, default_screen_window(32.f / 24),
                              lens, 3);
        // The direction density integrates to one over the sphere (midpoint quadrature over a
        // 1500^2 grid of the uniform-sphere map; error at the frustum's edge ~1e-3).
        const int n = 1500;
        double integral = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                Vec3f d = sample_uniform_sphere({(i + 0.5f) / n, (j + 0.5f) / n});
                float pdf_pos, pdf_dir;
                cam.pdf_we(Ray{{0, 0, 0}, d}, &pdf_pos, &pdf_dir);
                integral += pdf_dir;
            }
        integral *= 4 * Pi / (double(n) * n);
        EXPECT_NEAR(integral, 1, 5e-3);
        // We = pdf_pos * pdf_dir / cos: importance per unit projected solid angle and lens area.
        Rng rng(1, 2);
        for (int k = 0; k < 100; ++k) {
            Vec2f disk = sample_uniform_disk_concentric(rng.uniform2()) * lens;
            Vec3f o{disk.x, disk.y, 0};
            Vec3f d = normalize(Vec3f{rng.uniform() - 0.5f, rng.uniform() - 0.5f, 1});
            float pdf_pos, pdf_dir;
            cam.pdf_we(Ray{o, d}, &pdf_pos, &pdf_dir);
            float we = cam.We(Ray{o, d}, kLambda)[0];
            if (we == 0) {
                EXPECT_EQ(pdf_dir, 0);
                continue;
            }
            EXPECT_NEAR(pdf_pos, lens > 0 ? 1 / (Pi * lens * lens) : 1, 1e-4f);
            EXPECT_NEAR(we, pdf_pos * pdf_dir / d.z, 1e-4f * we);
        }
    }
}

// The measurement of each pixel estimated from the emitter (sample_wi, as light tracing does)
// must equal the one estimated from the camera (generate_ray). Scene: a one-sided emitting
// rectangle facing the camera at distance D, with radiance varying across it, filling the view.
TEST(PerspectiveCamera, ImportanceMeasurementMatchesCameraRays) {
    const Vec2i res{8, 6};
    const int pixels = res.x * res.y;
    const float D = 5, fov = 50;
    Vec3f pos{0.5f, -1, 2}, look{3, 0, 7}, up{0, 1, 0};
    Basis b = look_at_basis(pos, look, up);
    // Half extents of the emitter: the frustum at D plus a margin for the lens.
    const float hy = D * std::tan(radians(fov / 2)) + 0.5f, hx = D * std::tan(radians(fov / 2)) * 4 / 3 + 0.5f;
    auto radiance = [&](float a, float c) { return 1 + 0.6f * a / hx + 0.3f * c / hy; };
    Vec3f centre = pos + b.dir * D;

    for (auto [lens, focal] : {std::pair{0.f, 1e6f}, std::pair{0.15f, 3.f}}) {
        PerspectiveCamera cam(world_from_camera(pos, look, up), FilmExtent::whole_image(res), fov,
                              default_screen_window(4.f / 3), lens, focal);
        // Camera estimate: stratified film and lens positions per pixel (box filter), L at the
        // hit point. 32^2 strata: error ~1e-4 for this smooth radiance.
        std::vector<double> camera_estimate(pixels, 0);
        const int m = 32;
        Rng lens_rng(3, 4);
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                double sum = 0;
                for (int j = 0; j < m; ++j)
                    for (int i = 0; i < m; ++i) {
                        Vec2f u{(i + 0.5f) / m, (j + 0.5f) / m};
                        Ray r = ray_through(cam, {x + u.x, y + u.y}, lens_rng.uniform2()).ray;
                        float t = dot(centre - r.o, b.dir) / dot(r.d, b.dir);
                        Vec3f hit = r.at(t) - centre;
                        float a = dot(hit, b.right), c = dot(hit, b.up);
                        ASSERT_LE(std::abs(a), hx);
                        ASSERT_LE(std::abs(c), hy);
                        sum += radiance(a, c);
                    }
                camera_estimate[y * res.x + x] = sum / (m * m);
            }
        // Emitter estimate: uniform points x on the emitter (pdf 1/area), a lens point from
        // sample_wi; the contribution L We |cos_x| / (pdf_x pdf_wi) lands on the pixel at
        // p_raster, and a pixel's value is (pixels / N) times its sum (pbrt's splat scale with a
        // box filter, whose integral is 1).
        const int N = 1500000;
        const float area = 4 * hx * hy;
        std::vector<double> sum(pixels, 0), sum_sq(pixels, 0);
        Rng rng(7, 11);
        for (int k = 0; k < N; ++k) {
            Vec2f u = rng.uniform2();
            float a = lerp(u.x, -hx, hx), c = lerp(u.y, -hy, hy);
            Vec3f x = centre + b.right * a + b.up * c;
            auto s = cam.sample_wi(x, rng.uniform2(), kLambda);
            if (!s) continue;
            int px = int(std::floor(s->p_raster.x)), py = int(std::floor(s->p_raster.y));
            if (px < 0 || py < 0 || px >= res.x || py >= res.y) continue;
            float v = radiance(a, c) * s->We[0] * abs_dot(b.dir, s->wi) * area / s->pdf;
            sum[py * res.x + px] += v;
            sum_sq[py * res.x + px] += double(v) * v;
        }
        for (int p = 0; p < pixels; ++p) {
            double mean = sum[p] / N, var = sum_sq[p] / N - mean * mean;
            double estimate = pixels * mean, std_error = pixels * std::sqrt(var / N);
            // The bound is 4.5 standard errors of the emitter estimate (per pixel, ~1%), plus
            // the camera estimate's quadrature error; std_error itself must be small for the
            // comparison to mean anything.
            EXPECT_LT(std_error, 0.02 * camera_estimate[p]);
            EXPECT_NEAR(estimate, camera_estimate[p], 4.5 * std_error + 1e-3)
                << "pixel " << p % res.x << "," << p / res.x << " lens " << lens;
        }
    }
}

TEST(PerspectiveCamera, ImportanceVanishesOutsideTheSampleBounds) {
    // With a filter of radius 1.5, splats up to one pixel outside the image still reach it.
    Vec2i res{20, 10};
    PerspectiveCamera narrow(Transform(), FilmExtent::whole_image(res), 40, default_screen_window(2), 0, 1e6f);
    PerspectiveCamera wide(Transform(), FilmExtent::whole_image(res, {1.5f, 1.5f}), 40,
                           default_screen_window(2), 0, 1e6f);
    for (Vec2f p : {Vec2f{-0.5f, 5}, Vec2f{20.7f, 5}, Vec2f{10, -0.9f}}) {
        Vec3f d = normalize(narrow.camera_from_raster().apply_point({p.x, p.y, 0}));
        EXPECT_TRUE(narrow.We(Ray{{0, 0, 0}, d}, kLambda).is_black());
        Vec2f p_raster;
        EXPECT_FALSE(wide.We(Ray{{0, 0, 0}, d}, kLambda, &p_raster).is_black());
        EXPECT_NEAR(p_raster.x, p.x, 1e-3f);
        EXPECT_NEAR(p_raster.y, p.y, 1e-3f);
    }
    Vec3f far_out = normalize(narrow.camera_from_raster().apply_point({-1.2f, 5, 0}));
    EXPECT_TRUE(wide.We(Ray{{0, 0, 0}, far_out}, kLambda).is_black());
    EXPECT_TRUE(wide.We(Ray{{0, 0, 0}, {0, 0, -1}}, kLambda).is_black());  // behind the camera
}

TEST(OrthographicCamera, ParallelRaysOverTheScreenWindow) {
    Vec3f pos{1, 1, 1}, look{1, 1, 5}, up{0, 1, 0};
    OrthographicCamera cam(world_from_camera(pos, look, up), FilmExtent::whole_image({40, 20}),
                           default_screen_window(2), 0, 1e6f);
    EXPECT_FALSE(cam.models_importance());
    // Screen window [-2, 2] x [-1, 1] in camera units; raster (0, 0) is its top-left corner.
    Ray r = ray_through(cam, {0, 0}).ray;
    // Looking along world +z with +y up, camera +x = cross(up, dir) is world +x.
    EXPECT_NEAR(distance(r.o, pos + Vec3f{-2, 1, 0}), 0, 1e-5f);
    EXPECT_NEAR(distance(r.d, Vec3f{0, 0, 1}), 0, 1e-6f);
    Ray c = ray_through(cam, {20, 10}).ray;
    EXPECT_NEAR(distance(c.o, pos), 0, 1e-5f);
}

TEST(CameraFactory, ReadsPbrtParameters) {
    set_warnings_enabled(false);
    SourceLocation loc{"scene.pbrt", 5, 1};
    Transform id;
    auto cam = create_camera("perspective", id, Vec2i{100, 50}, dict({float_param("fov", {30})}), loc);
    Vec3f top = ray_through(*cam, {50, 0}).ray.d;
    EXPECT_NEAR(angle_between(top, {0, 0, 1}), radians(15), 1e-5f);
    // Default fov 90; "frameaspectratio" and "screenwindow" reshape the window.
    cam = create_camera("perspective", id, Vec2i{100, 50}, dict({}), loc);
    EXPECT_NEAR(angle_between(ray_through(*cam, {50, 0}).ray.d, {0, 0, 1}), radians(45), 1e-5f);
    cam = create_camera("perspective", id, Vec2i{100, 50},
                        dict({float_param("screenwindow", {-1, 1, -1, 1})}), loc);
    EXPECT_NEAR(angle_between(ray_through(*cam, {0, 25}).ray.d, {0, 0, 1}), radians(45), 1e-5f);
    EXPECT_FALSE(create_camera("spherical", id, Vec2i{10, 10}, dict({}), loc)->models_importance());
    EXPECT_FALSE(create_camera("orthographic", id, Vec2i{10, 10}, dict({}), loc)->models_importance());
    set_warnings_enabled(true);
    const Shutter shutter = camera_shutter(dict({float_param("shutteropen", {0.5}), float_param("shutterclose", {0.75})}), loc);
    EXPECT_FLOAT_EQ(shutter.open, 0.5f);
    EXPECT_FLOAT_EQ(shutter.close, 0.75f);
    EXPECT_FLOAT_EQ(shutter.time(0.5f), 0.625f);
}

TEST(CameraFactory, RejectsBadInput) {
    SourceLocation loc{"scene.pbrt", 5, 1};
    Transform id;
    EXPECT_THROW(create_camera("pinhole", id, Vec2i{10, 10}, dict({}), loc), InputError);
    EXPECT_THROW(create_camera("perspective", id, Vec2i{10, 10}, dict({float_param("fov", {180})}), loc),
                 InputError);
    EXPECT_THROW(create_camera("perspective", id, Vec2i{10, 10},
                               dict({float_param("screenwindow", {-1, 1, 0})}), loc),
                 InputError);
    EXPECT_THROW(create_camera("perspective", id, Vec2i{10, 10},
                               dict({float_param("lensradius", {-0.1})}), loc),
                 InputError);
    EXPECT_THROW(camera_shutter(dict({float_param("shutteropen", {2})}), loc), InputError);
}
