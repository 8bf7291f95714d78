// Directives other than transforms: entities, graphics state, names, files.
#include "parser_test_util.h"

#include "spectral/color_space.h"

#include <filesystem>

namespace caustica {
namespace {

using test::parse;
using test::parse_error;

TEST(ParserDirectives, RenderingOptions) {
    SceneDescription d = parse(
        "Film \"rgb\" \"integer xresolution\" 320 \"integer yresolution\" [240]\n"
        "  \"string filename\" \"out.exr\"\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 16\n"
        "Integrator \"volpath\" \"integer maxdepth\" [ 5 ]\n"
        "PixelFilter \"gaussian\" \"float radius\" 1.5\n"
        "Accelerator \"bvh\"\n"
        "Camera \"perspective\" \"float fov\" 45\n"
        "WorldBegin\n");
    EXPECT_EQ(d.film.type, "rgb");
    EXPECT_EQ(d.film.params.get_one_int("xresolution", 0), 320);
    EXPECT_EQ(d.film.params.get_one_int("yresolution", 0), 240);
    EXPECT_EQ(d.film.params.get_one_string("filename", ""), "out.exr");
    EXPECT_EQ(d.film.loc.line, 1);
    EXPECT_EQ(d.sampler.type, "zsobol");
    EXPECT_EQ(d.sampler.params.get_one_int("pixelsamples", 0), 16);
    EXPECT_EQ(d.integrator.type, "volpath");
    EXPECT_EQ(d.integrator.params.get_one_int("maxdepth", 0), 5);
    EXPECT_EQ(d.filter.type, "gaussian");
    EXPECT_FLOAT_EQ(d.filter.params.get_one_float("radius", 0), 1.5f);
    EXPECT_EQ(d.accelerator.type, "bvh");
    EXPECT_EQ(d.camera.type, "perspective");
    EXPECT_FLOAT_EQ(d.camera.params.get_one_float("fov", 0), 45);
    EXPECT_EQ(d.camera.loc.line, 7);
    EXPECT_EQ(d.camera.params.directive_location().line, 7);
}

TEST(ParserDirectives, DefaultsWhenNothingIsGiven) {
    SceneDescription d = parse("WorldBegin\n");
    EXPECT_TRUE(d.film.type.empty());
    EXPECT_TRUE(d.sampler.type.empty());
    EXPECT_FALSE(d.has_camera);
    EXPECT_EQ(d.color_space, &RGBColorSpace::srgb());
    EXPECT_TRUE(d.shapes.empty());
    EXPECT_TRUE(d.warnings.empty());
}

TEST(ParserDirectives, ParameterValueForms) {
    SceneDescription d = parse(
        "WorldBegin\nShape \"trianglemesh\"\n"
        "  \"point3 P\" [0 0 0  1 0 0  0 1 0]  \"point N\" [0 0 1]\n"
        "  \"normal Nn\" [0 0 1 0 0 1 0 0 1] \"vector S\" [1 0 0]\n"
        "  \"integer indices\" [0 1 2] \"point2 uv\" [0 0 1 0 0 1]\n"
        "  \"bool flag\" true \"bool quoted\" \"false\" \"string names\" [\"a\" \"b\"]\n"
        "  \"float neg\" -2.5e-1 \"float plus\" +3 \"float dot\" [.5 -.25 1.]\n");
    const ParameterDictionary &p = d.shapes[0].params;
    auto P = p.get_point3_array("P");
    ASSERT_EQ(P.size(), 3u);
    EXPECT_EQ(P[1].x, 1);
    EXPECT_EQ(p.get_one_point3("N", {}).z, 1);  // "point" is point3
    EXPECT_EQ(p.get_normal_array("Nn").size(), 3u);
    EXPECT_EQ(p.get_one_vector3("S", {}).x, 1);
    EXPECT_EQ(p.get_int_array("indices"), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(p.get_point2_array("uv").size(), 3u);
    EXPECT_TRUE(p.get_one_bool("flag", false));
    EXPECT_FALSE(p.get_one_bool("quoted", true));
    EXPECT_EQ(p.get_string_array("names"), (std::vector<std::string>{"a", "b"}));
    EXPECT_FLOAT_EQ(p.get_one_float("neg", 0), -0.25f);
    EXPECT_FLOAT_EQ(p.get_one_float("plus", 0), 3);
    EXPECT_EQ(p.get_float_array("dot"), (std::vector<float>{0.5f, -0.25f, 1.f}));
    EXPECT_EQ(p.location("S").line, 4);
    EXPECT_EQ(p.location("S").column, 35);
}

TEST(ParserDirectives, MaterialsAndNamedMaterials) {
    SceneDescription d = parse(
        "WorldBegin\n"
        "Shape \"sphere\"\n"
        "Material \"diffuse\" \"rgb reflectance\" [.2 .3 .4]\n"
        "Shape \"sphere\"\n"
        "MakeNamedMaterial \"gold\" \"string type\" \"conductor\"\n"
        "NamedMaterial \"gold\"\n"
        "Shape \"sphere\"\n"
        "AttributeBegin\nMaterial \"dielectric\"\nShape \"sphere\"\nAttributeEnd\n"
        "Shape \"disk\"\n"
        "NamedMaterial \"later\"\n"
        "Shape \"disk\"\n"
        "MakeNamedMaterial \"later\" \"string type\" \"diffuse\"\n");
    ASSERT_EQ(d.shapes.size(), 6u);
    EXPECT_EQ(d.shapes[0].material_index, -1);  // pbrt's default material
    EXPECT_TRUE(d.shapes[0].material_name.empty());
    ASSERT_EQ(d.materials.size(), 2u);
    EXPECT_EQ(d.materials[0].type, "diffuse");
    EXPECT_EQ(d.shapes[1].material_index, 0);
    EXPECT_EQ(d.shapes[2].material_index, -1);
    EXPECT_EQ(d.shapes[2].material_name, "gold");
    EXPECT_EQ(d.shapes[3].material_index, 1);
    EXPECT_TRUE(d.shapes[3].material_name.empty());
    EXPECT_EQ(d.shapes[4].material_name, "gold");  // restored by AttributeEnd
    // A named material may be defined after it is used, as in pbrt-v4.
    EXPECT_EQ(d.shapes[5].material_name, "later");
    ASSERT_EQ(d.named_materials.size(), 2u);
    EXPECT_EQ(d.named_materials[0].first, "gold");
    EXPECT_EQ(d.named_materials[0].second.type, "conductor");
    EXPECT_EQ(d.named_materials[1].first, "later");
}

TEST(ParserDirectives, Textures) {
    SceneDescription d = parse(
        "WorldBegin\n"
        "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 4\n"
        "Texture \"checks\" \"float\" \"checkerboard\"\n");  // float and spectrum names are separate
    ASSERT_EQ(d.textures.size(), 2u);
    EXPECT_EQ(d.textures[0].name, "checks");
    EXPECT_EQ(d.textures[0].texture_class, "spectrum");
    EXPECT_EQ(d.textures[0].type, "checkerboard");
    EXPECT_FLOAT_EQ(d.textures[0].params.get_one_float("uscale", 1), 4);
    EXPECT_EQ(d.textures[1].texture_class, "float");
}

TEST(ParserDirectives, LightsAreaLightsAndOrientation) {
    SceneDescription d = parse(
        "WorldBegin\n"
        "LightSource \"distant\" \"blackbody L\" 5500\n"
        "AttributeBegin\n"
        "AreaLightSource \"diffuse\" \"rgb L\" [4 4 4]\n"
        "ReverseOrientation\n"
        "Shape \"sphere\"\nShape \"disk\"\n"
        "AttributeEnd\n"
        "Shape \"sphere\"\n");
    ASSERT_EQ(d.lights.size(), 1u);
    EXPECT_EQ(d.lights[0].type, "distant");
    ASSERT_EQ(d.area_lights.size(), 2u);  // one per emissive shape
    EXPECT_EQ(d.area_lights[0].type, "diffuse");
    EXPECT_EQ(d.area_lights[0].loc.line, 4);
    EXPECT_EQ(d.shapes[0].area_light_index, 0);
    EXPECT_EQ(d.shapes[1].area_light_index, 1);
    EXPECT_EQ(d.shapes[2].area_light_index, -1);
    EXPECT_TRUE(d.shapes[0].reverse_orientation);
    EXPECT_TRUE(d.shapes[1].reverse_orientation);
    EXPECT_FALSE(d.shapes[2].reverse_orientation);
}

TEST(ParserDirectives, Media) {
    SceneDescription d = parse(
        "MakeNamedMedium \"air\" \"string type\" \"homogeneous\" \"float scale\" 2\n"
        "MediumInterface \"\" \"air\"\n"
        "Camera \"perspective\"\n"
        "WorldBegin\n"
        "MakeNamedMedium \"glass\" \"string type\" \"homogeneous\"\n"
        "LightSource \"point\"\n"
        "AttributeBegin\nMediumInterface \"glass\" \"air\"\nShape \"sphere\"\nAttributeEnd\n"
        "MediumInterface \"glass\"\nShape \"sphere\"\n");
    ASSERT_EQ(d.media.size(), 2u);
    EXPECT_EQ(d.media[0].name, "air");
    EXPECT_EQ(d.media[0].type, "homogeneous");
    EXPECT_FLOAT_EQ(d.media[0].params.get_one_float("scale", 1), 2);
    EXPECT_EQ(d.camera.medium, "air");
    EXPECT_EQ(d.lights[0].medium, "air");  // WorldBegin resets the CTM, not the media
    EXPECT_EQ(d.shapes[0].inside_medium, "glass");
    EXPECT_EQ(d.shapes[0].outside_medium, "air");
    EXPECT_EQ(d.shapes[1].inside_medium, "glass");
    EXPECT_EQ(d.shapes[1].outside_medium, "glass");
}

TEST(ParserDirectives, AttributeDefaultsApplyAndYieldToOwnValues) {
    SceneDescription d = parse(
        "WorldBegin\n"
        "AttributeBegin\n"
        "Attribute \"shape\" \"float radius\" 3 \"float zmax\" 1\n"
        "Attribute \"light\" \"float scale\" 2\n"
        "Shape \"sphere\" \"float radius\" 5\n"
        "Shape \"sphere\"\n"
        "LightSource \"point\"\n"
        "AttributeEnd\n"
        "Shape \"sphere\"\n");
    EXPECT_FLOAT_EQ(d.shapes[0].params.get_one_float("radius", 1), 5);
    EXPECT_FLOAT_EQ(d.shapes[0].params.get_one_float("zmax", 0), 1);
    EXPECT_FLOAT_EQ(d.shapes[1].params.get_one_float("radius", 1), 3);
    EXPECT_FLOAT_EQ(d.lights[0].params.get_one_float("scale", 1), 2);
    EXPECT_FLOAT_EQ(d.shapes[2].params.get_one_float("radius", 1), 1);  // popped
}

TEST(ParserDirectives, ObjectInstancing) {
    SceneDescription d = parse(
        "WorldBegin\n"
        "ObjectInstance \"early\"\n"  // allowed before the definition, as in pbrt-v4
        "ObjectBegin \"early\"\nShape \"sphere\"\nShape \"disk\"\nObjectEnd\n"
        "ObjectBegin \"other\"\nMaterial \"conductor\"\nShape \"sphere\"\nObjectEnd\n"
        "Shape \"cylinder\"\n"
        "ObjectInstance \"other\"\nObjectInstance \"early\"\n");
    ASSERT_EQ(d.instances.size(), 2u);
    EXPECT_EQ(d.instances[0].name, "early");
    EXPECT_EQ(d.instances[0].shapes.size(), 2u);
    EXPECT_EQ(d.instances[0].loc.line, 3);
    EXPECT_EQ(d.instances[1].shapes[0].material_index, 0);
    ASSERT_EQ(d.shapes.size(), 1u);  // instance shapes are not scene shapes
    EXPECT_EQ(d.shapes[0].material_index, -1);  // ObjectEnd restored the material
    ASSERT_EQ(d.instance_uses.size(), 3u);
    EXPECT_EQ(d.instance_uses[0].name, "early");
    EXPECT_EQ(d.instance_uses[1].name, "other");
    EXPECT_EQ(d.instance_uses[1].loc.line, 12);
}

TEST(ParserDirectives, AreaLightInsideInstanceWarns) {
    SceneDescription d = parse("WorldBegin\nAreaLightSource \"diffuse\"\n"
                               "ObjectBegin \"o\"\nShape \"sphere\"\nObjectEnd\n");
    EXPECT_EQ(d.instances[0].shapes[0].area_light_index, -1);
    EXPECT_TRUE(d.area_lights.empty());
    EXPECT_EQ(d.warnings.size(), 1u);
}

TEST(ParserDirectives, ColorSpace) {
    SceneDescription d = parse(
        "ColorSpace \"rec2020\"\nFilm \"rgb\"\nColorSpace \"srgb\"\nWorldBegin\n"
        "Shape \"sphere\"\n"
        "AttributeBegin\nColorSpace \"aces2065-1\"\nShape \"sphere\"\nAttributeEnd\n"
        "Shape \"sphere\"\n");
    // The film's colour space is the one in effect at Film.
    EXPECT_EQ(d.color_space, RGBColorSpace::by_name("rec2020"));
    EXPECT_EQ(&d.film.params.color_space(), RGBColorSpace::by_name("rec2020"));
    EXPECT_EQ(&d.shapes[0].params.color_space(), &RGBColorSpace::srgb());
    EXPECT_EQ(&d.shapes[1].params.color_space(), RGBColorSpace::by_name("aces2065-1"));
    EXPECT_EQ(&d.shapes[2].params.color_space(), &RGBColorSpace::srgb());
    SceneDescription without_film = parse("ColorSpace \"dci-p3\"\nWorldBegin\n");
    EXPECT_EQ(without_film.color_space, RGBColorSpace::by_name("dci-p3"));
}

TEST(ParserDirectives, Options) {
    SceneDescription d = parse("Option \"disablepixeljitter\" true\nOption \"seed\" 7\n"
                               "Option \"seed\" 9\nOption \"bool force-diffuse\" \"true\"\n"
                               "Option \"nonsense\" 1\nWorldBegin\n");
    EXPECT_TRUE(d.options.get_one_bool("disablepixeljitter", false));
    EXPECT_EQ(d.options.get_one_int("seed", 0), 9);
    EXPECT_TRUE(d.options.get_one_bool("forcediffuse", false));
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_NE(d.warnings[0].find("nonsense"), std::string::npos);
}

TEST(ParserDirectives, WarningsCarryLocations) {
    SceneDescription d = parse("WorldBegin\n\n  CoordSysTransform \"x\"\n");
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_EQ(d.warnings[0].rfind("test.pbrt:3:3: warning:", 0), 0u) << d.warnings[0];
}

std::string data_path(const std::string &name) {
    return std::string(CAUSTICA_TEST_DATA) + "/parser/" + name;
}

TEST(ParserFiles, IncludeIsTextualAndRelativeToTheIncludingFile) {
    SceneDescription d = parse_scene_file(data_path("scenes/include_main.pbrt"));
    // include_main.pbrt: Translate, then Include "parts/shapes.pbrt", which includes
    // "more.pbrt" next to itself and sets a material that stays in effect afterwards.
    ASSERT_EQ(d.shapes.size(), 3u);
    EXPECT_EQ(std::filesystem::path(d.shapes[0].loc.file).filename(), "shapes.pbrt");
    EXPECT_EQ(d.shapes[0].loc.line, 2);
    EXPECT_EQ(std::filesystem::path(d.shapes[1].loc.file).filename(), "more.pbrt");
    EXPECT_EQ(std::filesystem::path(d.shapes[2].loc.file).filename(), "include_main.pbrt");
    EXPECT_EQ(d.shapes[2].material_index, 0);
    EXPECT_EQ(d.shapes[0].render_from_object.apply_point({0, 0, 0}).x, 1);
    // Parameters resolve relative file names against the main scene file's directory.
    EXPECT_EQ(d.shapes[0].params.base_directory(),
              std::filesystem::path(data_path("scenes/include_main.pbrt")).parent_path().string());
}

TEST(ParserFiles, ImportDoesNotLeakGraphicsState) {
    SceneDescription d = parse_scene_file(data_path("scenes/import_main.pbrt"));
    // import_main.pbrt imports a file that sets a material and a transform, adds a shape and
    // a named material; afterwards the importer's state is back.
    ASSERT_EQ(d.shapes.size(), 2u);
    EXPECT_EQ(d.shapes[0].material_index, 0);
    EXPECT_EQ(d.shapes[0].render_from_object.apply_point({0, 0, 0}).y, 3);
    EXPECT_EQ(d.shapes[1].material_index, -1);
    EXPECT_TRUE(d.shapes[1].render_from_object.is_identity());
    ASSERT_EQ(d.named_materials.size(), 1u);
    EXPECT_EQ(d.shapes[1].material_name, "");
}

TEST(ParserFiles, MissingSceneFile) {
    EXPECT_THROW(parse_scene_file(data_path("no_such_file.pbrt")), InputError);
}

} // namespace
} // namespace caustica
