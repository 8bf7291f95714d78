// The portal-masked environment light: light arrives only through the portal, next-event
// samples pass through it with the density pdf_li reports (which integrates to one over the
// portal's solid angle), emitted rays cross it with the densities pdf_le reports, and the
// portal must be a rectangle.
#include "lights/portal_infinite_light.h"

#include "core/rng.h"
#include "light_test_util.h"
#include "lights/light_factory.h"
#include "spectral/color_space.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

using namespace caustica::testing;

// A window in the plane z = 1, x in [-0.4, 0.4], y in [0.8, 1.6], seen from z < 1.
const std::array<Vec3f, 4> kPortal = {Vec3f{-0.4f, 0.8f, 1}, Vec3f{-0.4f, 1.6f, 1}, Vec3f{0.4f, 1.6f, 1},
                                      Vec3f{0.4f, 0.8f, 1}};

RGBImage sky(int n) {
    RGBImage im;
    im.width = im.height = n;
    im.pixels.resize(size_t(n) * n * 3);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            float *p = im.at(x, y);
            p[0] = 0.2f + float(x) / n, p[1] = 0.3f + float(y) / n, p[2] = 0.5f;
            if (x == n / 2 && y == 2 * n / 3) p[0] = p[1] = p[2] = 40;
        }
    return im;
}

PortalInfiniteLight make_light() {
    PortalInfiniteLight light(Transform(), sky(16), RGBColorSpace::srgb(), 1, kPortal);
    light.preprocess(Bounds3f{{-1, 0, -1}, {1, 2, 1}});
    return light;
}

// Where the line from p along w meets the portal's plane, and whether inside the rectangle.
bool through_portal(Vec3f p, Vec3f w) {
    if (!(w.z > 0)) return false;
    const Vec3f q = p + w * ((1 - p.z) / w.z);
    return q.x >= -0.4f && q.x <= 0.4f && q.y >= 0.8f && q.y <= 1.6f;
}

const SampledWavelengths kLambda = SampledWavelengths::fixed(550);

TEST(PortalInfiniteLight, LightArrivesOnlyThroughThePortal) {
    const PortalInfiniteLight light = make_light();
    Rng rng(3, 4);
    int through = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3f p{-0.9f + 1.8f * rng.uniform(), 0.1f + 1.8f * rng.uniform(), -0.9f + 1.8f * rng.uniform()};
        const Vec3f w = sample_uniform_sphere(rng.uniform2());
        const bool lit = light.Le(Ray{p, w}, kLambda)[0] > 0;
        EXPECT_EQ(lit, through_portal(p, w)) << p.x << " " << p.y << " " << p.z;
        through += lit;
    }
    EXPECT_GT(through, 100);
    // Behind the portal (outside the room) nothing arrives through it.
    EXPECT_FALSE(light.window_from({0, 1.2f, 1.5f}));
}

