#include "sampler/randomization.h"
#include "sampler/sobol_sequence.h"

#include <gtest/gtest.h>

#include <vector>

using namespace caustica;

namespace {

// Multiplies by x modulo the polynomial (bit i = coefficient of x^i) over GF(2).
uint32_t times_x(uint32_t v, uint32_t polynomial, int degree) {
    v <<= 1;
    if ((v >> degree) & 1) v ^= polynomial;
    return v;
}

// True when the points' (x, y) digits put exactly one point in every elementary interval
// [i 2^-a, (i+1) 2^-a) x [j 2^-b, (j+1) 2^-b), a + b = m, for every a: a (0,m,2)-net.
bool is_02_net(const std::vector<uint32_t> &x, const std::vector<uint32_t> &y, int m) {
    if (x.size() != (size_t(1) << m)) return false;
    for (int a = 0; a <= m; ++a) {
        const int b = m - a;
        std::vector<int> count(size_t(1) << m, 0);
        for (size_t i = 0; i < x.size(); ++i) {
            uint32_t cx = a == 0 ? 0 : x[i] >> (32 - a), cy = b == 0 ? 0 : y[i] >> (32 - b);
            if (++count[(size_t(cx) << b) | cy] > 1) return false;
        }
    }
    return true;
}

} // namespace

TEST(SobolSequence, DirectionNumberTableIsWellFormed) {
    // Checks that catch transcription errors: rows numbered 2, 3, ...; polynomials sorted by
    // (degree, a), hence distinct, each primitive over GF(2) (x has order 2^s - 1 modulo it);
    // initial direction numbers odd and m_k < 2^k.
    int previous_degree = 0;
    uint32_t previous_a = 0;
    for (int d = 1; d < SobolDimensionCount; ++d) {
        const SobolDirectionNumbers &dn = JoeKuoDirectionNumbers[d - 1];
        EXPECT_EQ(dn.dimension, d + 1);
        const int s = dn.degree;
        ASSERT_GE(s, 1);
        ASSERT_LE(s, 9);
        EXPECT_TRUE(s > previous_degree || (s == previous_degree && dn.a > previous_a)) << d;
        previous_degree = s;
        previous_a = dn.a;
        EXPECT_LT(dn.a, 1u << (s - 1)) << d;
        const uint32_t polynomial = (1u << s) | (dn.a << 1) | 1u;
        uint32_t power = 1;
        int order = 0;
        do {
            power = times_x(power, polynomial, s);
            ++order;
        } while (power != 1 && order < (1 << s));
        EXPECT_EQ(order, (1 << s) - 1) << "dimension " << d;
        for (int k = 1; k <= s; ++k) {
            EXPECT_EQ(dn.m[k - 1] % 2, 1u) << d;
            EXPECT_LT(dn.m[k - 1], 1u << k) << d;
        }
        for (int k = s; k < 9; ++k) EXPECT_EQ(dn.m[k], 0u) << d;
    }
}

TEST(SobolSequence, FirstDimensionIsVanDerCorput) {
    for (uint64_t i : {0ull, 1ull, 2ull, 3ull, 12345ull, 0xfffffffeull, (1ull << 40) + 77})
        EXPECT_EQ(sobol_bits(i, 0), reverse_bits(uint32_t(i)));
}

TEST(SobolSequence, SecondDimensionIsPascalsTriangleModTwo) {
    // Polynomial x + 1 with m_1 = 1 gives m_k = (2 m_(k-1)) xor m_(k-1): the matrix entry in
    // row r, column c is binomial(c, r) mod 2, which is 1 exactly when r's bits are a subset
    // of c's (Lucas's theorem).
    for (int c = 0; c < SobolColumnCount; ++c) {
        uint32_t expected = 0;
        for (int r = 0; r < 32; ++r)
            if ((r & c) == r) expected |= 1u << (31 - r);
        EXPECT_EQ(sobol_generator_column(1, c), expected) << c;
    }
}

