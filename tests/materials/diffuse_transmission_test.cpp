// pbrt-v4's "diffusetransmission": Lambertian reflection R / pi on wo's side and transmission
// T / pi on the other, sampled in proportion to the larger lane of each.
#include "param_helpers.h"

#include "core/rng.h"
#include "geometry/interaction.h"
#include "materials/diffuse_transmission_bxdf.h"
#include "materials/material_factory.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {

using namespace caustica::testing;

Vec3f random_direction(Rng &rng) {
    Vec2f u = rng.uniform2();
    float z = 1 - 2 * u.x, r = safe_sqrt(1 - z * z), phi = 2 * Pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

TEST(DiffuseTransmission, ValuesDensitiesAndSamplesAgree) {
    const SampledSpectrum r(0.6f, 0.5f, 0.4f, 0.3f), t(0.2f, 0.3f, 0.1f, 0.35f);
    DiffuseTransmissionBxDF b(r, t);
    Rng rng(4, 4);
    double total_pdf = 0;
    const int n = 200000;
    SampledSpectrum albedo;
    const Vec3f wo = normalize(Vec3f(0.3f, -0.2f, -0.8f));  // from below: the lobes swap sides
    for (int i = 0; i < n; ++i) {
        // Exact, so reciprocal and mode-independent to rounding.
        const Vec3f a = random_direction(rng), c = random_direction(rng);
        EXPECT_EQ(b.f(a, c, TransportMode::Radiance), b.f(c, a, TransportMode::Importance));
        // The density integrates to 1 over the sphere (uniform-sphere quadrature, 4 pi p).
        total_pdf += 4 * Pi * b.pdf(wo, a, TransportMode::Radiance) / n;
        std::optional<BSDFSample> s = b.sample_f(wo, rng.uniform(), rng.uniform2(), TransportMode::Radiance);
        ASSERT_TRUE(s);
        EXPECT_NEAR(s->pdf, b.pdf(wo, s->wi, TransportMode::Radiance), 1e-5f);
        EXPECT_EQ(s->is_transmission(), !same_hemisphere(wo, s->wi));
        albedo += s->f * (std::abs(s->wi.z) / s->pdf / n);
    }
    // The standard error of the uniform quadrature is below 0.3% here; 1% is over 3 of them,
    // and a 3% error fails.
    EXPECT_NEAR(total_pdf, 1, 0.01);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_NEAR(albedo[i], r[i] + t[i], 0.01f * (r[i] + t[i]));
    EXPECT_EQ(b.flags(), BxDFDiffuseReflection | BxDFDiffuseTransmission);
    EXPECT_FALSE(b.sample_f(wo, 0.5f, {0.5f, 0.5f}, TransportMode::Radiance, SampleFlags::Reflection)
                     ->is_transmission());
}

TEST(DiffuseTransmission, MaterialDefaultsAndScale) {
    set_warnings_enabled(false);
    NamedTextures textures;
    ScratchBuffer scratch;
    SurfaceInteraction si;
    si.n = si.shading.n = {0, 0, 1};
    si.dpdu = si.shading.dpdu = {1, 0, 0};
    const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f);
    ParameterDictionary defaults = dictionary({});
    MaterialPtr m = create_material("diffusetransmission", defaults, textures, directive_location());
    BSDF bsdf = m->get_bsdf(si, lambda, scratch);
    EXPECT_NEAR(bsdf.f({0, 0, 1}, {0, 0, 1})[0], 0.25f * InvPi, 1e-6f);
    EXPECT_NEAR(bsdf.f({0, 0, 1}, {0, 0, -1})[0], 0.25f * InvPi, 1e-6f);
    ParameterDictionary scaled = dictionary({numbers("float", "scale", {2}, 2), numbers("rgb", "transmittance", {0.7, 0.7, 0.7}, 3)});
    m = create_material("diffusetransmission", scaled, textures, directive_location());
    bsdf = m->get_bsdf(si, lambda, scratch);
    EXPECT_NEAR(bsdf.f({0, 0, 1}, {0, 0, 1})[0], 0.5f * InvPi, 1e-6f);
    EXPECT_NEAR(bsdf.f({0, 0, 1}, {0, 0, -1})[0], InvPi, 1e-3f);  // 2 x 0.7 clamped to 1
    ParameterDictionary bad = dictionary({numbers("float", "scale", {-1}, 4)});
    EXPECT_EQ(input_error_line([&] { create_material("diffusetransmission", bad, textures, directive_location()); }), 4);
    set_warnings_enabled(true);
}

} // namespace
} // namespace caustica
