// next_float_up and next_float_down against the library's std::nextafter, which they replace on
// the ray-spawning path: they must agree on every kind of float.
#include "core/next_float.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using namespace caustica;

namespace {

bool same_bits(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); }

} // namespace

TEST(NextFloat, AgreesWithNextafterOnEveryKindOfFloat) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    std::vector<float> values = {0.f,
                                 -0.f,
                                 1.f,
                                 -1.f,
                                 std::numeric_limits<float>::denorm_min(),
                                 -std::numeric_limits<float>::denorm_min(),
                                 std::numeric_limits<float>::min(),
                                 -std::numeric_limits<float>::min(),
                                 std::numeric_limits<float>::max(),
                                 -std::numeric_limits<float>::max(),
                                 inf,
                                 -inf,
                                 0x1p-16f,
                                 1e-4f};
    std::mt19937 rng(7);
    for (int i = 0; i < 100000; ++i) {
        const float v = std::bit_cast<float>(uint32_t(rng()));
        if (!std::isnan(v)) values.push_back(v);
    }
    for (float v : values) {
        EXPECT_TRUE(same_bits(next_float_up(v), std::nextafter(v, inf))) << v;
        EXPECT_TRUE(same_bits(next_float_down(v), std::nextafter(v, -inf))) << v;
    }
    EXPECT_TRUE(std::isnan(next_float_up(std::numeric_limits<float>::quiet_NaN())));
    EXPECT_TRUE(std::isnan(next_float_down(std::numeric_limits<float>::quiet_NaN())));
}
