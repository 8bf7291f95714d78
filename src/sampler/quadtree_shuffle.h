// The random hierarchical ordering of pixels that zsobol and pmj02bn build their screen-space
// blue noise on (Ahmed and Wonka 2020, "Screen-space blue-noise diffusion of Monte Carlo
// sampling error via hierarchical ordering of pixels"): pixels numbered along a Morton (Z)
// curve, whose base-4 digits, one per quadtree level, are scrambled level by level.
#pragma once

#include <cstdint>

namespace caustica {

// Interleaves the bits of x (even positions) and y (odd positions): the Z-curve order.
uint32_t morton_code(uint16_t x, uint16_t y);

// Permutes the base-4 digits of `index` in bit positions [low, high), taken from the top (a
// last, single bit when high - low is odd), and returns them in place: a nested uniform
// scramble, in which each digit's permutation is one of the 24, chosen by a hash of `key` and
// of the digits above it. `marked` is the whole index with a 1 above its top bit.
uint64_t shuffle_digits(uint64_t index, uint64_t marked, int high, int low, uint64_t key);

} // namespace caustica
