// Every file in tests/data/parser/malformed/ must fail to parse with an InputError at the
// file:line:column recorded in expected.txt (positions were taken from the files as written,
// by marking the offending character, not from the parser's output).
#include "parser/scene_description.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace caustica {
namespace {

namespace fs = std::filesystem;

struct ExpectedError {
    std::string scene, location_file;
    int line = 0, column = 0;
    std::string message;
};

const fs::path &corpus_dir() {
    static const fs::path dir = fs::path(CAUSTICA_TEST_DATA) / "parser" / "malformed";
    return dir;
}

std::vector<ExpectedError> read_manifest() {
    std::ifstream in(corpus_dir() / "expected.txt");
    EXPECT_TRUE(in) << "cannot read expected.txt";
    std::vector<ExpectedError> cases;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        ExpectedError e;
        fields >> e.scene >> e.location_file >> e.line >> e.column;
        std::getline(fields >> std::ws, e.message);
        EXPECT_FALSE(e.message.empty()) << "malformed manifest line: " << line;
        cases.push_back(e);
    }
    return cases;
}

TEST(MalformedCorpus, EveryFileFailsAtTheRecordedLocation) {
    std::vector<ExpectedError> cases = read_manifest();
    EXPECT_GE(cases.size(), 30u);
    set_warnings_enabled(false);
    for (const ExpectedError &e : cases) {
        SCOPED_TRACE(e.scene);
        try {
            parse_scene_file((corpus_dir() / e.scene).string());
            ADD_FAILURE() << e.scene << " parsed without an error";
        } catch (const InputError &error) {
            const SourceLocation &loc = error.location();
            EXPECT_EQ(fs::weakly_canonical(loc.file), fs::weakly_canonical(corpus_dir() / e.location_file))
                << error.what();
            EXPECT_EQ(loc.line, e.line) << error.what();
            EXPECT_EQ(loc.column, e.column) << error.what();
            EXPECT_NE(error.message().find(e.message), std::string::npos)
                << "message \"" << error.message() << "\" lacks \"" << e.message << "\"";
        }
    }
    set_warnings_enabled(true);
}

TEST(MalformedCorpus, ManifestListsEveryScene) {
    std::set<std::string> listed;
    for (const ExpectedError &e : read_manifest()) listed.insert(e.scene);
    for (const auto &entry : fs::directory_iterator(corpus_dir())) {
        if (entry.path().extension() != ".pbrt") continue;
        EXPECT_TRUE(listed.count(entry.path().filename().string()))
            << entry.path() << " is not in expected.txt";
    }
}

} // namespace
} // namespace caustica
