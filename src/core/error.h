// User-facing errors and warnings that point into scene files as file:line:column.
#pragma once

#include <stdexcept>
#include <string>

namespace caustica {

struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;
    std::string to_string() const {
        if (file.empty()) return "<unknown>";
        return file + ":" + std::to_string(line) + ":" + std::to_string(column);
    }
};

// Bad user input (scene file, command line, referenced file). The command reports
// "file:line:column: error: message" and exits with status 2 without writing any image.
class InputError : public std::runtime_error {
  public:
    InputError(SourceLocation loc, const std::string &message)
        : std::runtime_error(loc.to_string() + ": error: " + message), loc_(std::move(loc)),
          message_(message) {}
    explicit InputError(const std::string &message)
        : std::runtime_error("error: " + message), message_(message) {}
    const SourceLocation &location() const { return loc_; }
    const std::string &message() const { return message_; }

  private:
    SourceLocation loc_;
    std::string message_;
};

// Prints "file:line:column: warning: message" to stderr (thread-safe, unless warnings are muted).
void warning(const SourceLocation &loc, const std::string &message);
void warning(const std::string &message);
// Prints "note: message" to stderr: information the user asked for implicitly (such as why
// `--integrator auto` chose an integrator); muted with the warnings.
void note(const std::string &message);
// While one of these is alive (the command line keeps one around reading and building a scene),
// warnings with a location are held back; when it ends they are printed in the order their
// locations are read, an included file's where its Include stands, and each distinct warning
// once however many times an Include repeats it. Warnings without a location follow them.
class SceneWarningOrder {
  public:
    SceneWarningOrder();
    ~SceneWarningOrder();
    SceneWarningOrder(const SceneWarningOrder &) = delete;
    SceneWarningOrder &operator=(const SceneWarningOrder &) = delete;
    // The parser reports each file it reads through Include or Import: `file` is read at `at`.
    static void file_included(const SourceLocation &at, const std::string &file);
};
// Tests silence warnings; the command line keeps them on.
void set_warnings_enabled(bool enabled);

} // namespace caustica
