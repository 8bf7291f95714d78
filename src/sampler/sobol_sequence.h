// The Sobol sequence (Sobol' 1967, "On the distribution of points in a cube and the approximate
// evaluation of integrals") as a base-2 digital sequence: coordinate d of point i is the binary
// fraction C_d * digits(i) over GF(2), with one generator matrix C_d per dimension. Dimension
// 0's matrix is the identity (the van der Corput sequence) and dimension 1's is Pascal's
// triangle mod 2; together they form a (0,2)-sequence: every aligned block of 2^m consecutive
// points puts exactly one point in every elementary interval of area 2^-m. The others come
// from primitive polynomials and initial direction numbers chosen by Joe and Kuo (2008,
// "Constructing Sobol sequences with better two-dimensional projections") for good 2D
// projections.
#pragma once

#include <cstdint>

namespace caustica {

// Distinct dimensions with their own generator matrix (Joe and Kuo's first 64).
inline constexpr int SobolDimensionCount = 64;
// Columns per matrix: point indices up to 2^64 - 1.
inline constexpr int SobolColumnCount = 64;

// A primitive polynomial x^s + a_1 x^(s-1) + ... + a_(s-1) x + 1 over GF(2), with a the
// binary number a_1...a_(s-1), and the initial direction numbers m_1..m_s (m_k odd, < 2^k).
struct SobolDirectionNumbers {
    int dimension;  // Joe and Kuo's numbering: 2 is our dimension 1
    int degree;
    uint32_t a;
    uint32_t m[9];
};
extern const SobolDirectionNumbers JoeKuoDirectionNumbers[SobolDimensionCount - 1];

// Column c of dimension d's generator matrix as a 32-bit binary fraction (bit 31 holds the
// first digit): the contribution of bit c of the point index. 0 <= d < SobolDimensionCount.
uint32_t sobol_generator_column(int dimension, int column);

// Coordinate `dimension` of point `index`, unrandomised, as a 32-bit binary fraction.
uint32_t sobol_bits(uint64_t index, int dimension);

// sobol_bits(index, 1) without the table, in a few word operations (the samplers' hot path).
uint32_t sobol_second_dimension(uint64_t index);

} // namespace caustica
