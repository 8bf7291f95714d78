// Progressive multi-jittered (0,2) sequences with blue-noise point choice ("pmj02bn"), the 2D
// point sets behind pbrt-v4's pmj02bn sampler (pmj02bn_sampler.h).
//
// Christensen, Kensler and Kilpatrick 2018, "Progressive Multi-Jittered Sample Sequences": the
// sequence doubles its count level by level, and every prefix of 2^k points is a (0,k,2)-net in
// base 2: each of the k+1 grids of 2^k equal rectangles of shape 2^-i x 2^-(k-i) holds one
// point. A level from n = 4^j to 2n points puts each new point in the sub-square diagonally
// opposite an old one's, in the grid of 4n squares; the level from 2n to 4n fills each quadrant's
// two remaining sub-squares, one of them (chosen at random) beside an old point and the other
// diagonally opposite it. Within its sub-square, a point may take any x stratum and any y stratum
// of width 1/N (N the level's count) whose rectangles are still empty in every grid that they
// determine; Pharr 2019 ("Efficient Generation of Points that Satisfy Two-Dimensional Elementary
// Intervals", JCGT 8(1)) shows that the valid positions are exactly the product of those x and y
// strata, found by descending the grids from the sub-square's. The "bn" is best-candidate choice
// (Mitchell 1991): of ten valid candidates, the one farthest from the points already placed
// (distance on the torus, since the sets are tiled across pixels). Once the sub-square is
// chosen, the (0,2) conditions leave a single x and a single y stratum, so the candidates
// differ only in where they lie within it, and the spread gained is small: the mean distance to
// the nearest neighbour of the first 1024 points is 0.65-0.69 grid spacings against 0.64-0.65
// with one candidate (docs/benchmarks.md).
//
// pbrt-v4 ships five such sets of 65536 points that Pixar generated; Caustica generates its own
// with the same construction, deterministically from a seed.
#pragma once

#include <cstdint>
#include <vector>

namespace caustica {

// A point of [0, 1)^2 in 32-bit fixed point (value / 2^32), so that every dyadic stratum a
// point was placed in is exact.
struct FixedPoint2 {
    uint32_t x, y;
};

// The first `count` points of the pmj02bn sequence drawn with `seed` (count at most 2^20).
std::vector<FixedPoint2> generate_pmj02bn(int count, uint64_t seed);

} // namespace caustica
