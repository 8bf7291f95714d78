// A moving camera (pbrt-v4's animated camera transform): rays leave from where the camera is at
// their time, importance queries see the camera where it is at the ray's time, and a motion
// that would change the camera's scale is refused.
#include "camera/camera_factory.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace caustica;

namespace {

const SampledWavelengths kLambda = SampledWavelengths::fixed(550);

void expect_near_vec(Vec3f a, Vec3f b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// A thin-lens camera at the origin looking along +z at the start, turned by 90 degrees about y
// and moved to (2, 0, 0) at the end, over TransformTimes 1 to 3.
CameraPtr moving_camera() {
    const Transform start;
    const Transform end = Transform::translate({2, 0, 0}) * Transform::rotate(90, {0, 1, 0});
    ParsedParameter lens;
    lens.type = "float";
    lens.name = "lensradius";
    lens.numbers = {0.1};
    ParameterDictionary params({lens}, SourceLocation{"scene.pbrt", 1, 1}, nullptr, ".");
    CameraMotion motion{end, TransformTimes{1, 3}};
    return create_camera("perspective", start, FilmExtent::whole_image(Vec2i{32, 32}), params, SourceLocation{"scene.pbrt", 1, 1}, &motion);
}

CameraRay centre_ray(const Camera &camera, float time) {
    CameraSample s;
    s.p_film = {16, 16};
    s.p_lens = {0.5f, 0.5f};
    s.time = time;
    std::optional<CameraRay> r = camera.generate_ray(s, kLambda);
    EXPECT_TRUE(r.has_value());
    return *r;
}

TEST(CameraMotion, RaysLeaveWhereTheCameraIsAtTheirTime) {
    CameraPtr camera = moving_camera();
    ASSERT_TRUE(camera->moves());
    CameraRay r = centre_ray(*camera, 1);
    expect_near_vec(r.ray.o, {0, 0, 0}, 1e-5f);
    expect_near_vec(normalize(r.ray.d), {0, 0, 1}, 1e-5f);
    EXPECT_FLOAT_EQ(r.ray.time, 1);
    // Half-way: turned by 45 degrees (slerp) and moved half the way.
    r = centre_ray(*camera, 2);
    expect_near_vec(r.ray.o, {1, 0, 0}, 1e-5f);
    expect_near_vec(normalize(r.ray.d), normalize(Vec3f{1, 0, 1}), 1e-5f);
    // After the end: at the end.
    r = centre_ray(*camera, 5);
    expect_near_vec(r.ray.o, {2, 0, 0}, 1e-5f);
    expect_near_vec(normalize(r.ray.d), {1, 0, 0}, 1e-5f);
}

// Importance is evaluated with the camera where it is at the ray's time: a lens sample towards a
// point reaches the film where the camera's own ray through that film point goes, and the same
// query at another time sees the camera elsewhere.
TEST(CameraMotion, ImportanceFollowsTheCamera) {
    CameraPtr camera = moving_camera();
    const float time = 2;
    const Vec3f ref = Vec3f{1, 0, 0} + normalize(Vec3f{1, 0.1f, 1}) * 4;
    std::optional<CameraWiSample> s = camera->sample_wi(ref, {0.3f, 0.7f}, kLambda, time);
    ASSERT_TRUE(s.has_value());
    ASSERT_GT(s->pdf, 0);
    Ray back{s->p_lens, -s->wi};
    back.time = time;
    Vec2f p_raster;
    const SampledSpectrum we = camera->We(back, kLambda, &p_raster);
    EXPECT_GT(we[0], 0);
    EXPECT_NEAR(p_raster.x, s->p_raster.x, 1e-3f);
    EXPECT_NEAR(p_raster.y, s->p_raster.y, 1e-3f);
    float pdf_pos = 0, pdf_dir = 0;
    camera->pdf_we(back, &pdf_pos, &pdf_dir);
    EXPECT_GT(pdf_dir, 0);
    // The lens point lies on the lens where the camera is at that time: 1 from the start point
    // along x, and no farther from its centre than the lens radius.
    EXPECT_LE(length(s->p_lens - Vec3f{1, 0, 0}), 0.1f + 1e-5f);
    // At the start the camera looks along +z from the origin, and ref lies outside its view.
    EXPECT_FALSE(camera->sample_wi(ref, {0.3f, 0.7f}, kLambda, 1).has_value() &&
                 camera->sample_wi(ref, {0.3f, 0.7f}, kLambda, 1)->pdf > 0);
}

TEST(CameraMotion, AMotionThatScalesIsRefused) {
    ParameterDictionary none({}, SourceLocation{"scene.pbrt", 1, 1}, nullptr, ".");
    CameraMotion motion{Transform::scale(2, 2, 2), TransformTimes{}};
    set_warnings_enabled(false);
    CameraPtr camera = create_camera("perspective", Transform(), FilmExtent::whole_image(Vec2i{8, 8}), none, SourceLocation{"scene.pbrt", 1, 1},
                                     &motion);
    set_warnings_enabled(true);
    EXPECT_FALSE(camera->moves());
}

} // namespace
