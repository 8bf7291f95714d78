// Transform directives: expected values are worked out by hand from the definitions of the
// transforms and pbrt's rule that each directive multiplies the CTM on the right.
#include "parser_test_util.h"

#include <cmath>

namespace caustica {
namespace {

using test::expect_near;
using test::parse;

// The shape's object-to-world transform after `transforms` inside the world block.
Transform shape_transform(const std::string &transforms) {
    SceneDescription d = parse("WorldBegin\n" + transforms + "\nShape \"sphere\"\n");
    EXPECT_EQ(d.shapes.size(), 1u);
    return d.shapes.at(0).render_from_object;
}

TEST(ParserTransforms, LookAtCameraMapsOriginToEyeAndZToViewDirection) {
    SceneDescription d = parse("LookAt 1 2 3  1 2 8  0 1 0\nCamera \"perspective\"\nWorldBegin\n");
    ASSERT_TRUE(d.has_camera);
    EXPECT_EQ(d.camera.type, "perspective");
    const Transform &wc = d.camera.world_from_camera;
    expect_near(wc.apply_point({0, 0, 0}), {1, 2, 3});
    expect_near(wc.apply_vector({0, 0, 1}), {0, 0, 1});
    // Up stays up; pbrt's camera space is left-handed, so +x is up x view = (1,0,0) here.
    expect_near(wc.apply_vector({0, 1, 0}), {0, 1, 0});
    expect_near(wc.apply_vector({1, 0, 0}), {1, 0, 0});
}

TEST(ParserTransforms, LookAtWithObliqueDirection) {
    SceneDescription d = parse("LookAt 0 0 0  3 4 0  0 0 1\nCamera \"perspective\"\nWorldBegin\n");
    const Transform &wc = d.camera.world_from_camera;
    expect_near(wc.apply_vector({0, 0, 1}), {0.6f, 0.8f, 0});
    expect_near(wc.apply_vector({0, 1, 0}), {0, 0, 1});
    // The camera transform is a rigid motion: camera +z at distance 5 is the look point.
    expect_near(wc.apply_point({0, 0, 5}), {3, 4, 0});
}

TEST(ParserTransforms, CameraUsesTheCtmBeforeIt) {
    // CTM at Camera = Translate(0,0,5): camera-from-world, so the camera sits at (0,0,-5).
    SceneDescription d = parse("Translate 0 0 5\nCamera \"orthographic\"\nWorldBegin\n");
    expect_near(d.camera.world_from_camera.apply_point({0, 0, 0}), {0, 0, -5});
}

TEST(ParserTransforms, TranslateThenScaleScalesFirst) {
    Transform t = shape_transform("Translate 1 2 3\nScale 2 3 4");
    expect_near(t.apply_point({1, 1, 1}), {1 + 2, 2 + 3, 3 + 4});
    Transform u = shape_transform("Scale 2 3 4\nTranslate 1 2 3");
    expect_near(u.apply_point({0, 0, 0}), {2, 6, 12});
}

TEST(ParserTransforms, RotateIsCounterClockwiseInDegrees) {
    expect_near(shape_transform("Rotate 90 0 0 1").apply_point({1, 0, 0}), {0, 1, 0});
    expect_near(shape_transform("Rotate 90 1 0 0").apply_point({0, 1, 0}), {0, 0, 1});
    // The axis need not be normalised.
    expect_near(shape_transform("Rotate 180 0 5 0").apply_point({1, 0, 0}), {-1, 0, 0});
    // Rotate after Translate: rotation applies to the object first.
    expect_near(shape_transform("Translate 5 0 0\nRotate 90 0 0 1").apply_point({1, 0, 0}),
                {5, 1, 0});
}

TEST(ParserTransforms, ConcatTransformIsColumnMajor) {
    // The last four numbers are the fourth column: a translation by (4, 5, 6).
    Transform t = shape_transform("ConcatTransform [1 0 0 0  0 1 0 0  0 0 1 0  4 5 6 1]");
    expect_near(t.apply_point({1, 1, 1}), {5, 6, 7});
    // Second column (0 2 0 0) is the image of +y.
    Transform s = shape_transform("ConcatTransform [1 0 0 0  0 2 0 0  0 0 1 0  0 0 0 1]");
    expect_near(s.apply_vector({0, 1, 0}), {0, 2, 0});
    // An element off the diagonal: m10 = 3 (second number) maps x to (1, 3, 0).
    Transform k = shape_transform("ConcatTransform [1 3 0 0  0 1 0 0  0 0 1 0  0 0 0 1]");
    expect_near(k.apply_vector({1, 0, 0}), {1, 3, 0});
    // It concatenates on the right of the CTM.
    Transform c = shape_transform("Scale 2 2 2\nConcatTransform [1 0 0 0 0 1 0 0 0 0 1 0 1 0 0 1]");
    expect_near(c.apply_point({0, 0, 0}), {2, 0, 0});
}

TEST(ParserTransforms, TransformReplacesAndIdentityResets) {
    Transform t = shape_transform("Scale 9 9 9\nTransform [1 0 0 0 0 1 0 0 0 0 1 0 4 5 6 1]");
    expect_near(t.apply_point({0, 0, 0}), {4, 5, 6});
    expect_near(t.apply_vector({1, 0, 0}), {1, 0, 0});
    EXPECT_TRUE(shape_transform("Translate 1 2 3\nIdentity").is_identity());
}

TEST(ParserTransforms, InverseIsKept) {
    Transform t = shape_transform("Translate 1 2 3\nRotate 30 1 1 0\nScale 2 3 4");
    Vec3f p{0.3f, -0.7f, 1.9f};
    expect_near(t.inverse().apply_point(t.apply_point(p)), p, 1e-5f);
}

TEST(ParserTransforms, WorldBeginResetsTheCtm) {
    SceneDescription d = parse("Translate 1 2 3\nCamera \"perspective\"\nWorldBegin\nShape \"sphere\"\n");
    EXPECT_TRUE(d.shapes[0].render_from_object.is_identity());
}

TEST(ParserTransforms, CoordSysTransformRestoresASavedFrame) {
    Transform t = shape_transform("Translate 1 0 0\nCoordinateSystem \"saved\"\nScale 5 5 5\n"
                                  "CoordSysTransform \"saved\"");
    expect_near(t.apply_point({1, 1, 1}), {2, 1, 1});
}

TEST(ParserTransforms, NamedFramesCameraAndWorld) {
    SceneDescription d = parse("LookAt 0 0 -10  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                               "CoordSysTransform \"camera\"\nShape \"sphere\"\n"
                               "CoordSysTransform \"world\"\nShape \"disk\"\n");
    // In the "camera" frame the object origin is the eye.
    expect_near(d.shapes[0].render_from_object.apply_point({0, 0, 0}), {0, 0, -10});
    expect_near(d.shapes[0].render_from_object.apply_point({0, 0, 1}), {0, 0, -9});
    EXPECT_TRUE(d.shapes[1].render_from_object.is_identity());
}

TEST(ParserTransforms, UnknownCoordinateSystemWarnsAndKeepsCtm) {
    SceneDescription d = parse("WorldBegin\nTranslate 1 0 0\nCoordSysTransform \"nowhere\"\n"
                               "Shape \"sphere\"\n");
    expect_near(d.shapes[0].render_from_object.apply_point({0, 0, 0}), {1, 0, 0});
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_NE(d.warnings[0].find("nowhere"), std::string::npos);
}

TEST(ParserTransforms, AttributeEndRestoresTheCtm) {
    SceneDescription d = parse("WorldBegin\nTranslate 1 0 0\nAttributeBegin\nScale 2 2 2\n"
                               "Shape \"sphere\"\nAttributeEnd\nShape \"disk\"\n");
    expect_near(d.shapes[0].render_from_object.apply_point({1, 0, 0}), {3, 0, 0});
    expect_near(d.shapes[1].render_from_object.apply_point({1, 0, 0}), {2, 0, 0});
}

TEST(ParserTransforms, TransformBeginEndIsAcceptedWithAWarning) {
    SceneDescription d = parse("WorldBegin\nTransformBegin\nTranslate 1 0 0\nTransformEnd\n"
                               "TransformBegin\nTransformEnd\nShape \"sphere\"\n");
    EXPECT_TRUE(d.shapes[0].render_from_object.is_identity());
    ASSERT_EQ(d.warnings.size(), 1u);  // warned once
    EXPECT_NE(d.warnings[0].find("deprecated"), std::string::npos);
}

// pbrt-v4's ActiveTransform: each transform directive changes the start transform, the end
// transform, or both, as the last ActiveTransform chose.
TEST(ParserTransforms, ActiveTransformChoosesWhichEndMoves) {
    SceneDescription d = parse("WorldBegin\nActiveTransform EndTime\nTranslate 9 9 9\n"
                               "ActiveTransform StartTime\nTranslate 1 0 0\n"
                               "ActiveTransform All\nTranslate 0 1 0\nShape \"sphere\"\n"
                               "Shape \"disk\"\n");
    expect_near(d.shapes[0].render_from_object.apply_point({0, 0, 0}), {1, 1, 0});
    ASSERT_TRUE(d.shapes[0].render_from_object_end);
    expect_near(d.shapes[0].render_from_object_end->apply_point({0, 0, 0}), {9, 10, 9});
    EXPECT_TRUE(d.warnings.empty());
    d = parse("WorldBegin\nTranslate 1 0 0\nShape \"sphere\"\n");
    EXPECT_FALSE(d.shapes[0].render_from_object_end); // still
}

TEST(ParserTransforms, TransformTimesAndMovingInstances) {
    SceneDescription d = parse("TransformTimes 0.25 2\nWorldBegin\nObjectBegin \"o\"\nShape \"sphere\"\n"
                               "ObjectEnd\nActiveTransform EndTime\nTranslate 0 0 3\nObjectInstance \"o\"\n");
    EXPECT_FLOAT_EQ(d.transform_times.start, 0.25f);
    EXPECT_FLOAT_EQ(d.transform_times.end, 2.f);
    ASSERT_EQ(d.instance_uses.size(), 1u);
    EXPECT_TRUE(d.instance_uses[0].render_from_instance.is_animated());
    expect_near(d.instance_uses[0].render_from_instance.end.apply_point({0, 0, 0}), {0, 0, 3});
    EXPECT_FLOAT_EQ(d.transform_times.fraction(1.125f), 0.5f);
    EXPECT_FLOAT_EQ(d.transform_times.fraction(3.f), 1.f); // at rest after the end
}

TEST(ParserTransforms, MotionThatPbrtV4DoesNotSupport) {
    // A moving camera keeps both placements; moving lights (and media and texture spaces) warn
    // and use the start, as pbrt-v4 does; a moving area light is an error at its shape, as in
    // pbrt-v4.
    SceneDescription d = parse("ActiveTransform EndTime\nTranslate 0 0 1\nCamera \"perspective\"\n"
                               "WorldBegin\nActiveTransform EndTime\nTranslate 1 0 0\n"
                               "LightSource \"point\"\n");
    ASSERT_TRUE(d.camera.world_from_camera_end);
    expect_near(d.camera.world_from_camera_end->apply_point({0, 0, 0}), {0, 0, -1});
    expect_near(d.camera.world_from_camera.apply_point({0, 0, 0}), {0, 0, 0});
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_NE(d.warnings[0].find("light cannot move"), std::string::npos);
    std::string message = test::parse_error("WorldBegin\nActiveTransform EndTime\nTranslate 1 0 0\n"
                                            "AreaLightSource \"diffuse\"\nShape \"sphere\"\n").what();
    EXPECT_NE(message.find("test.pbrt:5:1"), std::string::npos) << message;
    EXPECT_NE(message.find("area light cannot move"), std::string::npos) << message;
    message = test::parse_error("TransformTimes 1 0\n").what();
    EXPECT_NE(message.find("test.pbrt:1:1"), std::string::npos) << message;
}

TEST(ParserTransforms, LightsTexturesMediaAndInstancesGetTheCtm) {
    SceneDescription d = parse(
        "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
        "WorldBegin\nTranslate 0 0 2\n"
        "LightSource \"point\"\n"
        "Texture \"t\" \"float\" \"checkerboard\"\n"
        "MakeNamedMedium \"smoke\" \"string type\" \"homogeneous\"\n"
        "ObjectBegin \"obj\"\nTranslate 1 0 0\nShape \"sphere\"\nObjectEnd\n"
        "Scale 2 2 2\nObjectInstance \"obj\"\n");
    expect_near(d.lights[0].render_from_object.apply_point({0, 0, 0}), {0, 0, 2});
    expect_near(d.textures[0].render_from_object.apply_point({0, 0, 0}), {0, 0, 2});
    EXPECT_TRUE(d.media[0].render_from_object.is_identity());
    expect_near(d.media[1].render_from_object.apply_point({0, 0, 0}), {0, 0, 2});
    ASSERT_EQ(d.instances.size(), 1u);
    // Shapes in a definition keep their full CTM; ObjectEnd restores the CTM of ObjectBegin.
    expect_near(d.instances[0].shapes[0].render_from_object.apply_point({0, 0, 0}), {1, 0, 2});
    ASSERT_EQ(d.instance_uses.size(), 1u);
    expect_near(d.instance_uses[0].render_from_instance.start.apply_point({1, 1, 1}), {2, 2, 4});
}

// Exporters hide objects under transforms that collapse space (Cinema 4D's pbrt-v4 exports of
// transparent-machines hold empty blocks under a matrix whose x column is zero). pbrt-v4 accepts
// them; what would need the inverse is left out where it is placed.
TEST(ParserTransforms, ACollapsingTransformIsAcceptedAndWhatItPlacesIsLeftOut) {
    SceneDescription d = parse("WorldBegin\nAttributeBegin\n"
                               "ConcatTransform [-0 -0 0 0  0 1 0 0  0 0 -1 0  2637 -70 8 1]\n"
                               "AttributeBegin\nAttributeEnd\nAttributeEnd\nShape \"sphere\"\n");
    EXPECT_EQ(d.shapes.size(), 1u);
    EXPECT_TRUE(d.warnings.empty());

    d = parse("WorldBegin\nAttributeBegin\nScale 1 0 1\nShape \"sphere\"\nLightSource \"point\"\n"
              "ObjectInstance \"thing\"\nAttributeEnd\nShape \"disk\"\n");
    ASSERT_EQ(d.shapes.size(), 1u);
    EXPECT_EQ(d.shapes[0].type, "disk");
    EXPECT_TRUE(d.lights.empty());
    EXPECT_TRUE(d.instance_uses.empty());
    ASSERT_EQ(d.warnings.size(), 3u);
    for (const std::string &w : d.warnings) EXPECT_NE(w.find("is left out"), std::string::npos) << w;
}

TEST(ParserTransforms, ACollapsingTransformIsAnErrorForTheCameraMediaAndTextures) {
    for (const char *text : {"# the camera\nScale 0 1 1\nCamera \"perspective\"\nWorldBegin\n",
                             "WorldBegin\nScale 0 1 1\nMakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n",
                             "WorldBegin\nScale 0 1 1\nTexture \"t\" \"float\" \"constant\"\n"}) {
        try {
            parse(text);
            ADD_FAILURE() << text << " parsed";
        } catch (const InputError &e) {
            EXPECT_NE(std::string(e.what()).find("not invertible"), std::string::npos) << e.what();
            EXPECT_EQ(e.location().line, 3) << text;
        }
    }
}

} // namespace
} // namespace caustica
