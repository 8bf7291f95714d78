#include "core/error.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <utility>
#include <vector>

namespace caustica {

namespace {
std::atomic<bool> warnings_enabled{true};
std::mutex warning_mutex;

// The held-back warnings of the live SceneWarningOrder (guarded by warning_mutex).
struct HeldWarnings {
    std::map<std::string, SourceLocation> included_at; // file -> where it was first included
    std::vector<std::pair<SourceLocation, std::string>> located;
    std::vector<std::string> unlocated;
};
std::unique_ptr<HeldWarnings> held;
int held_depth = 0; // live SceneWarningOrder objects; the outermost prints

// A location's place in reading order: the positions of the Includes that lead to its file,
// outermost first, then its own line and column.
std::vector<std::pair<int, int>> reading_order(const SourceLocation &loc) {
    std::vector<std::pair<int, int>> key{{loc.line, loc.column}};
    std::set<std::string> seen{loc.file};
    for (auto it = held->included_at.find(loc.file); it != held->included_at.end();
         it = held->included_at.find(it->second.file)) {
        if (!seen.insert(it->second.file).second) break;
        key.insert(key.begin(), {it->second.line, it->second.column});
    }
    return key;
}

void print_located(const SourceLocation &loc, const std::string &message) {
    std::fprintf(stderr, "%s: warning: %s\n", loc.to_string().c_str(), message.c_str());
}
} // namespace

SceneWarningOrder::SceneWarningOrder() {
    std::lock_guard<std::mutex> lock(warning_mutex);
    if (held_depth++ == 0) held = std::make_unique<HeldWarnings>();
}

SceneWarningOrder::~SceneWarningOrder() {
    std::lock_guard<std::mutex> lock(warning_mutex);
    if (--held_depth > 0) return;
    std::vector<std::pair<std::vector<std::pair<int, int>>, size_t>> order;
    for (size_t i = 0; i < held->located.size(); ++i)
        order.push_back({reading_order(held->located[i].first), i});
    std::stable_sort(order.begin(), order.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    std::set<std::pair<std::string, std::string>> printed;
    for (const auto &[key, i] : order) {
        const auto &[loc, message] = held->located[i];
        if (printed.insert({loc.to_string(), message}).second) print_located(loc, message);
    }
    for (const std::string &message : held->unlocated) std::fprintf(stderr, "warning: %s\n", message.c_str());
    held.reset();
}

void SceneWarningOrder::file_included(const SourceLocation &at, const std::string &file) {
    std::lock_guard<std::mutex> lock(warning_mutex);
    if (held) held->included_at.emplace(file, at);
}

void set_warnings_enabled(bool enabled) { warnings_enabled = enabled; }

void warning(const SourceLocation &loc, const std::string &message) {
    if (!warnings_enabled) return;
    std::lock_guard<std::mutex> lock(warning_mutex);
    if (held) held->located.push_back({loc, message});
    else print_located(loc, message);
}

void warning(const std::string &message) {
    if (!warnings_enabled) return;
    std::lock_guard<std::mutex> lock(warning_mutex);
    if (held) held->unlocated.push_back(message);
    else std::fprintf(stderr, "warning: %s\n", message.c_str());
}

void note(const std::string &message) {
    if (!warnings_enabled) return;
    std::lock_guard<std::mutex> lock(warning_mutex);
    std::fprintf(stderr, "note: %s\n", message.c_str());
}

} // namespace caustica
