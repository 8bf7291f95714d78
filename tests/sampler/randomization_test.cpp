#include "core/rng.h"
#include "sampler/randomization.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>

using namespace caustica;

namespace {

constexpr Randomization AllRandomizations[] = {Randomization::None, Randomization::PermuteDigits,
                                               Randomization::FastOwen, Randomization::Owen};

// Flip of digit k (0 = most significant) that a scramble applied to v.
int flip(uint32_t v, uint32_t scrambled, int k) { return int(((v ^ scrambled) >> (31 - k)) & 1); }

} // namespace

TEST(Randomization, ParsesPbrtNames) {
    EXPECT_EQ(parse_randomization("none"), Randomization::None);
    EXPECT_EQ(parse_randomization("permutedigits"), Randomization::PermuteDigits);
    EXPECT_EQ(parse_randomization("fastowen"), Randomization::FastOwen);
    EXPECT_EQ(parse_randomization("owen"), Randomization::Owen);
    EXPECT_FALSE(parse_randomization("Owen").has_value());
    EXPECT_FALSE(parse_randomization("").has_value());
}

TEST(Randomization, ReverseBitsMatchesDigitByDigitReversal) {
    Rng rng(3, 4);
    for (int t = 0; t < 1000; ++t) {
        uint32_t v = rng.next_uint32(), expected = 0;
        for (int b = 0; b < 32; ++b) expected |= ((v >> b) & 1u) << (31 - b);
        EXPECT_EQ(reverse_bits(v), expected);
    }
}

TEST(Randomization, UnitFloatIsExactAndBelowOne) {
    EXPECT_EQ(bits_to_unit_float(0), 0.f);
    EXPECT_EQ(bits_to_unit_float(0x80000000u), 0.5f);
    EXPECT_LT(bits_to_unit_float(0xffffffffu), 1.f);
    // 0x7fffffff is below 1/2; a rounding conversion would give exactly 1/2 and leave the
    // interval [0, 1/2) the digits put it in.
    EXPECT_LT(bits_to_unit_float(0x7fffffffu), 0.5f);
}

TEST(Randomization, ScramblesKeepCommonLeadingDigits) {
    // The defining property of nested (and digit-wise) scrambling: two values sharing exactly
    // their first k digits map to values sharing exactly their first k digits. It maps every
    // elementary interval onto one of the same length, so nets stay nets, and makes the map a
    // bijection.
    Rng rng(7, 1);
    for (Randomization r : AllRandomizations)
        for (int t = 0; t < 20000; ++t) {
            uint32_t v = rng.next_uint32();
            int k = t % 32;
            uint32_t w = (v ^ (0x80000000u >> k)) ^ (rng.next_uint32() & (0x7fffffffu >> k));
            uint64_t seed = rng.next_uint32();
            uint32_t sv = randomize(v, r, seed), sw = randomize(w, r, seed);
            ASSERT_EQ(std::countl_zero(sv ^ sw), k) << int(r);
        }
}

TEST(Randomization, ScramblesFlipEveryDigitWithAFairCoin) {
    // For a fixed value, over seeds, every digit is flipped with probability 1/2 (Owen
    // scrambling: the first 24 digits, then none). With 20000 seeds the standard deviation of
    // a frequency is 0.0035; the bound is 6 of them.
    for (Randomization r : {Randomization::Owen, Randomization::FastOwen, Randomization::PermuteDigits}) {
        const int scrambled_digits = r == Randomization::Owen ? 24 : 32;
        for (uint32_t v : {0u, 0xffffffffu, 0x12345678u}) {
            int ones[32] = {};
            const int n = 20000;
            for (int s = 0; s < n; ++s) {
                uint32_t scrambled = randomize(v, r, uint64_t(s));
                for (int k = 0; k < 32; ++k) ones[k] += flip(v, scrambled, k);
            }
            for (int k = 0; k < scrambled_digits; ++k)
                EXPECT_NEAR(ones[k] / double(n), 0.5, 0.021) << int(r) << " " << k;
            for (int k = scrambled_digits; k < 32; ++k) EXPECT_EQ(ones[k], 0);
        }
    }
}

TEST(Randomization, OwenCoinsOfDifferentNodesAreIndependent) {
    // Values that part at digit k sit in different subtrees, so nested uniform scrambling
    // flips their later digits d > k by independent coins: the flips agree half the time.
    // (A digital shift flips both alike; the correlation is then 1.) 4000 seeds per (k, d):
    // the agreement correlation has standard deviation 0.016; the bound is 6.5 of them.
    Rng rng(11, 5);
    for (Randomization r : {Randomization::Owen, Randomization::FastOwen}) {
        for (int k = 0; k < 12; ++k)
            for (int d = k + 1; d < 24; d += 3) {
                double agreement = 0;
                const int n = 4000;
                for (int s = 0; s < n; ++s) {
                    uint32_t v = rng.next_uint32();
                    uint32_t w = (v ^ (0x80000000u >> k)) ^ (rng.next_uint32() & (0x7fffffffu >> k));
                    uint64_t seed = rng.next_uint32() | (uint64_t(s) << 32);
                    bool same = flip(v, randomize(v, r, seed), d) == flip(w, randomize(w, r, seed), d);
                    agreement += same ? 1 : -1;
                }
                EXPECT_NEAR(agreement / n, 0.0, 0.105) << int(r) << " k=" << k << " d=" << d;
            }
    }
    uint32_t v = 0x0f0f0f0fu, w = 0x8f0f0f0fu;
    for (uint64_t seed = 0; seed < 100; ++seed)
        EXPECT_EQ(flip(v, randomize(v, Randomization::PermuteDigits, seed), 10),
                  flip(w, randomize(w, Randomization::PermuteDigits, seed), 10));
}

TEST(Randomization, NoneIsTheIdentity) {
    for (uint32_t v : {0u, 1u, 0xdeadbeefu}) EXPECT_EQ(randomize(v, Randomization::None, 99), v);
}
