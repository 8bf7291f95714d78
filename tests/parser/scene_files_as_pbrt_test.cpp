// Scene-file handling that real pbrt-v4 scenes rely on: compressed Includes, the deprecated empty
// material, and warnings printed once each in the order the files are read.
#include "parser_test_util.h"

#include <zlib.h>

#include <filesystem>

namespace caustica {
namespace {

namespace fs = std::filesystem;

TEST(SceneFilesAsPbrt, IncludeOfAGzippedFile) {
    fs::path dir = fs::temp_directory_path() / "caustica_gz_include";
    fs::create_directories(dir);
    const std::string geometry = "Shape \"sphere\" \"float radius\" 2\n";
    gzFile out = gzopen((dir / "geometry.pbrt.gz").c_str(), "wb");
    ASSERT_TRUE(out);
    gzwrite(out, geometry.data(), unsigned(geometry.size()));
    gzclose(out);
    {
        FILE *f = std::fopen((dir / "main.pbrt").c_str(), "w");
        std::fputs("WorldBegin\nInclude \"geometry.pbrt.gz\"\n", f);
        std::fclose(f);
    }
    SceneDescription d = parse_scene_file((dir / "main.pbrt").string());
    ASSERT_EQ(d.shapes.size(), 1u);
    EXPECT_EQ(d.shapes[0].type, "sphere");
    EXPECT_EQ(d.shapes[0].loc.line, 1);
    // A missing compressed file is an error at the Include.
    {
        FILE *f = std::fopen((dir / "bad.pbrt").c_str(), "w");
        std::fputs("WorldBegin\nInclude \"missing.pbrt.gz\"\n", f);
        std::fclose(f);
    }
    try {
        parse_scene_file((dir / "bad.pbrt").string());
        ADD_FAILURE() << "no error";
    } catch (const InputError &e) {
        EXPECT_EQ(e.location().line, 2);
    }
    fs::remove_all(dir);
}

TEST(SceneFilesAsPbrt, EmptyMaterialIsInterface) {
    SceneDescription d = test::parse("WorldBegin\nMaterial \"\"\nShape \"sphere\"\n");
    ASSERT_EQ(d.materials.size(), 1u);
    EXPECT_EQ(d.materials[0].type, "interface");
}

TEST(SceneFilesAsPbrt, WarningsInReadingOrderAndOnceEach) {
    ParseOptions options;
    options.file_access = false;
    options.files = {{"parts/a.pbrt", "Material \"\"\n"}};
    testing::internal::CaptureStderr();
    {
        SceneWarningOrder in_file_order;
        parse_scene_string("WorldBegin\nInclude \"parts/a.pbrt\"\nMaterial \"none\"\n"
                           "Include \"parts/a.pbrt\"\n",
                           "main.pbrt", options);
        warning(SourceLocation{"main.pbrt", 1, 1}, "reported last, located first");
        warning("without a location");
    }
    std::string printed = testing::internal::GetCapturedStderr();
    const std::string deprecated = "warning: Material \"\" is deprecated";
    size_t first = printed.find("main.pbrt:1:1: warning: reported last");
    size_t included = printed.find("parts/a.pbrt:1:1: " + deprecated);
    size_t after = printed.find("main.pbrt:3:1: warning: Material \"none\"");
    size_t unlocated = printed.find("\nwarning: without a location");
    ASSERT_NE(first, std::string::npos) << printed;
    ASSERT_NE(included, std::string::npos) << printed;
    ASSERT_NE(after, std::string::npos) << printed;
    ASSERT_NE(unlocated, std::string::npos) << printed;
    EXPECT_LT(first, included);
    EXPECT_LT(included, after);
    EXPECT_LT(after, unlocated);
    // The file is included twice, its warning printed once.
    EXPECT_EQ(printed.find(deprecated, printed.find(deprecated) + 1), std::string::npos) << printed;
}

} // namespace
} // namespace caustica
