#include "core/error.h"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace caustica {

namespace {
std::atomic<bool> warnings_enabled{true};
std::mutex warning_mutex;
} // namespace

void set_warnings_enabled(bool enabled) { warnings_enabled = enabled; }

void warning(const SourceLocation &loc, const std::string &message) {
    if (!warnings_enabled) return;
    std::lock_guard<std::mutex> lock(warning_mutex);
    std::fprintf(stderr, "%s: warning: %s\n", loc.to_string().c_str(), message.c_str());
}

void warning(const std::string &message) {
    if (!warnings_enabled) return;
    std::lock_guard<std::mutex> lock(warning_mutex);
    std::fprintf(stderr, "warning: %s\n", message.c_str());
}

void note(const std::string &message) {
    if (!warnings_enabled) return;
    std::lock_guard<std::mutex> lock(warning_mutex);
    std::fprintf(stderr, "note: %s\n", message.c_str());
}

} // namespace caustica
