// Scenes that parse but are wrong when built (tests/data/parser/malformed/build/): absurd sizes,
// indices out of range, values outside their physical range. Building each must throw an
// InputError at the recorded place, before any large allocation (the command turns it into
// exit status 2, as the Cli tests check for the parser's corpus); the warning scenes must
// build, and `caustica info` must print the warning at theirs. Positions in the manifests were
// taken from the files as written, not from the program's output.
#include "../integrators/render_test_support.h"
#include "parser/scene_description.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace caustica::testing;
namespace fs = std::filesystem;

namespace {

struct Expectation {
    std::string scene, located_in;
    int line = 0, column = 0;
    std::string message;
};

std::string corpus_dir() { return data_path("parser/malformed/build"); }

std::vector<Expectation> read_manifest(const std::string &name) {
    std::ifstream in(corpus_dir() + "/" + name);
    EXPECT_TRUE(in) << "cannot read " << name;
    std::vector<Expectation> cases;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        Expectation e;
        fields >> e.scene >> e.located_in >> e.line >> e.column;
        std::getline(fields >> std::ws, e.message);
        EXPECT_FALSE(e.message.empty()) << "malformed manifest line: " << line;
        cases.push_back(e);
    }
    return cases;
}

// Runs `caustica info` on the scene; returns the exit status and its stderr.
int run_info(const Expectation &e, const std::string &dir, std::string *stderr_text) {
    std::string err = dir + "/" + e.scene + ".err";
    int status = run_caustica("info " + corpus_dir() + "/" + e.scene, err);
    *stderr_text = read_text(err);
    return status;
}

std::string warning_prefix(const Expectation &e) {
    return fs::path(e.located_in).filename().string() + ":" + std::to_string(e.line) + ":" +
           std::to_string(e.column) + ": warning: ";
}

TEST(MalformedScenes, BuildErrorsAtTheRecordedLocation) {
    std::vector<Expectation> cases = read_manifest("expected.txt");
    EXPECT_GE(cases.size(), 15u);
    caustica::set_warnings_enabled(false);
    for (const Expectation &e : cases) {
        SCOPED_TRACE(e.scene);
        try {
            caustica::SceneDescription d = caustica::parse_scene_file(corpus_dir() + "/" + e.scene);
            caustica::build_scene(d, caustica::RenderOverrides{});
            ADD_FAILURE() << e.scene << " built without an error";
        } catch (const caustica::InputError &error) {
            EXPECT_EQ(fs::weakly_canonical(error.location().file),
                      fs::weakly_canonical(corpus_dir() + "/" + e.located_in))
                << error.what();
            EXPECT_EQ(error.location().line, e.line) << error.what();
            EXPECT_EQ(error.location().column, e.column) << error.what();
            EXPECT_NE(error.message().find(e.message), std::string::npos)
                << "message \"" << error.message() << "\" lacks \"" << e.message << "\"";
        }
    }
    caustica::set_warnings_enabled(true);
}

TEST(MalformedScenes, WarningsAtTheRecordedLocation) {
    std::vector<Expectation> cases = read_manifest("warnings.txt");
    EXPECT_GE(cases.size(), 4u);
    std::string dir = scratch_dir("malformed-warnings");
    for (const Expectation &e : cases) {
        std::string text;
        EXPECT_EQ(run_info(e, dir, &text), 0) << e.scene << ": " << text;
        EXPECT_NE(text.find(warning_prefix(e)), std::string::npos) << e.scene << ": " << text;
        EXPECT_NE(text.find(e.message), std::string::npos)
            << e.scene << ": \"" << text << "\" lacks \"" << e.message << "\"";
    }
}

TEST(MalformedScenes, ManifestsListEveryScene) {
    std::set<std::string> listed;
    for (const char *manifest : {"expected.txt", "warnings.txt"})
        for (const Expectation &e : read_manifest(manifest)) listed.insert(e.scene);
    for (const auto &entry : fs::directory_iterator(corpus_dir())) {
        if (entry.path().extension() == ".pbrt") {
            EXPECT_TRUE(listed.count(entry.path().filename().string())) << entry.path() << " is in no manifest";
        }
    }
}

} // namespace
