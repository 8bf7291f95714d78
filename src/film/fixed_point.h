// Fixed-point sums: the film's stores add values as integers, so that a sum does not depend on
// the order of its terms. Floating-point addition is not associative; integer addition is. The
// image is therefore the same bit for bit whatever the number of threads, whatever order
// light-tracing splats arrive in, and whether the samples were taken by one process or shared
// between the ranks of an MPI job and added together afterwards (cli/process_group.h).
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

using Wide = __int128;

// The unit of each kind of sum, and the largest single term in units (so that adding two terms
// cannot wrap before the overflow check).
template <typename Sum> struct Units;
template <> struct Units<int64_t> {
    static constexpr double unit = 0x1p-28, limit = 0x1p62;
};
template <> struct Units<Wide> {
    static constexpr double unit = 0x1p-64, limit = 0x1p125;
};

// Adds v (in value units) to sum, rounded to the nearest unit; returns false if the term or the
// sum left the range (the sum is then clamped or wrapped, and the caller reports it).
template <typename Sum> bool add(Sum &sum, double v) {
    const double scaled = v / Units<Sum>::unit; // exact: the unit is a power of two
    // At and beyond the limit doubles are integers, so testing before rounding is the same test.
    const bool ok = std::abs(scaled) <= Units<Sum>::limit;
    Sum units;
    if (!ok)
        units = Sum(std::copysign(Units<Sum>::limit, scaled));
    else if constexpr (sizeof(Sum) == sizeof(long long))
        units = Sum(std::llrint(scaled)); // one instruction, where nearbyint is a library call
    else
        units = Sum(std::nearbyint(scaled));
    return !__builtin_add_overflow(sum, units, &sum) && ok;
}

template <typename Sum> double value(Sum sum) { return double(sum) * Units<Sum>::unit; }

} // namespace caustica::fixed_point
