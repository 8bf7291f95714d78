// libFuzzer entry point: parses the input as a scene and builds it, as `caustica render` would
// up to the first sample. scripts/fuzz.sh builds and runs it.
//
// The input is scene text. It may carry files for Include and Import too: a line "#file NAME"
// (a comment to the parser) starts an in-memory file called NAME that runs to the next such
// line; the text before the first one is "main.pbrt". Nothing is read from disk: the parse runs
// with ParseOptions::file_access off, so Include/Import see only these files and parameters
// that name files (spectrum files, "plymesh", image "filename"s) are InputErrors. The film is
// overridden to 16x16 pixels and one sample per pixel so that an execution stays small; the
// film's own size limits are covered by the malformed scenes instead.
//
// An InputError is the expected answer to bad input. Anything else is a finding: a crash or
// sanitizer report, another exception (libFuzzer reports it as an abort), a leak, a hang.
#include "core/error.h"
#include "parser/scene_description.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

constexpr std::string_view FileMarker = "#file ";

caustica::ParseOptions split_files(std::string_view input, std::string *main_text) {
    caustica::ParseOptions options;
    options.file_access = false;
    std::string *current = main_text;
    size_t pos = 0;
    while (pos < input.size()) {
        size_t end = input.find('\n', pos);
        size_t next = end == std::string_view::npos ? input.size() : end + 1;
        std::string_view line = input.substr(pos, next - pos);
        if (line.substr(0, FileMarker.size()) == FileMarker) {
            std::string_view name = line.substr(FileMarker.size());
            while (!name.empty() && (name.back() == '\n' || name.back() == '\r' || name.back() == ' '))
                name.remove_suffix(1);
            current = &options.files[std::string(name)];
        } else {
            current->append(line);
        }
        pos = next;
    }
    return options;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
    // Warnings are expected for most inputs; printing them would only slow the fuzzer down.
    caustica::set_warnings_enabled(false);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::string main_text;
    caustica::ParseOptions options =
        split_files(std::string_view(reinterpret_cast<const char *>(data), size), &main_text);
    try {
        caustica::SceneDescription description =
            caustica::parse_scene_string(main_text, "main.pbrt", options);
        caustica::RenderOverrides overrides;
        overrides.width = overrides.height = 16;
        overrides.spp = 1;
        caustica::build_scene(description, overrides);
    } catch (const caustica::InputError &) {
    }
    return 0;
}
