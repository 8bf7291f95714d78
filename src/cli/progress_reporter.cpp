#include "cli/progress_reporter.h"

#include <algorithm>
#include <string>
#include <unistd.h>

namespace caustica {

namespace {
std::string human_rate(double per_second) {
    char buf[32];
    if (per_second >= 1e6) std::snprintf(buf, sizeof buf, "%.2fM", per_second / 1e6);
    else if (per_second >= 1e3) std::snprintf(buf, sizeof buf, "%.1fk", per_second / 1e3);
    else std::snprintf(buf, sizeof buf, "%.0f", per_second);
    return buf;
}
} // namespace

ProgressReporter::ProgressReporter(bool enabled, FILE *out)
    : enabled_(enabled), terminal_(isatty(fileno(out))), out_(out),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void ProgressReporter::update(double fraction, uint64_t samples) {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    fraction = std::clamp(fraction, 0.0, 1.0);
    // Tiles finish out of order: keep the display monotonic.
    if (fraction < last_fraction_) return;
    last_fraction_ = fraction;
    last_samples_ = std::max(last_samples_, samples);
    auto now = std::chrono::steady_clock::now();
    if (terminal_) {
        if (now - last_draw_ < std::chrono::milliseconds(100) && fraction < 1) return;
        last_draw_ = now;
        draw(fraction, last_samples_);
    } else {
        int decile = int(fraction * 10 + 1e-9);
        if (decile <= last_decile_) return;
        last_decile_ = decile;
        draw(fraction, last_samples_);
    }
}

void ProgressReporter::draw(double fraction, uint64_t samples) {
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    double rate = elapsed > 0 ? samples / elapsed : 0;
    double left = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
    if (terminal_) {
        constexpr int width = 30;
        int filled = int(fraction * width);
        std::string bar(filled, '#');
        bar.resize(width, ' ');
        std::fprintf(out_, "\r[%s] %3d%%  %s samples/s  %.0fs left   ", bar.c_str(),
                     int(fraction * 100), human_rate(rate).c_str(), left);
    } else {
        std::fprintf(out_, "progress: %3d%%  %s samples/s  %.1fs elapsed  %.1fs left\n",
                     int(fraction * 100 + 1e-9), human_rate(rate).c_str(), elapsed, left);
    }
    std::fflush(out_);
}

void ProgressReporter::finish() {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    if (terminal_) std::fprintf(out_, "\n");
    std::fflush(out_);
}

} // namespace caustica