TEST(SobolSequence, TableFreeSecondDimensionMatchesTheMatrix) {
    uint64_t index = 0x9e3779b97f4a7c15ull;
    for (int t = 0; t < 2000; ++t) {
        index = index * 6364136223846793005ull + 1442695040888963407ull;
        for (uint64_t i : {index, index >> 20, index >> 40, uint64_t(t)})
            ASSERT_EQ(sobol_second_dimension(i), sobol_bits(i, 1)) << i;
    }
}

TEST(SobolSequence, RecurrenceByHand) {
    // Dimension 2: x^2 + x + 1 (a = 1), m_1 = 1, m_2 = 3, so m_3 = 2 m_2 ^ 4 m_1 ^ m_1 = 3 and
    // m_4 = 2 m_3 ^ 4 m_2 ^ m_2 = 6 ^ 12 ^ 3 = 9: directions 1/2, 3/4, 3/8, 9/16.
    EXPECT_EQ(sobol_generator_column(2, 0), 0x80000000u);
    EXPECT_EQ(sobol_generator_column(2, 1), 0xc0000000u);
    EXPECT_EQ(sobol_generator_column(2, 2), 0x60000000u);
    EXPECT_EQ(sobol_generator_column(2, 3), 0x90000000u);
    // Points are xors of the columns of their set index bits.
    EXPECT_EQ(sobol_bits(0b1011, 2), 0x80000000u ^ 0xc0000000u ^ 0x90000000u);
}

TEST(SobolSequence, FirstTwoDimensionsAreA02Sequence) {
    // Every aligned block of 2^m points, including blocks far into the sequence where the
    // high columns matter, is a (0,m,2)-net.
    for (int m = 0; m <= 12; ++m)
        for (uint64_t block : {0ull, 1ull, 5ull, (1ull << 30) + 3, (1ull << 50) / (1ull << m)}) {
            std::vector<uint32_t> x, y;
            for (uint64_t i = 0; i < (1ull << m); ++i) {
                uint64_t index = (block << m) | i;
                x.push_back(sobol_bits(index, 0));
                y.push_back(sobol_bits(index, 1));
            }
            EXPECT_TRUE(is_02_net(x, y, m)) << "m=" << m << " block=" << block;
        }
}

TEST(SobolSequence, EveryDimensionStratifiesIn1D) {
    // Each generator matrix is upper triangular with a unit diagonal (m_k odd), so every
    // aligned block of 2^m points has one point in each interval of length 2^-m.
    for (int d = 0; d < SobolDimensionCount; ++d)
        for (int m : {1, 5, 10})
            for (uint64_t block : {0ull, 3ull, 1ull << 40}) {
                std::vector<int> count(size_t(1) << m, 0);
                for (uint64_t i = 0; i < (1ull << m); ++i)
                    ++count[sobol_bits((block << m) | i, d) >> (32 - m)];
                for (int c : count) ASSERT_EQ(c, 1) << "dimension " << d << " m=" << m;
            }
}

TEST(SobolSequence, TabulatedPairsAreWellDistributed) {
    // Joe and Kuo chose their numbers for good 2D projections. A loose, independent check of
    // the transcription: the first 2^10 points of every pair of the first 16 dimensions are a
    // (t,10,2)-net with t <= 5 (exactly 2^t points in each elementary interval of area
    // 2^(t-10)), far from the t = 10 of a degenerate pair, which a typo in m_k tends to cause.
    const int m = 10, t = 5;
    for (int d1 = 0; d1 < 16; ++d1)
        for (int d2 = d1 + 1; d2 < 16; ++d2)
            for (int a = 0; a <= m - t; ++a) {
                const int b = m - t - a;
                std::vector<int> count(size_t(1) << (m - t), 0);
                for (uint64_t i = 0; i < (1u << m); ++i) {
                    uint32_t cx = a == 0 ? 0 : sobol_bits(i, d1) >> (32 - a);
                    uint32_t cy = b == 0 ? 0 : sobol_bits(i, d2) >> (32 - b);
                    ++count[(size_t(cx) << b) | cy];
                }
                for (int c : count) ASSERT_EQ(c, 1 << t) << d1 << " " << d2 << " a=" << a;
            }
}
