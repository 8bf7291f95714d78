// Render progress for people: a redrawn bar on a terminal, one plain line per 10% otherwise
// (logs and CI output stay readable).
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <mutex>

namespace caustica {

class ProgressReporter {
  public:
    ProgressReporter(bool enabled, FILE *out = stderr);
    // Thread-safe; fraction in [0,1], samples = pixel samples taken so far.
    void update(double fraction, uint64_t samples);
    void finish();

  private:
    bool enabled_, terminal_;
    FILE *out_;
    std::mutex mutex_;
    std::chrono::steady_clock::time_point start_, last_draw_;
    int last_decile_ = -1;
    double last_fraction_ = 0;
    uint64_t last_samples_ = 0;
    void draw(double fraction, uint64_t samples);
};

} // namespace caustica
