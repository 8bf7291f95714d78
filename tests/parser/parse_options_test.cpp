// Parsing without file access (ParseOptions): Include and Import read in-memory files only,
// with the nesting and cycle limits of files on disk, and parameters may not name files.
#include "parser_test_util.h"

#include <string>

namespace caustica {
namespace {

ParseOptions memory_files(std::map<std::string, std::string> files) {
    ParseOptions options;
    options.file_access = false;
    options.files = std::move(files);
    return options;
}

InputError parse_error_with(const std::string &text, const std::string &name, const ParseOptions &options) {
    set_warnings_enabled(false);
    try {
        parse_scene_string(text, name, options);
    } catch (const InputError &e) {
        set_warnings_enabled(true);
        return e;
    }
    set_warnings_enabled(true);
    ADD_FAILURE() << "expected an InputError for:\n" << text;
    return InputError("no error");
}

TEST(ParseOptions, IncludeAndImportReadInMemoryFilesRelativeToTheIncluder) {
    ParseOptions options = memory_files({
        {"scene/parts/a.pbrt", "Include \"b.pbrt\"\nShape \"sphere\" \"float radius\" 2\n"},
        {"scene/parts/b.pbrt", "Material \"conductor\"\n"},
        {"scene/lights.pbrt", "AttributeBegin\nLightSource \"point\"\nAttributeEnd\nReverseOrientation\n"},
    });
    SceneDescription d = parse_scene_string(
        "WorldBegin\nInclude \"parts/a.pbrt\"\nImport \"./parts/../lights.pbrt\"\nShape \"disk\"\n",
        "scene/main.pbrt", options);
    ASSERT_EQ(d.shapes.size(), 2u);
    EXPECT_EQ(d.shapes[0].loc.file, "scene/parts/a.pbrt");
    EXPECT_EQ(d.shapes[0].loc.line, 2);
    EXPECT_EQ(d.shapes[0].material_index, 0);  // the Include's material stays in effect
    // Import restores the importer's state: the ReverseOrientation does not reach the disk.
    EXPECT_FALSE(d.shapes[1].reverse_orientation);
    EXPECT_EQ(d.lights.size(), 1u);
    EXPECT_EQ(d.lights[0].loc.file, "scene/lights.pbrt");
}

TEST(ParseOptions, WithoutFileAccessNothingIsReadFromDisk) {
    // This test's own source exists on disk; without file access it is still not found.
    std::string on_disk = std::string(CAUSTICA_SOURCE_DIR) + "/tests/parser/parse_options_test.cpp";
    InputError e = parse_error_with("WorldBegin\nInclude \"" + on_disk + "\"\n", "main.pbrt", memory_files({}));
    EXPECT_EQ(e.location().line, 2);
    EXPECT_EQ(e.location().column, 9);
    EXPECT_NE(e.message().find("file access is disabled"), std::string::npos) << e.message();

    SceneDescription d = parse_scene_string(
        "WorldBegin\nShape \"plymesh\" \"string filename\" \"mesh.ply\"\n", "main.pbrt", memory_files({}));
    try {
        d.shapes[0].params.file_path("filename", "mesh.ply");
        ADD_FAILURE() << "file access was not disabled";
    } catch (const InputError &error) {
        EXPECT_EQ(error.location().line, 2);
        EXPECT_EQ(error.location().column, 17);
    }
}

TEST(ParseOptions, CyclesThroughInMemoryFilesAreErrors) {
    ParseOptions options = memory_files({{"a.pbrt", "Include \"b.pbrt\"\n"}, {"b.pbrt", "\nInclude \"main.pbrt\"\n"}});
    InputError e = parse_error_with("WorldBegin\nInclude \"a.pbrt\"\n", "main.pbrt", options);
    EXPECT_EQ(e.location().file, "b.pbrt");
    EXPECT_EQ(e.location().line, 2);
    EXPECT_EQ(e.location().column, 9);
    EXPECT_NE(e.message().find("cycle"), std::string::npos) << e.message();
}

TEST(ParseOptions, IncludeNestingIsLimited) {
    // f<k>.pbrt includes f<k+1>.pbrt: a chain longer than the parser's 32 levels, which counts the
    // main text as the first. The Include in f31.pbrt would open the 33rd.
    std::map<std::string, std::string> files;
    for (int k = 1; k <= 40; ++k)
        files["f" + std::to_string(k) + ".pbrt"] = "Include \"f" + std::to_string(k + 1) + ".pbrt\"\n";
    InputError e = parse_error_with("WorldBegin\nInclude \"f1.pbrt\"\n", "main.pbrt", memory_files(files));
    EXPECT_EQ(e.location().file, "f31.pbrt");
    EXPECT_EQ(e.location().line, 1);
    EXPECT_EQ(e.location().column, 9);
    EXPECT_NE(e.message().find("nested more than 32 levels"), std::string::npos) << e.message();

    // 31 levels below the main text are fine.
    files["f31.pbrt"] = "Shape \"sphere\"\n";
    SceneDescription d = parse_scene_string("WorldBegin\nInclude \"f1.pbrt\"\n", "main.pbrt", memory_files(files));
    EXPECT_EQ(d.shapes.size(), 1u);
}

} // namespace
} // namespace caustica
