#include "lights/equal_area_mapping.h"

#include "core/rng.h"
#include "core/sampling.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

TEST(EqualAreaMapping, LayoutMatchesPbrtV4) {
    // pbrt-v4 environment maps depend on where the axes land in the square.
    auto expect_dir = [](Vec2f uv, Vec3f d) {
        Vec3f w = equal_area_square_to_sphere(uv);
        EXPECT_NEAR(w.x, d.x, 1e-6f);
        EXPECT_NEAR(w.y, d.y, 1e-6f);
        EXPECT_NEAR(w.z, d.z, 1e-6f);
    };
    expect_dir({0.5f, 0.5f}, {0, 0, 1});
    expect_dir({1.0f, 0.5f}, {1, 0, 0});
    expect_dir({0.0f, 0.5f}, {-1, 0, 0});
    expect_dir({0.5f, 1.0f}, {0, 1, 0});
    expect_dir({0.5f, 0.0f}, {0, -1, 0});
    for (Vec2f corner : {Vec2f{0, 0}, Vec2f{1, 0}, Vec2f{0, 1}, Vec2f{1, 1}})
        expect_dir(corner, {0, 0, -1});
}

TEST(EqualAreaMapping, RoundTripsAndGivesUnitVectors) {
    Rng rng(1, 7);
    for (int i = 0; i < 100000; ++i) {
        Vec2f uv = rng.uniform2();
        Vec3f w = equal_area_square_to_sphere(uv);
        EXPECT_NEAR(length(w), 1.f, 1e-5f);
        Vec2f back = equal_area_sphere_to_square(w);
        // Float round-off through sqrt(1 - |z|) near the poles stays well under 1e-3 texels of a
        // 1k map.
        ASSERT_NEAR(back.x, uv.x, 2e-4f) << uv.x << " " << uv.y;
        ASSERT_NEAR(back.y, uv.y, 2e-4f) << uv.x << " " << uv.y;
    }
    Rng rng2(2, 7);
    for (int i = 0; i < 100000; ++i) {
        Vec3f w = sample_uniform_sphere(rng2.uniform2());
        Vec3f back = equal_area_square_to_sphere(equal_area_sphere_to_square(w));
        ASSERT_NEAR(distance(back, w), 0.f, 5e-4f);
    }
}

// The mapping preserves area: its Jacobian |dw/du x dw/dv| is 4 pi everywhere (central
// differences at interior points away from the creases u' = 0, v' = 0 and |u'| + |v'| = 1, in
// double-spaced steps so float round-off stays below 0.5%).
TEST(EqualAreaMapping, JacobianIsFourPi) {
    const float h = 1e-3f;
    int checked = 0;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            Vec2f p{(i + 0.5f) / 40, (j + 0.5f) / 40};
            float up = 2 * p.x - 1, vp = 2 * p.y - 1;
            if (std::abs(up) < 4 * h || std::abs(vp) < 4 * h ||
                std::abs(std::abs(up) + std::abs(vp) - 1) < 8 * h)
                continue;
            Vec3f du = (equal_area_square_to_sphere({p.x + h, p.y}) -
                        equal_area_square_to_sphere({p.x - h, p.y})) /
                       (2 * h);
            Vec3f dv = (equal_area_square_to_sphere({p.x, p.y + h}) -
                        equal_area_square_to_sphere({p.x, p.y - h})) /
                       (2 * h);
            EXPECT_NEAR(length(cross(du, dv)), 4 * Pi, 0.02f * 4 * Pi) << p.x << " " << p.y;
            ++checked;
        }
    EXPECT_GT(checked, 1000);
}

// Uniform points in the square must be uniform on the sphere: the fraction above height z0 is
// (1 - z0) / 2 and each octant holds 1/8. With N = 10^6 the binomial standard deviation is at
// most 5e-4; the bound is 6 sigma.
TEST(EqualAreaMapping, UniformSquareGivesUniformSphere) {
    const int n = 1000000;
    Rng rng(3, 11);
    int above[3] = {0, 0, 0};
    const float z0[3] = {-0.5f, 0.2f, 0.9f};
    int octant[8] = {};
    for (int i = 0; i < n; ++i) {
        Vec3f w = equal_area_square_to_sphere(rng.uniform2());
        for (int k = 0; k < 3; ++k) above[k] += w.z > z0[k];
        octant[(w.x > 0) + 2 * (w.y > 0) + 4 * (w.z > 0)]++;
    }
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(double(above[k]) / n, (1 - z0[k]) / 2, 3e-3);
    for (int k = 0; k < 8; ++k) EXPECT_NEAR(double(octant[k]) / n, 0.125, 3e-3);
}

}  // namespace
}  // namespace caustica
