// Round trips through both octahedral encodings stay within their stated angular error, on
// random directions of the whole sphere and on the map's seams (the equator, where the lower
// half is folded over, and the axes).
#include "core/octahedral.h"
#include "core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace caustica {
namespace {

// The angle between two unit vectors, in double and through atan2, so that the float rounding of
// a dot product near 1 (about 3e-4 radians) does not hide the encoding's own error.
double angle_between(Vec3f a, Vec3f b) {
    const double cx = double(a.y) * b.z - double(a.z) * b.y, cy = double(a.z) * b.x - double(a.x) * b.z,
                 cz = double(a.x) * b.y - double(a.y) * b.x;
    const double d = double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z;
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), d);
}

std::vector<Vec3f> test_directions() {
    std::vector<Vec3f> directions;
    Rng rng(5, 6);
    for (int i = 0; i < 200000; ++i) {
        const float z = 1 - 2 * rng.uniform(), r = std::sqrt(std::max(0.f, 1 - z * z)), phi = 2 * Pi * rng.uniform();
        directions.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    for (int i = 0; i < 1000; ++i) {
        const float phi = 2 * Pi * float(i) / 1000;
        directions.push_back({std::cos(phi), std::sin(phi), 0});
        directions.push_back(normalize(Vec3f(std::cos(phi), std::sin(phi), -1e-4f)));
    }
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.f, 1.f}) {
            Vec3f v;
            v[axis] = sign;
            directions.push_back(v);
        }
    return directions;
}

// Bounds: the measured worst cases over these directions are 6.4e-5 and 0.0165 radians (a
// quantisation step of the folded square, 2 / (2^bits - 1), stretched by the map); the bounds
// leave a margin above them. A wrong fold of the lower half would put directions off by
// radians.
TEST(Octahedral, FineEncodingIsWithinATenThousandthOfARadian) {
    double worst = 0;
    for (Vec3f v : test_directions()) worst = std::max(worst, angle_between(v, decode_octahedral(encode_octahedral(v))));
    EXPECT_LT(worst, 1e-4);
    EXPECT_GT(worst, 1e-5); // the encoding is lossy: a test that finds no error measures nothing
}

TEST(Octahedral, CoarseEncodingIsWithinADegree) {
    double worst = 0;
    for (Vec3f v : test_directions())
        worst = std::max(worst, angle_between(v, decode_octahedral_coarse(encode_octahedral_coarse(v))));
    EXPECT_LT(worst, 0.02);
    EXPECT_GT(worst, 0.005);
}

} // namespace
} // namespace caustica
