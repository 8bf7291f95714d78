// `--integrator auto`: the scene probe that measures what the camera and the lights see
// (scene/scene_probe.h), and the choice made from it and from the materials.
#include "render_test_support.h"

#include "parser/scene_description.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <string>

using namespace caustica;

namespace {

std::unique_ptr<Scene> build(const std::string &text) {
    set_warnings_enabled(false);
    RenderOverrides overrides;
    overrides.integrator = "auto";
    return build_scene(parse_scene_string(text), overrides);
}

std::unique_ptr<Scene> build_file(const std::string &path) {
    set_warnings_enabled(false);
    RenderOverrides overrides;
    overrides.integrator = "auto";
    return build_scene(parse_scene_file(path), overrides);
}

const char *camera_down_the_z_axis =
    "LookAt 0 0 1  0 0 0  0 1 0\n"
    "Camera \"perspective\" \"float fov\" [ 60 ]\n"
    "Film \"rgb\" \"integer xresolution\" [ 32 ] \"integer yresolution\" [ 32 ]\n"
    "WorldBegin\n";

} // namespace

// A wall filling the view, its left half an emitter and its right half glass: the probe's grid
// is symmetric about the image centre, where the two halves meet, so exactly half of its rays
// see each (48 columns, 24 on either side; the probe traces through no surface).
TEST(SceneProbe, MeasuresTheShareOfTheImageShowingEmittersAndSpecularSurfaces) {
    auto scene = build(std::string(camera_down_the_z_axis) +
                       "AttributeBegin\n"
                       "  AreaLightSource \"diffuse\" \"rgb L\" [ 1 1 1 ]\n"
                       "  Shape \"bilinearmesh\" \"point3 P\" [ -5 -5 -1  0 -5 -1  -5 5 -1  0 5 -1 ]\n"
                       "AttributeEnd\n"
                       "AttributeBegin\n"
                       "  Material \"dielectric\" \"float eta\" [ 1.5 ]\n"
                       "  Shape \"bilinearmesh\" \"point3 P\" [ 0 -5 -1  5 -5 -1  0 5 -1  5 5 -1 ]\n"
                       "AttributeEnd\n");
    EXPECT_FLOAT_EQ(scene->features.probe.view_emitters, 0.5f);
    EXPECT_FLOAT_EQ(scene->features.probe.view_specular, 0.5f);
}

// Every ray from a point light at the centre of a closed glass sphere first meets the glass;
// with the sphere replaced by a diffuse one, none meets a specular surface.
TEST(SceneProbe, MeasuresTheShareOfLightMeetingSpecularSurfacesFirst) {
    auto scene_with = [](const std::string &material) {
        return build(std::string(camera_down_the_z_axis) + "LightSource \"point\" \"point3 from\" [ 0 0 -3 ]\n"
                     "AttributeBegin\n  " + material + "\n  Translate 0 0 -3\n"
                     "  Shape \"sphere\" \"float radius\" [ 0.5 ]\nAttributeEnd\n");
    };
    EXPECT_FLOAT_EQ(scene_with("Material \"dielectric\"")->features.probe.lights_behind_specular, 1.f);
    EXPECT_FLOAT_EQ(scene_with("Material \"diffuse\"")->features.probe.lights_behind_specular, 0.f);
}

TEST(AutoIntegrator, ChoosesThePathTracerWithoutCausticPaths) {
    auto scene = build_file(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cornell-box.pbrt");
    EXPECT_FALSE(scene->features.caustic_paths);
    EXPECT_EQ(scene->integrator_name, "pt");
}

// A glass sphere on a floor: the caustic is seen directly, and light mostly meets the floor.
TEST(AutoIntegrator, ChoosesVcmForCausticsSeenDirectly) {
    auto scene = build_file(caustica::testing::data_path("reference/glass-sphere.pbrt"));
    EXPECT_TRUE(scene->features.caustic_paths);
    EXPECT_LT(scene->features.probe.view_specular, 0.5f);
    EXPECT_EQ(scene->integrator_name, "vcm");
}

// A pool seen and lit through its water surface: specular-diffuse-specular paths dominate.
TEST(AutoIntegrator, ChoosesSppmWhenCameraAndLightsLookThroughSpecularSurfaces) {
    auto scene = build_file(caustica::testing::data_path("reference/water-pool.pbrt"));
    EXPECT_GE(scene->features.probe.view_specular, 0.5f);
    EXPECT_GE(scene->features.probe.lights_behind_specular, 0.5f);
    EXPECT_EQ(scene->integrator_name, "sppm");
}

// A camera that cannot receive light paths rules out lt, bdpt, bpm and vcm: with caustic paths
// auto takes sppm, which needs camera rays only; without them, the path tracer.
TEST(AutoIntegrator, ChoosesSppmForCausticsSeenByACameraWithoutImportance) {
    const std::string lens = std::string(CAUSTICA_SOURCE_DIR) + "/scenes/cameras/lenses/triplet-60mm.dat";
    const std::string text = caustica::testing::read_text(caustica::testing::data_path("reference/glass-sphere.pbrt"));
    const std::string perspective = "Camera \"perspective\" \"float fov\" [ 40 ]";
    ASSERT_NE(text.find(perspective), std::string::npos);
    for (const std::string &camera :
         {std::string("Camera \"spherical\" \"string mapping\" \"equirectangular\""),
          "Camera \"realistic\" \"string lensfile\" \"" + lens + "\" \"float focusdistance\" 5"}) {
        std::string with_camera = text;
        with_camera.replace(with_camera.find(perspective), perspective.size(), camera);
        auto scene = build(with_camera);
        EXPECT_TRUE(scene->features.caustic_paths);
        EXPECT_FALSE(scene->camera->models_importance());
        EXPECT_EQ(scene->integrator_name, "sppm") << camera;
    }
}

// Curves are seen as pbrt-v4 sees them by camera paths only: auto takes the path tracer even
// where caustic paths would call for vcm (the glass sphere with a hair on its floor).
TEST(AutoIntegrator, ChoosesThePathTracerForCurves) {
    std::string text = caustica::testing::read_text(caustica::testing::data_path("reference/glass-sphere.pbrt"));
    text += "\nShape \"curve\" \"point3 P\" [-1 0 0  -0.3 0.2 0  0.3 0.2 0  1 0 0] \"float width\" 0.01\n";
    auto scene = build(text);
    EXPECT_TRUE(scene->features.caustic_paths);
    EXPECT_TRUE(scene->features.curves);
    EXPECT_EQ(scene->integrator_name, "pt");
}