TEST(PortalInfiniteLight, NextEventSamplesPassThroughThePortalWithTheirDensity) {
    const PortalInfiniteLight light = make_light();
    Rng rng(5, 6);
    for (Vec3f p : {Vec3f{0, 1, 0}, Vec3f{0.8f, 0.2f, 0.7f}, Vec3f{-0.9f, 1.9f, -0.9f}}) {
        const LightSampleContext ctx{p, {0, 1, 0}, {0, 1, 0}};
        for (int i = 0; i < 2000; ++i) {
            std::optional<LightLiSample> s = light.sample_li(ctx, rng.uniform2(), kLambda);
            ASSERT_TRUE(s);
            EXPECT_TRUE(through_portal(p, s->wi));
            EXPECT_NEAR(s->pdf, light.pdf_li(ctx, s->wi), 1e-3f * s->pdf);
            EXPECT_NEAR(s->L[0], light.Le(Ray{p, s->wi}, kLambda)[0], 1e-5f * s->L[0]);
        }
        // pdf_li integrates to one over the directions through the portal: uniform points q on
        // the portal give directions of solid-angle density dist^2 / (area cos), so the mean of
        // pdf_li(w) area cos / dist^2 is the integral.
        double sum = 0;
        const int n = 40000;
        for (int i = 0; i < n; ++i) {
            const Vec2f u = rng.uniform2();
            const Vec3f q{-0.4f + 0.8f * u.x, 0.8f + 0.8f * u.y, 1};
            const Vec3f d = q - p;
            const float dist2 = length_squared(d);
            const Vec3f w = normalize(d);
            sum += light.pdf_li(ctx, w) * 0.64 * w.z / dist2;
        }
        EXPECT_NEAR(sum / n, 1, 0.02) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(PortalInfiniteLight, EmittedRaysCrossThePortalWithTheirDensities) {
    const PortalInfiniteLight light = make_light();
    Rng rng(7, 8);
    for (int i = 0; i < 2000; ++i) {
        std::optional<LightLeSample> s = light.sample_le(rng.uniform2(), rng.uniform2(), kLambda);
        ASSERT_TRUE(s);
        // The ray comes from outside through the rectangle, into the room.
        EXPECT_LT(s->ray.d.z, 0);
        const Vec3f q = s->ray.o + s->ray.d * ((1 - s->ray.o.z) / s->ray.d.z);
        EXPECT_NEAR(q.x, std::clamp(q.x, -0.4f, 0.4f), 1e-4f);
        EXPECT_NEAR(q.y, std::clamp(q.y, 0.8f, 1.6f), 1e-4f);
        float pdf_pos, pdf_dir;
        light.pdf_le(s->ray, {}, &pdf_pos, &pdf_dir);
        EXPECT_NEAR(pdf_pos, s->pdf_pos, 1e-4f * pdf_pos);
        // (Float rounding of the parameterisation near grazing directions, at the image's edge
        // where the solid angle per uv vanishes, is a few parts in a thousand.)
        EXPECT_NEAR(pdf_dir, s->pdf_dir, 2e-2f * pdf_dir);
        // The radiance carried is what a point in the room sees back along the ray.
        const Vec3f inside = q + s->ray.d * 0.3f;
        EXPECT_NEAR(s->L[0], light.Le(Ray{inside, -s->ray.d}, kLambda)[0], 1e-5f * s->L[0]);
    }
}

TEST(PortalInfiniteLight, FactoryReadsAndChecksThePortal) {
    set_warnings_enabled(false);
    const LightPtr uniform = create_light(
        "infinite", Transform(),
        dictionary({numbers("rgb", "L", {0.5, 0.5, 0.5}),
                    numbers("point3", "portal", {-0.4, 0.8, 1, -0.4, 1.6, 1, 0.4, 1.6, 1, 0.4, 0.8, 1})}),
        {"test.pbrt", 1, 1});
    ASSERT_TRUE(dynamic_cast<const PortalInfiniteLight *>(uniform.get()));
    EXPECT_THROW(create_light("infinite", Transform(),
                              dictionary({numbers("point3", "portal", {-0.4, 0.8, 1, -0.4, 1.6, 1, 0.4, 1.6, 1})}),
                              {"test.pbrt", 1, 1}),
                 InputError);
    try {
        create_light("infinite", Transform(),
                     dictionary({numbers("point3", "portal", {-0.4, 0.8, 1, -0.4, 1.6, 1, 0.5, 1.6, 1, 0.4, 0.8, 1})}),
                     {"test.pbrt", 1, 1});
        ADD_FAILURE() << "a trapezoid was accepted";
    } catch (const InputError &e) {
        EXPECT_NE(std::string(e.what()).find("test.pbrt:7:6: error: the portal is not a planar rectangle"),
                  std::string::npos)
            << e.what();
    }
    set_warnings_enabled(true);
}

}  // namespace
}  // namespace caustica
