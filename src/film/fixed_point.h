// Fixed-point sums: the film's stores add values as integers, so that a sum does not depend on
// the order of its terms. Floating-point addition is not associative; integer addition is. The
// image is therefore the same bit for bit whatever the number of threads, whatever order
// light-tracing splats arrive in, and whether the samples were taken by one process or shared
// between the ranks of an MPI job and added together afterwards (cli/distributed_render.h).
//
// Sums of values (camera samples, their filter weights, splats) are 64-bit integers in units of
// 2^-28: rounding is below 2e-9 absolute, far under what any image format shows, and the range
// (+-3.4e10 per pixel and channel) is far above any pixel value times any realistic sample
// count. Sums of squares (the variance layers' moments) span the squares of that range, so they
// are 128-bit, in units of 2^-64. Leaving the range is detected, never wrapped silently.
#pragma once

#include <cmath>
#include <cstdint>

namespace caustica::fixed_point {

inline constexpr double kUnit = 0x1p-28;
// The largest single term, in units: sums of 2 terms cannot wrap before the overflow check.
inline constexpr double kLimit = 0x1p62;

// Adds v (in value units) to sum, rounded to the nearest unit; returns false if the term or the
// sum left the range (the sum is then clamped or wrapped, and the caller reports it).
inline bool add(int64_t &sum, double v) {
    double units = std::nearbyint(v / kUnit);
    bool ok = std::abs(units) <= kLimit;
    if (!ok) units = std::copysign(kLimit, units);
    return !__builtin_add_overflow(sum, int64_t(units), &sum) && ok;
}

inline double value(int64_t sum) { return double(sum) * kUnit; }

// The 128-bit sums of squares: units of 2^-64.
using Wide = __int128;
inline constexpr double kWideUnit = 0x1p-64;
inline constexpr double kWideLimit = 0x1p125;

inline bool add(Wide &sum, double v) {
    double units = std::nearbyint(v / kWideUnit);
    bool ok = std::abs(units) <= kWideLimit;
    if (!ok) units = std::copysign(kWideLimit, units);
    return !__builtin_add_overflow(sum, Wide(units), &sum) && ok;
}

inline double value(Wide sum) { return double(sum) * kWideUnit; }

} // namespace caustica::fixed_point
