#include "sampler/sobol_sequence.h"

#include "sampler/randomization.h"

#include <array>
#include <bit>

namespace caustica {

// Transcribed from Joe and Kuo's direction number file joe-kuo-6.10200 (its first rows equal
// those of new-joe-kuo-6.21201), https://web.maths.unsw.edu.au/~fkuo/sobol/: columns d, s, a
// and m_1..m_s.
constexpr SobolDirectionNumbers JoeKuoDirectionNumbers[SobolDimensionCount - 1] = {
    {2, 1, 0, {1}},
    {3, 2, 1, {1, 3}},
    {4, 3, 1, {1, 3, 1}},
    {5, 3, 2, {1, 1, 1}},
    {6, 4, 1, {1, 1, 3, 3}},
    {7, 4, 4, {1, 3, 5, 13}},
    {8, 5, 2, {1, 1, 5, 5, 17}},
    {9, 5, 4, {1, 1, 5, 5, 5}},
    {10, 5, 7, {1, 1, 7, 11, 19}},
    {11, 5, 11, {1, 1, 5, 1, 1}},
    {12, 5, 13, {1, 1, 1, 3, 11}},
    {13, 5, 14, {1, 3, 5, 5, 31}},
    {14, 6, 1, {1, 3, 3, 9, 7, 49}},
    {15, 6, 13, {1, 1, 1, 15, 21, 21}},
    {16, 6, 16, {1, 3, 1, 13, 27, 49}},
    {17, 6, 19, {1, 1, 1, 15, 7, 5}},
    {18, 6, 22, {1, 3, 1, 15, 13, 25}},
    {19, 6, 25, {1, 1, 5, 5, 19, 61}},
    {20, 7, 1, {1, 3, 7, 11, 23, 15, 103}},
    {21, 7, 4, {1, 3, 7, 13, 13, 15, 69}},
    {22, 7, 7, {1, 1, 3, 13, 7, 35, 63}},
    {23, 7, 8, {1, 3, 5, 9, 1, 25, 53}},
    {24, 7, 14, {1, 3, 1, 13, 9, 35, 107}},
    {25, 7, 19, {1, 3, 1, 5, 27, 61, 31}},
    {26, 7, 21, {1, 1, 5, 11, 19, 41, 61}},
    {27, 7, 28, {1, 3, 5, 3, 3, 13, 69}},
    {28, 7, 31, {1, 1, 7, 13, 1, 19, 1}},
    {29, 7, 32, {1, 3, 7, 5, 13, 19, 59}},
    {30, 7, 37, {1, 1, 3, 9, 25, 29, 41}},
    {31, 7, 41, {1, 3, 5, 13, 23, 1, 55}},
    {32, 7, 42, {1, 3, 7, 3, 13, 59, 17}},
    {33, 7, 50, {1, 3, 1, 3, 5, 53, 69}},
    {34, 7, 55, {1, 1, 5, 5, 23, 33, 13}},
    {35, 7, 56, {1, 1, 7, 7, 1, 61, 123}},
    {36, 7, 59, {1, 1, 7, 9, 13, 61, 49}},
    {37, 7, 62, {1, 3, 3, 5, 3, 55, 33}},
    {38, 8, 14, {1, 3, 1, 15, 31, 13, 49, 245}},
    {39, 8, 21, {1, 3, 5, 15, 31, 59, 63, 97}},
    {40, 8, 22, {1, 3, 1, 11, 11, 11, 77, 249}},
    {41, 8, 38, {1, 3, 1, 11, 27, 43, 71, 9}},
    {42, 8, 47, {1, 1, 7, 15, 21, 11, 81, 45}},
    {43, 8, 49, {1, 3, 7, 3, 25, 31, 65, 79}},
    {44, 8, 50, {1, 3, 1, 1, 19, 11, 3, 205}},
    {45, 8, 52, {1, 1, 5, 9, 19, 21, 29, 157}},
    {46, 8, 56, {1, 3, 7, 11, 1, 33, 89, 185}},
    {47, 8, 67, {1, 3, 3, 3, 15, 9, 79, 71}},
    {48, 8, 70, {1, 3, 7, 11, 15, 39, 119, 27}},
    {49, 8, 84, {1, 1, 3, 1, 11, 31, 97, 225}},
    {50, 8, 97, {1, 1, 1, 3, 23, 43, 57, 177}},
    {51, 8, 103, {1, 3, 7, 7, 17, 17, 37, 71}},
    {52, 8, 115, {1, 3, 1, 5, 27, 63, 123, 213}},
    {53, 8, 122, {1, 1, 3, 5, 11, 43, 53, 133}},
    {54, 9, 8, {1, 3, 5, 5, 29, 17, 47, 173, 479}},
    {55, 9, 13, {1, 3, 3, 11, 3, 1, 109, 9, 69}},
    {56, 9, 16, {1, 1, 1, 5, 17, 39, 23, 5, 343}},
    {57, 9, 22, {1, 3, 1, 5, 25, 15, 31, 103, 499}},
    {58, 9, 25, {1, 1, 1, 11, 11, 17, 63, 105, 183}},
    {59, 9, 44, {1, 1, 5, 11, 9, 29, 97, 231, 363}},
    {60, 9, 47, {1, 1, 5, 15, 19, 45, 41, 7, 383}},
    {61, 9, 52, {1, 3, 7, 7, 31, 19, 83, 137, 221}},
    {62, 9, 55, {1, 1, 1, 3, 23, 15, 111, 223, 83}},
    {63, 9, 59, {1, 1, 5, 13, 31, 15, 55, 25, 161}},
    {64, 9, 62, {1, 1, 3, 13, 25, 47, 39, 87, 257}},
};

namespace {

using GeneratorMatrices = std::array<std::array<uint32_t, SobolColumnCount>, SobolDimensionCount>;

constexpr GeneratorMatrices make_generator_matrices() {
    GeneratorMatrices matrices{};
    // Dimension 0: column c is the single digit 2^-(c+1); digits beyond 32 fall below the
    // 32-bit fraction.
    for (int c = 0; c < 32; ++c) matrices[0][c] = uint32_t(1) << (31 - c);
    for (int d = 1; d < SobolDimensionCount; ++d) {
        const SobolDirectionNumbers &dn = JoeKuoDirectionNumbers[d - 1];
        const int s = dn.degree;
        // Sobol's recurrence (as in Bratley and Fox 1988, "Algorithm 659"): m_k = 2 a_1 m_(k-1)
        // ^ 4 a_2 m_(k-2) ^ ... ^ 2^(s-1) a_(s-1) m_(k-s+1) ^ 2^s m_(k-s) ^ m_(k-s). As
        // m_k < 2^k, every m_k up to k = 64 fits 64 bits.
        std::array<uint64_t, SobolColumnCount + 1> m{};  // m[k], k = 1..64
        for (int k = 1; k <= SobolColumnCount; ++k) {
            if (k <= s) {
                m[k] = dn.m[k - 1];
                continue;
            }
            uint64_t v = (m[k - s] << s) ^ m[k - s];
            for (int i = 1; i < s; ++i)
                if ((dn.a >> (s - 1 - i)) & 1) v ^= m[k - i] << i;
            m[k] = v;
        }
        // Direction number v_k = m_k / 2^k is column k-1; its first 32 binary digits.
        for (int k = 1; k <= SobolColumnCount; ++k)
            matrices[d][k - 1] = k <= 32 ? uint32_t(m[k] << (32 - k)) : uint32_t(m[k] >> (k - 32));
    }
    return matrices;
}

// Computed by the compiler: no start-up work and no initialisation guard on the sampling path.
constexpr GeneratorMatrices generator_matrices = make_generator_matrices();

} // namespace

uint32_t sobol_generator_column(int dimension, int column) {
    return generator_matrices[dimension][column];
}

uint32_t sobol_bits(uint64_t index, int dimension) {
    const std::array<uint32_t, SobolColumnCount> &columns = generator_matrices[dimension];
    uint32_t v = 0;
    while (index != 0) {
        int c = std::countr_zero(index);
        v ^= columns[c];
        index &= index - 1;
    }
    return v;
}

uint32_t sobol_second_dimension(uint64_t index) {
    // Entry (r, c) of Pascal's triangle mod 2 is 1 exactly when r's bits are a subset of c's
    // (Lucas's theorem), so digit r is the xor of the index bits at positions c that contain r:
    // a superset-xor transform over the six bits of a bit position, one step per bit. Step b
    // adds to every position with bit b clear the value at that position plus 2^b.
    uint64_t w = index;
    w ^= (w >> 1) & 0x5555555555555555ull;
    w ^= (w >> 2) & 0x3333333333333333ull;
    w ^= (w >> 4) & 0x0f0f0f0f0f0f0f0full;
    w ^= (w >> 8) & 0x00ff00ff00ff00ffull;
    w ^= (w >> 16) & 0x0000ffff0000ffffull;
    w ^= w >> 32;
    // Digit r, now bit r of w, is bit 31 - r of the fraction.
    return reverse_bits(uint32_t(w));
}

} // namespace caustica
