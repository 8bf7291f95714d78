// The Disney BSDF (Burley 2015; disney_bxdf.h) and the "disney" material: sampling against the
// pdf (chi-square), the weak white furnace of its microfacet lobes, energy bounds, the limits
// that must reduce to other models, reciprocity and the transport modes, and the parameters.
#include "chi_square.h"
#include "param_helpers.h"

#include "core/rng.h"
#include "geometry/interaction.h"
#include "materials/dielectric_bxdf.h"
#include "materials/disney_bxdf.h"
#include "materials/disney_material.h"
#include "materials/random_walk_albedo.h"
#include "materials/subsurface_coefficients.h"
#include "materials/fresnel.h"
#include "materials/material_factory.h"
#include "media/medium_interface.h"
#include "spectral/cie.h"
#include "spectral/color_space.h"
#include "spectral/ior.h"
#include "spectral/rgb_spectrum.h"
#include "textures/texture_factory.h"

#include <gtest/gtest.h>

#include <memory>
#include <sstream>
#include <vector>

namespace caustica {
namespace {

using testing::chi_square_test;
using testing::SphereChart;

Vec3f direction_at(float theta_degrees, float phi_degrees = 30) {
    float theta = radians(theta_degrees), phi = radians(phi_degrees);
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

Vec3f random_direction(Rng &rng) {
    Vec2f u = rng.uniform2();
    float z = 1 - 2 * u.x, r = safe_sqrt(1 - z * z), phi = 2 * Pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec3f mirror_z(Vec3f w) { return {w.x, w.y, -w.z}; }

void expect_relative(float a, float b, float tolerance, const std::string &what) {
    EXPECT_LE(std::abs(a - b), tolerance * std::max(std::abs(a), std::abs(b)) + 1e-7f)
        << what << ": " << a << " vs " << b;
}

// A named parameter set for the suites below.
struct Named {
    std::string name;
    DisneyParameters p;
};

DisneyParameters grey(float base) {
    DisneyParameters p;
    p.base_color = SampledSpectrum(base);
    p.base_luminance = base;
    return p;
}

// A coloured base (lanes differ) with its luminance given independently of the material code.
DisneyParameters coloured() {
    DisneyParameters p;
    p.base_color = SampledSpectrum(0.7f, 0.45f, 0.2f, 0.6f);
    p.base_luminance = 0.45f;
    return p;
}

// Parameter sets covering every lobe, both kinds of surface and both sides of eta = 1.
std::vector<Named> parameter_grid() {
    std::vector<Named> grid;
    auto add = [&](const std::string &name, DisneyParameters p) { grid.push_back({name, p}); };
    add("defaults", DisneyParameters());
    {
        DisneyParameters p = grey(0.8f);
        p.metallic = 1, p.roughness = 0.3f;
        add("metal", p);
    }
    {
        DisneyParameters p = coloured();
        p.metallic = 0.5f, p.roughness = 0.6f, p.anisotropic = 0.8f, p.specular_tint = 1;
        add("half metal anisotropic tinted", p);
    }
    {
        DisneyParameters p = grey(0.9f);
        p.spec_trans = 1, p.roughness = 0.5f;
        add("rough glass", p);
    }
    {
        DisneyParameters p = coloured();
        p.spec_trans = 0.5f, p.roughness = 0.4f, p.sheen = 1, p.sheen_tint = 1, p.eta = SampledSpectrum(1.33f);
        add("half glass with sheen", p);
    }
    {
        DisneyParameters p = grey(0.5f);
        p.spec_trans = 1, p.roughness = 0.35f, p.eta = SampledSpectrum(1 / 1.5f);
        add("glass eta < 1", p);
    }
    {
        DisneyParameters p = grey(0.6f);
        p.roughness = 0.7f, p.clearcoat = 1, p.clearcoat_gloss = 0.6f;
        add("clearcoat", p);
    }
    {
        DisneyParameters p = grey(0.6f);
        p.metallic = 0.3f, p.roughness = 0.5f, p.clearcoat = 1, p.clearcoat_gloss = 1;
        add("glossiest clearcoat", p);
    }
    for (float gloss : {0.f, 1.f}) {
        // Only the clearcoat reflects: black base, and eta 1 makes the specular lobe black.
        DisneyParameters p = grey(0);
        p.eta = SampledSpectrum(1), p.clearcoat = 1, p.clearcoat_gloss = gloss;
        add(gloss == 0 ? "clearcoat alone" : "glossiest clearcoat alone", p);
    }
    {
        DisneyParameters p = coloured();
        p.thin = true, p.spec_trans = 0.6f, p.diff_trans = 1, p.flatness = 0.5f, p.sheen = 0.5f;
        add("thin blend", p);
    }
    {
        DisneyParameters p = grey(0.9f);
        p.thin = true, p.spec_trans = 1, p.roughness = 0.8f, p.anisotropic = 0.5f;
        p.eta = SampledSpectrum(2), p.reference_eta = 2;
        add("thin rough glass", p);
    }
    {
        DisneyParameters p = grey(0.7f);
        p.thin = true, p.diff_trans = 2, p.roughness = 1, p.flatness = 1;
        add("thin all diffuse transmission", p);
    }
    {
        DisneyParameters p = coloured();
        p.roughness = 0.45f, p.specular_tint = 1, p.sheen = 1, p.sheen_tint = 1, p.eta = SampledSpectrum(0.8f);
        add("tints with eta < 1", p);
    }
    {
        DisneyParameters p = grey(0.5f);
        p.metallic = 0.2f, p.spec_trans = 0.7f, p.roughness = 1, p.anisotropic = 1, p.clearcoat = 0.5f,
        p.clearcoat_gloss = 0.3f;
        add("everything rough", p);
    }
    {
        DisneyParameters p = grey(0.8f);
        p.spec_trans = 1, p.roughness = 0.5f, p.eta = SampledSpectrum(1.50f, 1.52f, 1.54f, 1.56f);
        add("dispersive glass", p);
    }
    {
        DisneyParameters p = grey(0.7f);
        p.roughness = 0.5f, p.subsurface = true;
        add("subsurface", p);
    }
    {
        DisneyParameters p = coloured();
        p.roughness = 0.3f, p.spec_trans = 0.3f, p.sheen = 0.5f, p.clearcoat = 0.5f, p.clearcoat_gloss = 0.4f;
        p.subsurface = true;
        add("subsurface with glass, sheen and clearcoat", p);
    }
    return grid;
}

// ---------------------------------------------------------------------------------------------
// Sampling: chi-square goodness of fit of sample_f against pdf.

// Significance as in chi_square_test.cpp: the suite is one family of tests at level 1e-3 with
// Sidak-corrected per-case levels, so a correct implementation fails with probability 1e-3
// for a given seed, and the fixed seeds make the outcome reproducible.
TEST(DisneyBxDF, SamplingMatchesPdf) {
    struct Case {
        std::string name;
        std::shared_ptr<DisneyBxDF> bxdf;
        Vec3f wo;
        TransportMode mode;
        SampleFlags flags;
        SphereChart chart;
    };
    std::vector<Case> cases;
    int counter = 0;
    for (const Named &n : parameter_grid())
        for (float theta : {10.f, 60.f, 85.f, 140.f}) {
            // Sampling does not depend on the transport mode (SamplingIgnoresTransportMode), so
            // the cases alternate between them.
            TransportMode mode = counter++ % 2 ? TransportMode::Importance : TransportMode::Radiance;
            Vec3f wo = direction_at(theta);
            auto bxdf = std::make_shared<DisneyBxDF>(n.p);
            // A GTR1 lobe of alpha 0.001 is far narrower than a bin of the plain chart: centre
            // the chart on the mirror direction with bins shrinking towards it (the power 5 of
            // chi_square_test.cpp's lobe charts), which still covers the whole sphere.
            SphereChart chart;
            if (n.p.clearcoat > 0 && n.p.clearcoat_gloss > 0.9f) chart = {Vec3f(-wo.x, -wo.y, wo.z), 5};
            std::ostringstream name;
            name << n.name << " theta_o=" << theta << (mode == TransportMode::Radiance ? " radiance" : " importance");
            cases.push_back({name.str(), bxdf, wo, mode, SampleFlags::All, chart});
            // Restricted sampling on one case of each set that both reflects and transmits.
            if (theta == 60.f && (n.p.spec_trans > 0 || n.p.diff_trans > 0)) {
                cases.push_back({name.str() + " R", bxdf, wo, mode, SampleFlags::Reflection, chart});
                cases.push_back({name.str() + " T", bxdf, wo, mode, SampleFlags::Transmission, chart});
            }
        }
    constexpr double SuiteSignificance = 1e-3;
    constexpr int SampleCount = 30000;
    double per_case = 1 - std::pow(1 - SuiteSignificance, 1.0 / double(cases.size()));
    int failures = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case &c = cases[i];
        auto sample = [&](float uc, Vec2f u, Vec3f *w) {
            auto s = c.bxdf->sample_f(c.wo, uc, u, c.mode, c.flags);
            if (!s) return false;
            EXPECT_FALSE(s->is_specular()) << c.name;
            *w = s->wi;
            return true;
        };
        auto pdf = [&](Vec3f wi) { return double(c.bxdf->pdf(c.wo, wi, c.mode, c.flags)); };
        auto r = chi_square_test(sample, pdf, c.chart, SampleCount, 5000 + i);
        if (r.p_value < per_case) {
            ++failures;
            ADD_FAILURE() << c.name << ": " << r.details << " (level " << per_case << ")";
        }
    }
    EXPECT_EQ(failures, 0);
}

TEST(DisneyBxDF, SamplingIgnoresTransportMode) {
    Rng rng(21, 1);
    for (const Named &n : parameter_grid()) {
        DisneyBxDF b(n.p);
        for (int k = 0; k < 300; ++k) {
            Vec3f wo = random_direction(rng);
            float uc = rng.uniform();
            Vec2f u = rng.uniform2();
            auto r = b.sample_f(wo, uc, u, TransportMode::Radiance);
            auto i = b.sample_f(wo, uc, u, TransportMode::Importance);
            ASSERT_EQ(bool(r), bool(i)) << n.name;
            if (!r) continue;
            EXPECT_EQ(r->wi, i->wi) << n.name;
            EXPECT_EQ(r->pdf, i->pdf) << n.name;
            EXPECT_EQ(r->flags, i->flags) << n.name;
        }
    }
}

TEST(DisneyBxDF, SampledValuesMatchEvaluation) {
    // Non-delta samples carry the whole BSDF's f and pdf for their direction.
    Rng rng(21, 2);
    for (const Named &n : parameter_grid()) {
        DisneyBxDF b(n.p);
        for (int k = 0; k < 1000; ++k) {
            Vec3f wo = random_direction(rng);
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                auto s = b.sample_f(wo, rng.uniform(), rng.uniform2(), mode);
                if (!s) continue;
                ASSERT_FALSE(s->is_specular()) << n.name;
                expect_relative(s->pdf, b.pdf(wo, s->wi, mode), 1e-4f, n.name + " pdf");
                SampledSpectrum f = b.f(wo, s->wi, mode);
                int lanes = s->dispersive ? 1 : NumWavelengths;
                for (int i = 0; i < lanes; ++i) expect_relative(s->f[i], f[i], 1e-4f, n.name + " f");
                EXPECT_EQ(s->is_transmission(), !same_hemisphere(wo, s->wi)) << n.name;
                if (n.p.thin || s->is_reflection()) {
                    EXPECT_EQ(s->eta, 1) << n.name;
                }
            }
        }
    }
}

TEST(DisneyBxDF, RoughDispersiveGlassSamplesAsOneLane) {
    // The specular BSDF of a rough dispersive solid has lane lobes (BxDF::has_lane_lobes):
    // sampled as lane k, a sample reports every lane's density of the whole BSDF, lane k's being
    // the sample's, and their mean is pdf(), the density of sample_f. Every lane is kept.
    DisneyParameters p;
    p.base_color = SampledSpectrum(0.8f), p.base_luminance = 0.8f;
    p.spec_trans = 0.8f, p.roughness = 0.3f, p.eta = SampledSpectrum(1.50f, 1.60f, 1.70f, 1.80f);
    DisneyBxDF b(p);
    ASSERT_TRUE(b.has_lane_lobes());
    Rng rng(21, 3);
    int refractions = 0;
    for (int k = 0; k < 2000; ++k) {
        const Vec3f wo = random_direction(rng);
        const int lane = k % NumWavelengths;
        auto s = b.sample_f_as(lane, wo, rng.uniform(), rng.uniform2(), TransportMode::Radiance);
        if (!s) continue;
        EXPECT_FALSE(s->dispersive);
        const SampledSpectrum f = b.f(wo, s->wi, TransportMode::Radiance);
        for (int i = 0; i < NumWavelengths; ++i) expect_relative(s->f[i], f[i], 1e-4f, "f");
        refractions += s->is_transmission();
        ASSERT_TRUE(s->lane_pdf);
        EXPECT_EQ((*s->lane_pdf)[lane], s->pdf);
        expect_relative(s->lane_pdf->average(), b.pdf(wo, s->wi, TransportMode::Radiance), 1e-4f, "mean pdf");
    }
    EXPECT_GT(refractions, 200);
    p.eta = SampledSpectrum(1.5f);
    EXPECT_FALSE(DisneyBxDF(p).has_lane_lobes());
}

TEST(DisneyBxDF, FilmOnTheSpecularLobes) {
    // Over the dielectric, the film's reflectance takes the place of Fresnel's: on a black,
    // untinted dielectric the reflection lobe is that reflectance times the microfacet terms, so
    // f with a film over f without is R_film / R_fresnel at the half vector, per wavelength.
    ThinFilm film;
    film.thickness_nm = 420;
    film.eta = SampledSpectrum(1.38f);
    film.lambda = SampledSpectrum(430, 520, 610, 700);
    DisneyParameters plain;
    plain.base_color = SampledSpectrum(0.f), plain.base_luminance = 0;
    plain.roughness = 0.4f, plain.eta = SampledSpectrum(1.5f);
    DisneyParameters coated = plain;
    coated.film = film;
    const DisneyBxDF without(plain), with(coated);
    Rng rng(21, 4);
    for (int k = 0; k < 200; ++k) {
        Vec3f wo = random_direction(rng), wi = random_direction(rng);
        wo.z = std::abs(wo.z), wi.z = std::abs(wi.z);
        const float cos_d = dot(wo, normalize(wo + wi));
        const SampledSpectrum a = with.f(wo, wi, TransportMode::Radiance), b = without.f(wo, wi, TransportMode::Radiance);
        for (int i = 0; i < NumWavelengths; ++i)
            if (b[i] > 1e-6f)
                expect_relative(a[i] / b[i], film.over_dielectric(cos_d, 1.5f, i) / fresnel_dielectric(cos_d, 1.5f),
                                1e-4f, "film over the dielectric");
    }
    // Over the metal: an index-matched film (eta 1) leaves the real index that reflects
    // base_color at normal incidence, as Schlick's F0 does.
    DisneyParameters metal;
    metal.base_color = SampledSpectrum(0.95f, 0.64f, 0.54f, 0.3f), metal.base_luminance = 0.7f;
    metal.metallic = 1, metal.roughness = 0.3f;
    DisneyParameters tinted = metal;
    tinted.film = film;
    tinted.film.eta = SampledSpectrum(1.f);
    const Vec3f up(0, 0, 1);
    const SampledSpectrum a = DisneyBxDF(tinted).f(up, up, TransportMode::Radiance);
    const SampledSpectrum b = DisneyBxDF(metal).f(up, up, TransportMode::Radiance);
    for (int i = 0; i < NumWavelengths; ++i) expect_relative(a[i], b[i], 1e-4f, "index-matched film on metal");
    // A film conserves energy: the albedo of a filmed metal and of a filmed glass stays at most 1.
    tinted.film.eta = SampledSpectrum(2.2f);
    DisneyParameters glass = plain;
    glass.spec_trans = 1, glass.film = film;
    for (const DisneyParameters &p : {tinted, glass}) {
        const DisneyBxDF b(p);
        for (float theta : {10.f, 60.f, 85.f}) {
            const Vec3f wo = direction_at(theta);
            SampledSpectrum sum;
            constexpr int N = 20000;
            for (int n = 0; n < N; ++n)
                if (auto s = b.sample_f(wo, rng.uniform(), rng.uniform2(), TransportMode::Importance))
                    sum += s->f * (std::abs(s->wi.z) / s->pdf);
            for (int i = 0; i < NumWavelengths; ++i) EXPECT_LE(sum[i] / N, 1.02f) << theta;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Numerical integration over directions, independent of the BxDF's sampling.

// Integral over the upper hemisphere of g(w) dw by the midpoint rule: in phi with 2n steps, in
// theta with n uniform steps on [0, theta0] and n steps uniform in log(theta) on [theta0, pi/2]
// (only uniform steps when theta0 = pi / 2). A lobe of width w at the pole needs theta0 of
// about w / 4; the logarithmic steps then also follow long tails such as GTR1's.
template <typename F> double integrate_hemisphere(F g, double theta0 = Pi / 2, int n = 300) {
    std::vector<std::pair<double, double>> thetas;  // (theta, dtheta)
    for (int i = 0; i < n; ++i) thetas.push_back({theta0 * (i + 0.5) / n, theta0 / n});
    if (theta0 < Pi / 2) {
        double log_ratio = std::log(Pi / 2 / theta0);
        for (int i = 0; i < n; ++i) {
            double theta = theta0 * std::exp(log_ratio * (i + 0.5) / n);
            thetas.push_back({theta, theta * log_ratio / n});
        }
    }
    double sum = 0;
    for (auto [theta, dtheta] : thetas) {
        double st = std::sin(theta), ct = std::cos(theta);
        for (int j = 0; j < 2 * n; ++j) {
            double phi = 2 * Pi * (j + 0.5) / (2 * n);
            Vec3f w(float(st * std::cos(phi)), float(st * std::sin(phi)), float(ct));
            sum += g(w) * st * dtheta * (Pi / n);
        }
    }
    return sum;
}

// Smith's Lambda for anisotropic GGX (Heitz 2014, eq. 86), written out for the tests.
double ggx_lambda(Vec3f w, double alpha_x, double alpha_y) {
    double a2_tan2 = (sqr(alpha_x * w.x) + sqr(alpha_y * w.y)) / sqr(double(w.z));
    return (std::sqrt(1 + a2_tan2) - 1) / 2;
}

// Probability that an anisotropic GGX normal lies beyond 45 degrees of the pole, the fraction
// of mirror reflections of normal incidence that leave below the horizon. In slope space
// scaled by the alphas the GGX slopes are isotropic with P(|slope|^2 > s) = 1 / (1 + s); along
// the direction psi, tan^2(theta) = |slope|^2 A(psi) with A = ax^2 cos^2 + ay^2 sin^2, so the
// probability is the mean over psi of A / (1 + A).
double ggx_beyond_45_degrees(double alpha_x, double alpha_y) {
    int n = 20000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        double psi = 2 * Pi * (i + 0.5) / n;
        double a = sqr(alpha_x * std::cos(psi)) + sqr(alpha_y * std::sin(psi));
        sum += a / (1 + a);
    }
    return sum / n;
}

// The GGX distribution D(theta) of an isotropic alpha, written out for the tests.
double ggx_d(double cos_theta, double alpha) {
    double c2 = sqr(cos_theta), tan2 = (1 - c2) / c2;
    return 1 / (Pi * sqr(alpha) * sqr(c2) * sqr(1 + tan2 / sqr(alpha)));
}

// Integral of g(cos theta_m) D(theta_m) cos(theta_m) over the normals within 45 degrees of the
// pole (the normals that reflect normal incidence above the horizon).
template <typename F> double integrate_normals_within_45(F g, double alpha, int n = 200000) {
    double sum = 0, top = Pi / 4;
    for (int i = 0; i < n; ++i) {
        double theta = top * (i + 0.5) / n;
        sum += g(std::cos(theta)) * ggx_d(std::cos(theta), alpha) * std::cos(theta) * std::sin(theta);
    }
    return sum * 2 * Pi * top / n;
}

// ---------------------------------------------------------------------------------------------
// Weak white furnace (Heitz 2014, section 6.3; Burley 2015, section 5.1): with the shadowing
// of the outgoing direction removed and a white Fresnel factor, a microfacet lobe scatters all
// the light seen by its visible normals. At normal incidence G1(wo) = 1 and G = G1(wi), so
// integral f cos(wi) / G1(wi) dwi = the fraction of normals whose mirror direction stays above
// the horizon (the rest is what the masking term removes in the full model).

TEST(DisneyBxDF, WeakWhiteFurnaceSpecularLobe) {
    // metallic 1 with a white base: Schlick's F0 = 1 makes the Fresnel factor exactly 1.
    Vec3f wo(0, 0, 1);
    for (float roughness : {0.3f, 0.5f, 0.8f, 1.f})
        for (float anisotropic : {0.f, 0.7f}) {
            DisneyParameters p = grey(1);
            p.metallic = 1, p.roughness = roughness, p.anisotropic = anisotropic;
            DisneyBxDF b(p);
            // Burley 2012's anisotropic alphas.
            double aspect = std::sqrt(1 - 0.9 * anisotropic), alpha = sqr(roughness);
            double ax = alpha / aspect, ay = alpha * aspect;
            double integral = integrate_hemisphere(
                [&](Vec3f wi) { return b.f(wo, wi, TransportMode::Radiance)[0] * wi.z * (1 + ggx_lambda(wi, ax, ay)); },
                std::min(ax, ay) / 4);
            // Tolerance: the quadrature's error, below 1e-3 for these smooth integrands.
            EXPECT_NEAR(integral, 1 - ggx_beyond_45_degrees(ax, ay), 2e-3) << roughness << " " << anisotropic;
        }
}

TEST(DisneyBxDF, WeakWhiteFurnaceClearcoat) {
    // Only the clearcoat reflects: no diffuse (black base), no specular (eta 1 reflects nothing).
    // Dividing out its Fresnel factor, Smith G1s and the clearcoat / 4 scale leaves D / (4 cos o),
    // whose integral is the GTR1 probability of normals within 45 degrees of the pole:
    // 1 - ln((1 + a^2) / 2) / ln(a^2) by the GTR1 cdf in cos^2 theta_m (Burley 2012, appendix B).
    Vec3f wo(0, 0, 1);
    for (float gloss : {0.f, 0.5f, 1.f}) {
        DisneyParameters p = grey(0);
        p.eta = SampledSpectrum(1), p.clearcoat = 1, p.clearcoat_gloss = gloss;
        DisneyBxDF b(p);
        double a = lerp(gloss, 0.1f, 0.001f);  // Burley 2012: mix(.1, .001, clearcoatGloss)
        double integral = integrate_hemisphere(
            [&](Vec3f wi) {
                Vec3f wh = normalize(wo + wi);
                double fresnel = 0.04 + 0.96 * std::pow(1 - wh.z, 5.0);
                double g1 = 1 / (1 + ggx_lambda(wi, 0.25, 0.25));
                return b.f(wo, wi, TransportMode::Radiance)[0] * wi.z / (0.25 * fresnel * g1);
            },
            a / 2);
        double expected = 1 - std::log((1 + a * a) / 2) / std::log(a * a);
        EXPECT_NEAR(integral, expected, 2e-3) << gloss;
    }
}

TEST(DisneyBxDF, WeakWhiteFurnaceThinSurface) {
    // Thin specular transmission mirrors the reflection lobe through the surface with roughness
    // scaled by 0.65 eta - 0.35 (Burley 2015, Figure 15). At eta = 1 nothing reflects and the
    // transmission alone passes the weak furnace with alpha_t = (0.3 roughness)^2; at eta = 1.5
    // reflection and transmission split each normal's light into F and 1 - F.
    Vec3f wo(0, 0, 1);
    for (float roughness : {0.5f, 1.f})
        for (float eta : {1.f, 1.5f}) {
            DisneyParameters p = grey(1);
            p.thin = true, p.spec_trans = 1, p.roughness = roughness;
            p.eta = SampledSpectrum(eta), p.reference_eta = eta;
            DisneyBxDF b(p);
            double alpha_r = sqr(roughness), alpha_t = sqr(roughness * (0.65 * eta - 0.35));
            double reflected = integrate_hemisphere(
                [&](Vec3f wi) { return b.f(wo, wi, TransportMode::Radiance)[0] * wi.z * (1 + ggx_lambda(wi, alpha_r, alpha_r)); },
                alpha_r / 4);
            double transmitted = integrate_hemisphere(
                [&](Vec3f w) {
                    Vec3f wi = mirror_z(w);
                    return b.f(wo, wi, TransportMode::Radiance)[0] * w.z * (1 + ggx_lambda(w, alpha_t, alpha_t));
                },
                alpha_t / 4);
            double expected_r = integrate_normals_within_45([&](double c) { return fresnel_dielectric(float(c), eta); }, alpha_r);
            double expected_t = integrate_normals_within_45([&](double c) { return 1 - fresnel_dielectric(float(c), eta); }, alpha_t);
            if (eta == 1.f) {  // the closed form
                EXPECT_NEAR(expected_t, 1 / (1 + sqr(alpha_t)), 1e-4);
            }
            EXPECT_NEAR(reflected, expected_r, 2e-3) << roughness << " " << eta;
            EXPECT_NEAR(transmitted, expected_t, 2e-3) << roughness << " " << eta;
        }
}

// ---------------------------------------------------------------------------------------------
// Energy.

// Monte Carlo directional albedo: mean of f |cos wi| / pdf, with its standard error.
struct Albedo {
    double mean = 0, standard_error = 0;
};
Albedo directional_albedo(const BxDF &b, Vec3f wo, TransportMode mode, int count, uint64_t seed) {
    Rng rng(seed, 9);
    double sum = 0, sum2 = 0;
    for (int n = 0; n < count; ++n) {
        auto s = b.sample_f(wo, rng.uniform(), rng.uniform2(), mode);
        double w = s ? s->f[0] * std::abs(s->wi.z) / s->pdf : 0;
        sum += w;
        sum2 += w * w;
    }
    Albedo a;
    a.mean = sum / count;
    a.standard_error = std::sqrt(std::max(0.0, sum2 / count - sqr(a.mean)) / count);
    return a;
}

TEST(DisneyBxDF, SamplingWeightsIntegrateF) {
    // The Monte Carlo albedo from sample_f equals the quadrature of f |cos| over the sphere plus
    // the delta lobes' weights computed from the Fresnel equations: this checks f / pdf of every
    // sampling path, including mixtures of delta and non-delta lobes. Bound: 5 standard errors
    // plus the quadrature's error (2e-3).
    struct Setup {
        std::string name;
        DisneyParameters p;
        bool delta;
    };
    std::vector<Setup> setups;
    for (const Named &n : parameter_grid())
        // The glossiest clearcoat is too narrow for the quadrature around a tilted mirror direction.
        if (n.p.clearcoat_gloss < 0.9f || n.p.clearcoat == 0) setups.push_back({n.name, n.p, false});
    {
        DisneyParameters p = grey(0.6f);
        p.roughness = 0, p.spec_trans = 0.5f, p.sheen = 0.3f, p.eta = SampledSpectrum(1.4f);
        setups.push_back({"smooth half glass", p, true});
    }
    int seed = 0;
    for (const Setup &setup : setups)
        for (float theta : {40.f, 130.f}) {
            Vec3f wo = direction_at(theta);
            DisneyBxDF b(setup.p);
            TransportMode mode = TransportMode::Importance;
            auto g = [&](Vec3f w) { return double(b.f(wo, w, mode)[0]) * std::abs(w.z); };
            // Lobes are at least 0.04 wide in alpha here and away from the pole: uniform theta
            // steps of pi / 2 / 250 resolve them.
            double quadrature = integrate_hemisphere(g, Pi / 2, 250) +
                                integrate_hemisphere([&](Vec3f w) { return g(mirror_z(w)); }, Pi / 2, 250);
            if (setup.delta) {
                // Mirror reflection by the dielectric BRDF and the specular BSDF, refraction by the
                // latter with surface absorption sqrt(baseColor); Importance mode has no 1/eta^2.
                float eta = setup.p.eta[0], fr = fresnel_dielectric(std::abs(wo.z), eta);
                float fr_side = fresnel_dielectric(wo.z, eta);  // the specular BSDF knows the sides
                float w_dielectric = (1 - setup.p.spec_trans), w_glass = setup.p.spec_trans;
                quadrature += w_dielectric * fr + w_glass * (fr_side + (1 - fr_side) * std::sqrt(setup.p.base_color[0]));
            }
            Albedo a = directional_albedo(b, wo, mode, 60000, ++seed);
            EXPECT_NEAR(a.mean, quadrature, 5 * a.standard_error + 2e-3) << setup.name << " theta " << theta;
        }
}

TEST(DisneyBxDF, AlbedoAtMostOne) {
    // Energy conservation (Burley 2015, section 2.1: the model conserves energy "given plausible
    // albedos which are typically much less than one"), measured in Importance mode, where
    // f |cos| / pdf is the fraction of a particle's energy scattered (Radiance mode refraction
    // into a denser medium exceeds 1 by the eta^2 of radiance compression). Bound: 1 + 5
    // standard errors, plus 1e-5 for float rounding where every weight is exactly 1.
    //
    // The metallic BRDF and the specular BSDF conserve energy at every angle. The dielectric
    // BRDF does not at grazing angles: its diffuse lobe is not reduced by the specular lobe's
    // Fresnel reflectance (neither in 2012 nor in 2015), which tends to 1 there; with
    // baseColor 0.8 and roughness 0 the albedo is 1.33 at 89 degrees (docs/disney.md). Its
    // bound is checked up to 70 degrees from the normal, on either side, with baseColor 0.6 and
    // moderate sheen and clearcoat.
    struct Setup {
        DisneyParameters p;
        std::vector<float> thetas;
    };
    std::vector<Setup> setups;
    std::vector<float> all = {0, 30, 60, 75, 80, 85, 89, 100, 120, 150, 170};
    std::vector<float> moderate = {0, 30, 60, 70, 110, 120, 150, 170};
    for (float roughness : {0.f, 0.3f, 1.f})
        for (bool thin : {false, true}) {
            DisneyParameters metal = grey(1), glass = grey(1);
            metal.metallic = 1, glass.spec_trans = 1;
            for (DisneyParameters *p : {&metal, &glass}) {
                p->roughness = roughness, p->thin = thin;
                setups.push_back({*p, all});
            }
            for (float metallic : {0.f, 0.5f})
                for (float spec_trans : {0.f, 1.f}) {
                    DisneyParameters p = grey(0.6f);
                    p.roughness = roughness, p.metallic = metallic, p.spec_trans = spec_trans, p.thin = thin;
                    p.sheen = 0.5f, p.clearcoat = 0.5f, p.clearcoat_gloss = 0.5f, p.diff_trans = 1, p.flatness = 0.3f;
                    setups.push_back({p, moderate});
                }
        }
    int seed = 100;
    for (const Setup &s : setups)
        for (float theta : s.thetas) {
            DisneyBxDF b(s.p);
            Albedo a = directional_albedo(b, direction_at(theta), TransportMode::Importance, 8000, ++seed);
            EXPECT_LE(a.mean, 1 + 5 * a.standard_error + 1e-5)
                << "base " << s.p.base_color[0] << " roughness " << s.p.roughness << " metallic " << s.p.metallic
                << " specTrans " << s.p.spec_trans << " thin " << s.p.thin << " theta " << theta;
        }
}

TEST(DisneyBxDF, SubsurfaceBoundaryConservesEnergy) {
    // From inside, a walk that reaches the surface leaves (albedo 41/42) or is reflected back
    // (1/42): the boundary's total albedo is the dielectric blend weight, exactly. From outside,
    // the crossing takes w (1 - F_V / 2), the Lambertian share of eq. 4 for the view direction.
    // Quadrature over both hemispheres (smooth integrands, error below 1e-4).
    for (float metallic : {0.f, 0.4f}) {
        DisneyParameters p = grey(0.5f);
        p.metallic = metallic, p.roughness = 0.6f, p.subsurface = true;
        DisneyBxDF b(p);
        const float w = 1 - metallic;
        for (float theta : {100.f, 135.f, 179.f}) {
            Vec3f wo = direction_at(theta);
            auto g = [&](Vec3f wi) { return double(b.f(wo, wi, TransportMode::Radiance)[0]) * std::abs(wi.z); };
            double total = integrate_hemisphere(g) + integrate_hemisphere([&](Vec3f wi) { return g(mirror_z(wi)); });
            EXPECT_NEAR(total, w, 1e-3) << "inside, theta " << theta << " metallic " << metallic;
        }
        for (float theta : {0.f, 45.f, 80.f}) {
            Vec3f wo = direction_at(theta);
            double entering = integrate_hemisphere([&](Vec3f wi) {
                wi = mirror_z(wi);
                return double(b.f(wo, wi, TransportMode::Radiance)[0]) * std::abs(wi.z);
            });
            double fv = std::pow(1 - std::cos(radians(theta)), 5);
            EXPECT_NEAR(entering, w * (1 - fv / 2), 1e-3) << "outside, theta " << theta;
        }
    }
}

TEST(DisneyBxDF, ProfileEntryIsADiscreteEvent) {
    // With a profile (diffusion, dipole), light from outside enters through a discrete event
    // that carries w (1 - F_V / 2) and has no direction: f and pdf have nothing below the surface
    // from outside, and sample_f returns the entry with weight f |cos| / pdf = share / P(entry).
    // Over stratified lobe choices uc the entry is chosen for a fraction P(entry) of them (to
    // within 1 / N), so the mean weight is the share to within 1 / (N P(entry)) < 1e-3. Every
    // other sample is an ordinary one: its value and density are f and pdf. From inside, the
    // lobes are the random walk's.
    for (float metallic : {0.f, 0.3f}) {
        DisneyParameters p = coloured();
        p.metallic = metallic, p.roughness = 0.6f, p.sheen = 0.5f, p.clearcoat = 0.5f, p.subsurface = true;
        DisneyParameters walk = p;
        p.profile_subsurface = true;
        DisneyBxDF b(p), random_walk(walk);
        const float w = 1 - metallic;
        for (float theta : {0.f, 45.f, 80.f}) {
            Vec3f wo = direction_at(theta);
            for (float below : {100.f, 150.f}) {
                Vec3f wi = direction_at(below, 70);
                EXPECT_TRUE(b.f(wo, wi, TransportMode::Radiance).is_black());
                EXPECT_EQ(b.pdf(wo, wi, TransportMode::Radiance), 0);
            }
            const int n = 20000;
            double entering = 0;
            for (int i = 0; i < n; ++i) {
                auto s = b.sample_f(wo, (i + 0.5f) / n, {0.3f, 0.6f}, TransportMode::Radiance);
                if (!s) continue;
                if (s->wi.z < 0) {
                    EXPECT_EQ(s->flags, BxDFDiffuseTransmission);
                    EXPECT_EQ(s->wi.z, -1);
                    entering += s->f[0] * std::abs(s->wi.z) / s->pdf / n;
                } else if (!is_specular(s->flags)) {
                    expect_relative(s->f[1], b.f(wo, s->wi, TransportMode::Radiance)[1], 1e-5f, "sampled f");
                    expect_relative(s->pdf, b.pdf(wo, s->wi, TransportMode::Radiance), 1e-5f, "sampled pdf");
                }
            }
            double fv = std::pow(1 - std::cos(radians(theta)), 5);
            EXPECT_NEAR(entering, w * (1 - fv / 2), 1e-3) << "theta " << theta << " metallic " << metallic;
            // Reflection is the random walk's (neither has a Lambertian part above the surface).
            Vec3f wr = direction_at(35, 200);
            expect_relative(b.f(wo, wr, TransportMode::Radiance)[2], random_walk.f(wo, wr, TransportMode::Radiance)[2],
                            1e-6f, "reflection");
        }
        Vec3f inside = direction_at(130), out = direction_at(20, 100), back = direction_at(160, 250);
        for (Vec3f wi : {out, back}) {
            EXPECT_EQ(b.f(inside, wi, TransportMode::Radiance)[0], random_walk.f(inside, wi, TransportMode::Radiance)[0]);
            EXPECT_EQ(b.pdf(inside, wi, TransportMode::Radiance), random_walk.pdf(inside, wi, TransportMode::Radiance));
        }
    }
}

TEST(DisneyBxDF, SubsurfaceExitLobe) {
    // (1 - F_L / 2) / pi from inside to outside: albedo 1 - 1/42 (the integral of (1 - mu)^5 mu
    // over [0, 1] is B(2, 6) = 1/42), by quadrature; samples weigh exactly 1 - F_L / 2.
    DisneySubsurfaceExitBxDF exit;
    Vec3f wo = direction_at(170);
    double albedo = integrate_hemisphere(
        [&](Vec3f wi) { return double(exit.f(wo, wi, TransportMode::Radiance)[0]) * wi.z; });
    EXPECT_NEAR(albedo, 41.0 / 42, 1e-4);
    EXPECT_TRUE(exit.f(direction_at(10), direction_at(40), TransportMode::Radiance).is_black());
    EXPECT_TRUE(exit.f(wo, direction_at(120), TransportMode::Radiance).is_black());
    Rng rng(3, 1);
    for (int i = 0; i < 100; ++i) {
        auto s = exit.sample_f(wo, 0, rng.uniform2(), TransportMode::Radiance);
        ASSERT_TRUE(s);
        ASSERT_GT(s->wi.z, 0);
        EXPECT_NEAR(s->f[0] * s->wi.z / s->pdf, 1 - std::pow(1 - s->wi.z, 5) / 2, 1e-5);
        EXPECT_NEAR(s->pdf, exit.pdf(wo, s->wi, TransportMode::Radiance), 1e-6);
    }
}

// ---------------------------------------------------------------------------------------------
// Lobe values.

TEST(DisneyBxDF, DiffuseLobeIsTheRefactoredBRDFDiffuse) {
    // Burley 2015's eq. 4 (Lambert with edge factors plus retro-reflection) must equal the 2012
    // diffuse of eq. 3, baseColor / pi (1 + (F_D90 - 1) F_L)(1 + (F_D90 - 1) F_V) with
    // F_D90 = 0.5 + 2 roughness cos^2 theta_d, on either side of the surface. On thin surfaces
    // diffTrans moves the Lambertian part to an isotropic transmission lobe, (1 - diffTrans / 2)
    // staying in front and diffTrans / 2 passing, and flatness blends the Lambertian part with
    // the 2012 Hanrahan-Krueger-like shape 1.25 (F_ss (1 / (cos_l + cos_v) - 0.5) + 0.5),
    // F_ss = (1 + (F_ss90 - 1) F_L)(1 + (F_ss90 - 1) F_V), F_ss90 = roughness cos^2 theta_d.
    // eta 1 and no sheen leave the diffuse lobes alone.
    Rng rng(31, 1);
    for (float roughness : {0.f, 0.4f, 1.f})
        for (bool thin : {false, true}) {
            DisneyParameters p = coloured();
            p.roughness = roughness, p.eta = SampledSpectrum(1), p.thin = thin, p.diff_trans = 0.6f, p.flatness = 0.3f;
            DisneyBxDF b(p);
            for (int n = 0; n < 1000; ++n) {
                Vec3f wo = random_direction(rng), wi = random_direction(rng);
                SampledSpectrum f = b.f(wo, wi, TransportMode::Radiance);
                double expected;  // in units of baseColor / pi
                if (same_hemisphere(wo, wi)) {
                    double cos_l = std::abs(wi.z), cos_v = std::abs(wo.z);
                    double cos_d = abs_dot(wi, normalize(wo + wi));
                    double fl = std::pow(1 - cos_l, 5), fv = std::pow(1 - cos_v, 5);
                    double fd90 = 0.5 + 2 * roughness * sqr(cos_d);
                    double diffuse_2012 = (1 + (fd90 - 1) * fl) * (1 + (fd90 - 1) * fv);
                    expected = diffuse_2012;
                    if (thin) {
                        double lambert = (1 - fl / 2) * (1 - fv / 2), retro = diffuse_2012 - lambert;
                        double fss90 = roughness * sqr(cos_d);
                        double fss = (1 + (fss90 - 1) * fl) * (1 + (fss90 - 1) * fv);
                        double hanrahan_krueger = 1.25 * (fss * (1 / (cos_l + cos_v) - 0.5) + 0.5);
                        expected = (1 - 0.3) * (1 - 0.6 / 2) * lambert + 0.3 * (1 - 0.6 / 2) * hanrahan_krueger + retro;
                    }
                } else {
                    expected = thin ? 0.6 / 2 : 0;
                }
                for (int i = 0; i < NumWavelengths; ++i)
                    EXPECT_NEAR(f[i], expected * p.base_color[i] * InvPi, 1e-5 * (1 + expected)) << roughness << thin;
            }
        }
}

// ---------------------------------------------------------------------------------------------
// Limits.

TEST(DisneyBxDF, MetallicHasNoDiffuse) {
    // metallic = 1 kills the diffuse, sheen, transmission and specular BSDF lobes: what is left
    // is GGX reflection with Schlick's Fresnel at F0 = baseColor, whatever the other parameters.
    Rng rng(23, 1);
    for (float roughness : {0.3f, 0.8f})
        for (bool thin : {false, true}) {
            DisneyParameters p = coloured();
            p.metallic = 1, p.roughness = roughness, p.anisotropic = 0.4f, p.sheen = 1, p.spec_trans = 0.6f;
            p.thin = thin, p.diff_trans = 1.5f, p.flatness = 1;
            DisneyBxDF b(p);
            EXPECT_EQ(b.flags(), BxDFGlossyReflection);
            TrowbridgeReitzDistribution d = DisneyBxDF::specular_distribution(roughness, 0.4f);
            for (int n = 0; n < 2000; ++n) {
                Vec3f wo = random_direction(rng), wi = random_direction(rng);
                SampledSpectrum f = b.f(wo, wi, TransportMode::Radiance);
                if (!same_hemisphere(wo, wi)) {
                    EXPECT_TRUE(f.is_black());
                    continue;
                }
                Vec3f wm = face_forward(normalize(wo + wi), Vec3f(0, 0, 1));
                float cos_d = abs_dot(wo, wm), m = std::pow(1 - cos_d, 5.f);
                float g = d.D(wm) * d.G(wo, wi) / (4 * std::abs(wo.z * wi.z));
                for (int i = 0; i < NumWavelengths; ++i) {
                    float schlick = p.base_color[i] + (1 - p.base_color[i]) * m;
                    expect_relative(f[i], schlick * g, 1e-4f, "metal");
                }
                auto s = b.sample_f(wo, rng.uniform(), rng.uniform2(), TransportMode::Radiance);
                if (s) {
                    EXPECT_EQ(s->flags, BxDFGlossyReflection);
                }
            }
        }
}

TEST(DisneyBxDF, SmoothSpecTransEqualsSmoothDielectric) {
    // specTrans = 1, roughness 0, metallic 0, white base: the Disney BSDF is the smooth
    // dielectric of the same eta, sample by sample (same random numbers), in both modes.
    Rng rng(23, 2);
    for (SampledSpectrum eta : {SampledSpectrum(1.5f), SampledSpectrum(1.33f), SampledSpectrum(2.4f),
                                SampledSpectrum(1.50f, 1.52f, 1.54f, 1.56f)}) {
        DisneyParameters p = grey(1);
        p.spec_trans = 1, p.roughness = 0, p.eta = eta;
        DisneyBxDF disney(p);
        DielectricBxDF dielectric(eta, TrowbridgeReitzDistribution(0, 0));
        EXPECT_EQ(disney.flags(), dielectric.flags());
        for (int n = 0; n < 2000; ++n) {
            Vec3f wo = random_direction(rng);
            float uc = rng.uniform();
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                auto a = disney.sample_f(wo, uc, {}, mode), b = dielectric.sample_f(wo, uc, {}, mode);
                ASSERT_EQ(bool(a), bool(b));
                if (!a) continue;
                EXPECT_EQ(a->wi, b->wi);
                EXPECT_EQ(a->flags, b->flags);
                EXPECT_FLOAT_EQ(a->pdf, b->pdf);
                EXPECT_EQ(a->eta, b->eta);
                EXPECT_EQ(a->dispersive, b->dispersive);
                for (int i = 0; i < NumWavelengths; ++i) EXPECT_FLOAT_EQ(a->f[i], b->f[i]);
                EXPECT_TRUE(disney.f(wo, a->wi, mode).is_black());
                EXPECT_EQ(disney.pdf(wo, a->wi, mode), 0);
            }
        }
    }
    // A coloured base absorbs sqrt(baseColor) at each refraction and nothing on reflection.
    DisneyParameters p = grey(0.25f);
    p.spec_trans = 1, p.roughness = 0;
    DisneyBxDF tinted(p);
    DielectricBxDF clear(SampledSpectrum(1.5f), TrowbridgeReitzDistribution(0, 0));
    Vec3f wo = direction_at(40);
    for (SampleFlags flags : {SampleFlags::Reflection, SampleFlags::Transmission}) {
        auto a = tinted.sample_f(wo, 0.5f, {}, TransportMode::Radiance, flags);
        auto b = clear.sample_f(wo, 0.5f, {}, TransportMode::Radiance, flags);
        ASSERT_TRUE(a && b);
        EXPECT_FLOAT_EQ(a->f[0] / a->pdf, b->f[0] / b->pdf * (flags == SampleFlags::Reflection ? 1 : 0.5f));
    }
}

TEST(DisneyBxDF, RoughSpecTransEqualsRoughDielectric) {
    // The rough specular BSDF is Walter et al.'s dielectric with Disney's roughness mapping.
    Rng rng(23, 3);
    DisneyParameters p = grey(1);
    p.spec_trans = 1, p.roughness = 0.5f, p.anisotropic = 0.5f, p.eta = SampledSpectrum(1.45f);
    DisneyBxDF disney(p);
    float aspect = std::sqrt(1 - 0.9f * 0.5f);
    DielectricBxDF dielectric(p.eta, TrowbridgeReitzDistribution(0.25f / aspect, 0.25f * aspect));
    for (int n = 0; n < 4000; ++n) {
        Vec3f wo = random_direction(rng), wi = random_direction(rng);
        for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
            expect_relative(disney.f(wo, wi, mode)[0], dielectric.f(wo, wi, mode)[0], 1e-5f, "f");
            expect_relative(disney.pdf(wo, wi, mode), dielectric.pdf(wo, wi, mode), 1e-5f, "pdf");
        }
    }
}

TEST(DisneyBxDF, DeltaLobesWhenSmooth) {
    // roughness 0 mixes delta lobes (mirror and refraction) with the diffuse: delta samples
    // report specular flags and their selection probability as pdf; f and pdf exclude them.
    DisneyParameters p = grey(0.6f);
    p.roughness = 0, p.spec_trans = 0.5f;
    DisneyBxDF b(p);
    BxDFFlags flags = b.flags();
    EXPECT_TRUE(is_specular(flags) && is_diffuse(flags) && is_reflective(flags) && is_transmissive(flags));
    Vec3f wo = direction_at(35);
    Vec3f mirror(-wo.x, -wo.y, wo.z);
    Rng rng(23, 4);
    int delta = 0, diffuse = 0;
    for (int n = 0; n < 2000; ++n) {
        auto s = b.sample_f(wo, rng.uniform(), rng.uniform2(), TransportMode::Radiance);
        ASSERT_TRUE(s);
        if (s->is_specular()) {
            ++delta;
            EXPECT_LT(s->pdf, 1);
            if (s->is_reflection()) {
                EXPECT_EQ(s->wi, mirror);
            }
        } else {
            ++diffuse;
            EXPECT_TRUE(is_diffuse(s->flags));
            expect_relative(s->pdf, b.pdf(wo, s->wi, TransportMode::Radiance), 1e-5f, "pdf");
        }
    }
    EXPECT_GT(delta, 0);
    EXPECT_GT(diffuse, 0);
    // The diffuse part at the mirror direction is all f() reports there.
    DisneyParameters no_delta = p;
    no_delta.spec_trans = 0, no_delta.eta = SampledSpectrum(1);
    SampledSpectrum diffuse_only = DisneyBxDF(no_delta).f(wo, mirror, TransportMode::Radiance) * 0.5f;
    expect_relative(b.f(wo, mirror, TransportMode::Radiance)[0], diffuse_only[0], 1e-5f, "f at mirror");
}

TEST(DisneyBxDF, SchlickCriticalAngleWithSpecularTint) {
    // For eta < 1 Burley's eq. 7 evaluates Schlick's weight at the refracted angle and reflects
    // everything beyond the critical angle; specularTint blends that with the exact Fresnel
    // term. A smooth, black dielectric BRDF has only this mirror lobe, so the sampled weight is
    // the Fresnel factor.
    float eta = 0.7f, f0 = sqr((1 - eta) / (1 + eta));
    for (float tint : {0.f, 0.5f, 1.f})
        for (float theta : {0.f, 30.f, 43.f, 50.f, 80.f, 150.f}) {
            DisneyParameters p = grey(0);
            p.roughness = 0, p.specular_tint = tint, p.eta = SampledSpectrum(eta);
            DisneyBxDF b(p);
            Vec3f wo = direction_at(theta);
            float cos_i = std::abs(wo.z);
            auto s = b.sample_f(wo, 0.3f, {}, TransportMode::Radiance);
            ASSERT_TRUE(s);
            float cos2_t = 1 - (1 - sqr(cos_i)) / sqr(eta);
            float schlick = cos2_t <= 0 ? 1 : f0 + (1 - f0) * std::pow(1 - std::sqrt(cos2_t), 5.f);
            // Exact Fresnel from the wo side, as the two-sided BRDF sees it (cos_i > 0).
            float expected = lerp(tint, fresnel_dielectric(cos_i, eta), schlick);
            EXPECT_NEAR(s->f[0] * std::abs(s->wi.z) / s->pdf, expected, 1e-5f) << tint << " " << theta;
            if (std::sqrt(1 - sqr(cos_i)) > eta) {
                EXPECT_NEAR(expected, 1, 1e-6f);
            }
        }
}

TEST(DisneyBxDF, TintsFollowTheBaseColourHue) {
    // Sheen is sheen (1 - cos theta_d)^5 times lerp(1, baseColor / luminance, sheenTint).
    DisneyParameters p = coloured();
    p.sheen = 0.8f, p.sheen_tint = 0.75f;
    DisneyParameters no_sheen = p;
    no_sheen.sheen = 0;
    DisneyBxDF with(p), without(no_sheen);
    Vec3f wo = direction_at(70, 10), wi = direction_at(80, 200);
    float cos_d = dot(wi, normalize(wo + wi)), m = std::pow(1 - cos_d, 5.f);
    SampledSpectrum sheen = with.f(wo, wi, TransportMode::Radiance) - without.f(wo, wi, TransportMode::Radiance);
    for (int i = 0; i < NumWavelengths; ++i) {
        float tint = p.base_color[i] / p.base_luminance;
        EXPECT_NEAR(sheen[i], 0.8f * lerp(0.75f, 1.f, tint) * m, 1e-5f);
    }
}

// ---------------------------------------------------------------------------------------------
// Reciprocity and transport modes.

TEST(DisneyBxDF, ReciprocityAndTransportModes) {
    // Reflection: f(wo, wi) = f(wi, wo) in both modes (Helmholtz). Thin transmission leaves into
    // the medium it came from: symmetric too, and the same in both modes. A solid's refraction
    // obeys f_radiance(wo, wi) / n_o^2 = f_radiance(wi, wo) / n_i^2 (Veach 1997, eq. 5.15),
    // f_importance(wo, wi) = f_radiance(wi, wo), and the modes differ by eta'^2 = (n_i / n_o)^2.
    Rng rng(29, 1);
    for (const Named &n : parameter_grid()) {
        DisneyBxDF b(n.p);
        float eta = n.p.eta[0];
        int transmissions = 0;
        for (int k = 0; k < 3000; ++k) {
            Vec3f wo = random_direction(rng), wi = random_direction(rng);
            float rad = b.f(wo, wi, TransportMode::Radiance)[0];
            float rad_reverse = b.f(wi, wo, TransportMode::Radiance)[0];
            float imp = b.f(wo, wi, TransportMode::Importance)[0];
            if (same_hemisphere(wo, wi) || n.p.thin) {
                expect_relative(rad, rad_reverse, 1e-4f, n.name + " reciprocity");
                expect_relative(rad, imp, 1e-6f, n.name + " modes");
                continue;
            }
            if (n.p.subsurface && n.p.spec_trans == 0) {
                // The subsurface crossing is index-matched: symmetric, the same in both modes.
                expect_relative(rad, rad_reverse, 1e-4f, n.name + " crossing reciprocity");
                expect_relative(rad, imp, 1e-6f, n.name + " crossing modes");
                continue;
            }
            // Skip pairs whose refraction microfacet is within 0.02 of grazing for either
            // direction, where float rounding moves the Fresnel transmittance by percents (as
            // in bxdf_test.cpp).
            float n_o = wo.z > 0 ? 1 : eta, n_i = wi.z > 0 ? 1 : eta;
            Vec3f h = wo * n_o + wi * n_i;
            if (length(h) == 0 || std::min(abs_dot(wo, normalize(h)), abs_dot(wi, normalize(h))) < 0.02f) continue;
            if (rad > 0) ++transmissions;
            expect_relative(imp, rad_reverse, 2e-3f, n.name + " adjoint");
            // With subsurface, refraction (eta) and the index-matched crossing add up, so only
            // the adjoint relation holds for the sum; each part's own relation is tested above.
            if (n.p.subsurface) continue;
            expect_relative(rad / sqr(n_o), rad_reverse / sqr(n_i), 2e-3f, n.name + " generalised reciprocity");
            expect_relative(rad * sqr(n_i / n_o), imp, 1e-5f, n.name + " mode ratio");
        }
        if (!n.p.thin && n.p.spec_trans > 0 && n.p.metallic < 1) {
            EXPECT_GT(transmissions, 100) << n.name;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The material and its parameters.

SurfaceInteraction surface_at(float u, float v) {
    SurfaceInteraction si;
    si.n = si.shading.n = {0, 0, 1};
    si.dpdu = si.shading.dpdu = {1, 0, 0};
    si.dpdv = si.shading.dpdv = {0, 1, 0};
    si.uv = {u, v};
    return si;
}

using namespace caustica::testing;

class DisneyMaterialTest : public ::testing::Test {
  protected:
    void SetUp() override { set_warnings_enabled(false); }
    void TearDown() override { set_warnings_enabled(true); }

    std::shared_ptr<const DisneyMaterial> create(std::vector<ParsedParameter> params) {
        dict_ = std::make_unique<ParameterDictionary>(dictionary(std::move(params)));
        MaterialPtr m = create_material("disney", *dict_, textures_, directive_location());
        auto disney = std::dynamic_pointer_cast<const DisneyMaterial>(m);
        EXPECT_TRUE(disney);
        return disney;
    }
    int error_line(std::vector<ParsedParameter> params) {
        return input_error_line([&] { create(std::move(params)); });
    }
    DisneyParameters at(const DisneyMaterial &m, float u = 0.5f, float v = 0.5f) const {
        return m.parameters(TextureEvalContext(surface_at(u, v)), lambda_);
    }

    std::unique_ptr<ParameterDictionary> dict_;
    NamedTextures textures_;
    ScratchBuffer scratch_;
    SampledWavelengths lambda_ = SampledWavelengths::sample_visible(0.4f);
};

TEST_F(DisneyMaterialTest, Defaults) {
    auto m = create({});
    DisneyParameters p = at(*m);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_FLOAT_EQ(p.base_color[i], 0.5f);
    EXPECT_NEAR(p.base_luminance, 0.5f, 1e-6f);
    EXPECT_EQ(p.metallic, 0);
    EXPECT_EQ(p.roughness, 0.5f);
    EXPECT_EQ(p.anisotropic, 0);
    EXPECT_EQ(p.specular_tint, 0);
    EXPECT_EQ(p.sheen, 0);
    EXPECT_EQ(p.sheen_tint, 0.5f);
    EXPECT_EQ(p.clearcoat, 0);
    EXPECT_EQ(p.clearcoat_gloss, 1);
    EXPECT_EQ(p.spec_trans, 0);
    EXPECT_FLOAT_EQ(p.eta[0], 1.5f);
    EXPECT_FALSE(p.thin);
    EXPECT_FALSE(m->has_specular_lobe());
    EXPECT_FALSE(m->is_dispersive());
    EXPECT_FALSE(m->has_interior_absorption());
    EXPECT_FALSE(m->has_subsurface());
    EXPECT_FALSE(m->interior_medium());
    BSDF bsdf = m->get_bsdf(surface_at(0.5f, 0.5f), lambda_, scratch_);
    EXPECT_EQ(bsdf.flags(), BxDFDiffuseReflection | BxDFGlossyReflection);
}

TEST_F(DisneyMaterialTest, TexturedParameters) {
    // A scene's `Texture "checks" "float" "checkerboard" "float uscale" 2 "float tex1" 0.1
    // "float tex2" 0.9` and `Texture "tint" "spectrum" "constant" ...` referenced by the material.
    ParameterDictionary checks = dictionary({numbers("float", "uscale", {2}, 2), numbers("float", "tex1", {0.1}, 3),
                                             numbers("float", "tex2", {0.9}, 4)});
    textures_.float_textures["checks"] = create_float_texture("checkerboard", {}, checks, textures_, directive_location());
    ParameterDictionary tint = dictionary({numbers("spectrum", "value", {0.25}, 5)});
    textures_.albedo["tint"] =
        create_spectrum_texture("constant", {}, tint, SpectrumType::Albedo, textures_, directive_location());
    auto m = create({strings("texture", "roughness", {"checks"}, 6), strings("texture", "baseColor", {"tint"}, 7),
                     strings("texture", "sheen", {"checks"}, 8), numbers("float", "metallic", {0.25}, 9)});
    EXPECT_TRUE(m->has_specular_lobe());  // textured roughness may be 0
    DisneyParameters a = at(*m, 0.25f, 0.25f), b = at(*m, 0.75f, 0.25f);
    EXPECT_FLOAT_EQ(a.roughness, 0.1f);
    EXPECT_FLOAT_EQ(b.roughness, 0.9f);
    EXPECT_FLOAT_EQ(b.sheen, 0.9f);
    EXPECT_FLOAT_EQ(a.base_color[2], 0.25f);
    EXPECT_NEAR(a.base_luminance, 0.25f, 1e-6f);
    EXPECT_EQ(a.metallic, 0.25f);
    // The BSDF at each point is the BxDF of that point's parameters.
    Vec3f wo = direction_at(30), wi = direction_at(50, 200);
    for (auto [u, p] : {std::pair{0.25f, a}, std::pair{0.75f, b}}) {
        BSDF bsdf = m->get_bsdf(surface_at(u, 0.25f), lambda_, scratch_);
        EXPECT_FLOAT_EQ(bsdf.f(wo, wi)[0], DisneyBxDF(p).f(wo, wi, TransportMode::Radiance)[0]);
    }
}

TEST_F(DisneyMaterialTest, LuminanceOfASpectrum) {
    // baseColor's luminance is the CIE Y of the reflectance under an equal-energy illuminant;
    // reference: the 1 nm sum over [360, 830] nm. The material's 16-node rule differs from it by
    // the midpoint rule's error on this smooth ramp, well below 1%.
    auto m = create({numbers("spectrum", "baseColor", {400, 0.2, 700, 0.8}, 2)});
    auto ramp = [](double l) { return l <= 400 ? 0.2 : (l >= 700 ? 0.8 : 0.2 + 0.6 * (l - 400) / 300); };
    double weighted = 0, total = 0;
    for (int l = 360; l <= 830; ++l) {
        weighted += ramp(l) * cie_y()(float(l));
        total += cie_y()(float(l));
    }
    EXPECT_NEAR(at(*m).base_luminance, weighted / total, 0.01 * weighted / total);
}

TEST_F(DisneyMaterialTest, DispersionAndThinSurfaces) {
    auto glass = create({strings("spectrum", "eta", {"glass-BK7"}, 2), numbers("float", "specTrans", {1}, 3),
                         numbers("float", "roughness", {0}, 4)});
    EXPECT_TRUE(glass->is_dispersive());
    EXPECT_TRUE(glass->has_specular_lobe());
    SampledSpectrum bk7 = named_ior("glass-BK7")->sample(lambda_);
    DisneyParameters p = at(*glass);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_FLOAT_EQ(p.eta[i], bk7[i]);
    BSDF bsdf = glass->get_bsdf(surface_at(0.5f, 0.5f), lambda_, scratch_);
    auto s = bsdf.sample_f(direction_at(40), 0.5f, {}, TransportMode::Radiance, SampleFlags::Transmission);
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->dispersive);
    // Sellmeier coefficients through the dielectric's parameters (Schott's N-BK7).
    auto sellmeier = create({numbers("float", "sellmeierB", {1.03961212, 0.231792344, 1.01046945}, 2),
                             numbers("float", "sellmeierC", {0.00600069867, 0.0200179144, 103.560653}, 3),
                             numbers("float", "specTrans", {0.5}, 4)});
    EXPECT_TRUE(sellmeier->is_dispersive());
    // Without refraction, or on a thin surface (both refractions cancel), nothing disperses.
    EXPECT_FALSE(create({strings("spectrum", "eta", {"glass-BK7"}, 2)})->is_dispersive());
    auto thin = create({strings("spectrum", "eta", {"glass-BK7"}, 2), numbers("float", "specTrans", {1}, 3),
                        boolean("thin", true, 4), numbers("float", "diffTrans", {1.5}, 5),
                        numbers("float", "flatness", {0.5}, 6)});
    EXPECT_FALSE(thin->is_dispersive());
    EXPECT_TRUE(thin->is_thin());
    DisneyParameters tp = at(*thin);
    EXPECT_EQ(tp.diff_trans, 1.5f);
    EXPECT_EQ(tp.flatness, 0.5f);
    // The thin transmission roughness uses BK7's index at the d line, 1.5168.
    EXPECT_NEAR(tp.reference_eta, 1.5168f, 1e-4f);
}

TEST_F(DisneyMaterialTest, InteriorAbsorptionAndScatterDistance) {
    // Burley 2015, section 2.2: sigma_a = -ln(transmittance) / atDistance.
    auto clear = create({numbers("spectrum", "transmittance", {0.5}, 2), numbers("float", "atDistance", {2}, 3)});
    EXPECT_TRUE(clear->has_interior_absorption());
    EXPECT_NEAR(clear->interior_sigma_a(lambda_)[1], std::log(2.f) / 2, 1e-6f);
    EXPECT_FALSE(clear->has_subsurface());
    // With a scatter distance the interior is the random-walk volume, which takes over the
    // absorption: sigma_a = the walk's own absorption + ln 2 / 2.
    auto solid = create({numbers("spectrum", "transmittance", {0.5}, 2), numbers("float", "atDistance", {2}, 3),
                         numbers("spectrum", "scatterDistance", {0.5}, 4), numbers("spectrum", "baseColor", {0.6}, 5)});
    EXPECT_TRUE(solid->has_subsurface());
    EXPECT_FALSE(solid->has_interior_absorption());
    ASSERT_TRUE(solid->interior_medium());
    const Medium &medium = *solid->interior_medium();
    float alpha = random_walk_single_scattering_albedo(0.6f * 41 / 42);
    float sigma_t = 1 / random_walk_mean_free_path(0.5f, 0.6f);
    EXPECT_NEAR(medium.properties({}, lambda_).sigma_s[0], alpha * sigma_t, 1e-4f * sigma_t);
    EXPECT_NEAR(medium.properties({}, lambda_).sigma_a[2], (1 - alpha) * sigma_t + std::log(2.f) / 2, 1e-4f * sigma_t);
    EXPECT_TRUE(at(*solid).subsurface);
    // Zero scatter distance everywhere is the diffuse BRDF: no volume.
    auto brdf = create({numbers("rgb", "scatterDistance", {0, 0, 0}, 2)});
    EXPECT_FALSE(brdf->has_subsurface());
    // A thin surface has no interior and no subsurface: the solid-only parameters are ignored.
    auto thin = create({boolean("thin", true, 2), numbers("spectrum", "transmittance", {0.5}, 3),
                        numbers("rgb", "scatterDistance", {0.5, 0.25, 0.125}, 4)});
    EXPECT_FALSE(thin->has_interior_absorption());
    EXPECT_FALSE(thin->has_subsurface());
    EXPECT_FALSE(dict_->parameters()[2].looked_up);
    // And a solid does not read the thin-only parameters (they are reported as unused).
    create({numbers("float", "diffTrans", {1}, 2), numbers("float", "flatness", {1}, 3)});
    EXPECT_FALSE(dict_->parameters()[0].looked_up);
    EXPECT_FALSE(dict_->parameters()[1].looked_up);
}

// Jensen et al. 2001's total diffuse reflectance, written out here from the paper (section 2.4,
// with the diffuse Fresnel reflectance of Egan and Hilgeman's fit they use).
double jensen_reflectance(double sigma_a, double sigma_s_reduced, double eta) {
    double fdr = -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
    double A = (1 + fdr) / (1 - fdr);
    double albedo = sigma_s_reduced / (sigma_a + sigma_s_reduced);
    double s = std::sqrt(3 * (1 - albedo));
    return albedo / 2 * (1 + std::exp(-4.0 / 3 * A * s)) * std::exp(-s);
}

// A textured base colour gives the random walk one volume per entry point (for the path's
// wavelengths): at each point, the volume of the constant base colour found there, with the
// solid's Beer-Lambert absorption added as for a constant one; and a path that entered at one
// point keeps its volume when it meets the surface from inside at another (medium_after).
TEST_F(DisneyMaterialTest, TexturedRandomWalkMakesTheVolumeOfTheEntryPoint) {
    ParameterDictionary checks = dictionary({numbers("float", "uscale", {2}, 2), numbers("spectrum", "tex1", {0.3}, 3),
                                             numbers("spectrum", "tex2", {0.7}, 4)});
    textures_.albedo["tint"] =
        create_spectrum_texture("checkerboard", {}, checks, SpectrumType::Albedo, textures_, directive_location());
    auto textured = create({numbers("spectrum", "scatterDistance", {0.2}, 2), strings("texture", "baseColor", {"tint"}, 3),
                            numbers("spectrum", "transmittance", {0.5}, 4), numbers("float", "atDistance", {2}, 5)});
    EXPECT_TRUE(textured->has_interior_medium());
    EXPECT_FALSE(textured->interior_medium());
    EXPECT_FALSE(textured->has_interior_absorption());
    const SurfaceInteraction first = surface_at(0.25f, 0.25f), second = surface_at(0.75f, 0.25f);
    const Medium *at_first = textured->interior_medium(first, lambda_, scratch_);
    const Medium *at_second = textured->interior_medium(second, lambda_, scratch_);
    ASSERT_TRUE(at_first && at_second);
    EXPECT_EQ(at_first->interior_of(), textured.get());
    int compared = 0;
    for (const auto &[si, medium] : {std::pair{first, at_first}, std::pair{second, at_second}}) {
        const float base = at(*textured, si.uv.x, si.uv.y).base_color[0];
        auto constant = create({numbers("spectrum", "scatterDistance", {0.2}, 2), numbers("spectrum", "baseColor", {base}, 3),
                                numbers("spectrum", "transmittance", {0.5}, 4), numbers("float", "atDistance", {2}, 5)});
        const Medium &reference = *constant->interior_medium();
        for (int i = 0; i < NumWavelengths; ++i) {
            EXPECT_NEAR(medium->properties({}, lambda_).sigma_s[i], reference.properties({}, lambda_).sigma_s[i], 1e-5f * reference.properties({}, lambda_).sigma_s[i]);
            EXPECT_NEAR(medium->properties({}, lambda_).sigma_a[i], reference.properties({}, lambda_).sigma_a[i], 1e-5f * reference.properties({}, lambda_).sigma_a[i]);
        }
        ++compared;
    }
    EXPECT_EQ(compared, 2);
    // The two checks give different volumes.
    EXPECT_GT(std::abs(at_first->properties({}, lambda_).sigma_s[0] - at_second->properties({}, lambda_).sigma_s[0]), 0.1f * at_first->properties({}, lambda_).sigma_s[0]);

    // At the second point, seen from inside (as a walk reaches it): a path in the first point's
    // volume keeps it when it turns back in, and leaves it when it crosses out; a path arriving
    // from outside enters the second point's own volume.
    SurfaceInteraction boundary = second;
    boundary.material = textured.get();
    shade(boundary, lambda_, scratch_);
    ASSERT_TRUE(boundary.interior);
    EXPECT_EQ(medium_after(boundary, -boundary.n, at_first), at_first);
    EXPECT_EQ(medium_after(boundary, boundary.n, at_first), nullptr);
    EXPECT_EQ(medium_after(boundary, -boundary.n, nullptr), boundary.interior);
}

// A textured scatter distance is read at the entry point, by the profiles and by the random
// walk (whose volume is then made per point even with a constant base colour): each matches the
// material with the constant distance found there.
TEST_F(DisneyMaterialTest, TexturedScatterDistanceIsReadAtTheEntryPoint) {
    ParameterDictionary checks = dictionary({numbers("float", "uscale", {2}, 2), numbers("spectrum", "tex1", {0.1}, 3),
                                             numbers("spectrum", "tex2", {0.4}, 4)});
    textures_.unbounded["spread"] =
        create_spectrum_texture("checkerboard", {}, checks, SpectrumType::Unbounded, textures_, directive_location());
    for (const char *model : {"randomwalk", "diffusion"}) {
        auto textured = create({strings("string", "subsurface", {model}, 2), strings("texture", "scatterDistance", {"spread"}, 3),
                                numbers("spectrum", "baseColor", {0.6}, 4)});
        EXPECT_TRUE(textured->has_subsurface()) << model;
        int different = 0;
        float first_radius = 0;
        for (float u : {0.25f, 0.75f}) {
            const SurfaceInteraction si = surface_at(u, 0.25f);
            const float d = textures_.unbounded["spread"]->evaluate(TextureEvalContext(si), lambda_)[0];
            auto constant = create({strings("string", "subsurface", {model}, 2), numbers("spectrum", "scatterDistance", {d}, 3),
                                    numbers("spectrum", "baseColor", {0.6}, 4)});
            if (std::string(model) == "randomwalk") {
                EXPECT_FALSE(textured->interior_medium());
                const Medium *medium = textured->interior_medium(si, lambda_, scratch_);
                ASSERT_TRUE(medium);
                const Medium &reference = *constant->interior_medium();
                EXPECT_NEAR(medium->properties({}, lambda_).sigma_s[0], reference.properties({}, lambda_).sigma_s[0], 1e-5f * reference.properties({}, lambda_).sigma_s[0]);
                EXPECT_NEAR(medium->properties({}, lambda_).sigma_a[0], reference.properties({}, lambda_).sigma_a[0], 1e-5f * reference.properties({}, lambda_).sigma_a[0]);
            } else {
                const float radius = as_profile(textured->subsurface_profile(si, lambda_)).max_radius(0);
                EXPECT_FLOAT_EQ(radius, as_profile(constant->subsurface_profile(si, lambda_)).max_radius(0));
                if (u == 0.25f) first_radius = radius;
                else different += radius != first_radius;
            }
        }
        if (std::string(model) == "diffusion") {
            EXPECT_EQ(different, 1);
        }
    }
}

TEST_F(DisneyMaterialTest, SubsurfaceModels) {
    // The default is the random walk.
    auto walk = create({numbers("spectrum", "scatterDistance", {0.5}, 2)});
    EXPECT_EQ(walk->subsurface_model(), SubsurfaceModel::RandomWalk);
    EXPECT_TRUE(walk->interior_medium());
    EXPECT_FALSE(walk->has_profile_subsurface());
    EXPECT_FALSE(at(*walk).profile_subsurface);

    // Diffusion: no volume, Beer-Lambert absorption kept for refracted paths, a textured base
    // colour allowed, and a profile whose albedo is the base colour at the entry point and whose
    // spread is the scatter distance.
    ParameterDictionary checks = dictionary({numbers("float", "uscale", {2}, 2), numbers("spectrum", "tex1", {0.3}, 3),
                                             numbers("spectrum", "tex2", {0.7}, 4)});
    textures_.albedo["tint"] =
        create_spectrum_texture("checkerboard", {}, checks, SpectrumType::Albedo, textures_, directive_location());
    auto diffusion = create({strings("string", "subsurface", {"diffusion"}, 2),
                             numbers("spectrum", "scatterDistance", {0.2}, 3), strings("texture", "baseColor", {"tint"}, 4),
                             numbers("spectrum", "transmittance", {0.5}, 5)});
    EXPECT_EQ(diffusion->subsurface_model(), SubsurfaceModel::Diffusion);
    EXPECT_TRUE(diffusion->has_subsurface());
    EXPECT_TRUE(diffusion->has_profile_subsurface());
    EXPECT_FALSE(diffusion->interior_medium());
    EXPECT_TRUE(diffusion->has_interior_absorption());
    DisneyParameters p = at(*diffusion);
    EXPECT_TRUE(p.subsurface);
    EXPECT_TRUE(p.profile_subsurface);
    DisneySubsurfaceProfile profile = diffusion->subsurface_profile(surface_at(0.25f, 0.25f), lambda_);
    DisneySubsurfaceProfile other = diffusion->subsurface_profile(surface_at(0.75f, 0.25f), lambda_);
    ASSERT_TRUE(std::holds_alternative<NormalizedDiffusionProfile>(profile));
    NormalizedDiffusionProfile expected(SampledSpectrum(0.3f), SampledSpectrum(0.2f));
    for (int i = 0; i < NumWavelengths; ++i) {
        EXPECT_FLOAT_EQ(as_profile(profile).albedo()[i], 0.3f);
        EXPECT_FLOAT_EQ(as_profile(other).albedo()[i], 0.7f);
        EXPECT_FLOAT_EQ(as_profile(profile).max_radius(i), expected.max_radius(i));
    }

    // A channel with scatter distance 0 is held at a thousandth of the largest: the BRDF limit
    // at the scale of the others, but within the probes' reach.
    auto partly = create({strings("string", "subsurface", {"diffusion"}, 2),
                          numbers("spectrum", "scatterDistance", {360, 0, 550, 0, 560, 0.1, 830, 0.1}, 3)});
    SampledWavelengths lambda = SampledWavelengths::sample_uniform(0.1f);
    DisneySubsurfaceProfile partial = partly->subsurface_profile(surface_at(0.5f, 0.5f), lambda);
    NormalizedDiffusionProfile floor(SampledSpectrum(0.5f), SampledSpectrum(1e-4f));
    for (int i = 0; i < NumWavelengths; ++i)
        if (lambda[i] < 550) {
            EXPECT_FLOAT_EQ(as_profile(partial).max_radius(i), floor.max_radius(0)) << lambda[i];
        }

    // Dipole from (baseColor, scatterDistance): it reflects the base colour (Jensen's R_d of
    // its coefficients), and its mean free path is d s(A) (s(0.6) = 1.34).
    auto dipole = create({strings("string", "subsurface", {"dipole"}, 2), numbers("spectrum", "scatterDistance", {0.2}, 3),
                          numbers("spectrum", "baseColor", {0.6}, 4), numbers("float", "eta", {1.4}, 5)});
    EXPECT_FALSE(dipole->interior_medium());
    DisneySubsurfaceProfile mapped = dipole->subsurface_profile(surface_at(0.5f, 0.5f), lambda_);
    ASSERT_TRUE(std::holds_alternative<DipoleProfile>(mapped));
    EXPECT_NEAR(as_profile(mapped).albedo()[0], 0.6f, 1e-4f);
    DipoleCoefficients c = dipole_coefficients(SampledSpectrum(0.6f), SampledSpectrum(0.2f), 1.4f);
    EXPECT_NEAR(1 / (c.sigma_a[0] + c.sigma_s_reduced[0]), 0.2 * (1.9 - 0.6 + 3.5 * 0.04), 1e-5);
    EXPECT_NEAR(jensen_reflectance(c.sigma_a[0], c.sigma_s_reduced[0], 1.4), 0.6, 1e-4);
    // (alpha' as a float: near 1 its rounding moves R_d by up to ~1e-5.)
    for (float r : {0.f, 0.05f, 0.3f, 0.9f, 0.99f, 1.f})
        EXPECT_NEAR(dipole_diffuse_reflectance(dipole_reduced_albedo(r, 1.3f), 1.3f), r, 1e-4f) << r;
    // Near white the absorption is a tiny fraction of the extinction, which the coefficients keep
    // to full precision (1 - alpha' is below a float's resolution at 1 here).
    DipoleCoefficients white = dipole_coefficients(SampledSpectrum(0.9999f), SampledSpectrum(0.2f), 1.3f);
    EXPECT_NEAR(jensen_reflectance(white.sigma_a[0], white.sigma_s_reduced[0], 1.3), 0.9999, 1e-6);

    // Dipole from a preset: Jensen's coefficients in mm^-1 times "scale" (scene units per mm):
    // the albedo is Jensen's R_d whatever the scale, which only shrinks the spread.
    auto skin = create({strings("string", "subsurface", {"dipole"}, 2), strings("string", "preset", {"Skin1"}, 3),
                        numbers("float", "eta", {1.3}, 4)});
    auto small_skin = create({strings("string", "subsurface", {"dipole"}, 2), strings("string", "preset", {"skin1"}, 3),
                              numbers("float", "eta", {1.3}, 4), numbers("float", "scale", {10}, 5)});
    EXPECT_TRUE(skin->has_profile_subsurface());
    auto measured = find_measured_subsurface_medium("skin1");
    ASSERT_TRUE(measured);
    RGBUnboundedSpectrum sigma_a(RGBColorSpace::srgb(), measured->sigma_a);
    RGBUnboundedSpectrum sigma_s(RGBColorSpace::srgb(), measured->sigma_s_reduced);
    DisneySubsurfaceProfile big = skin->subsurface_profile(surface_at(0.5f, 0.5f), lambda_);
    DisneySubsurfaceProfile small = small_skin->subsurface_profile(surface_at(0.5f, 0.5f), lambda_);
    for (int i = 0; i < NumWavelengths; ++i) {
        double rd = jensen_reflectance(sigma_a(lambda_[i]), sigma_s(lambda_[i]), 1.3);
        EXPECT_NEAR(as_profile(big).albedo()[i], rd, 1e-5);
        EXPECT_NEAR(as_profile(small).albedo()[i], rd, 1e-5);
        EXPECT_NEAR(as_profile(small).max_radius(i), as_profile(big).max_radius(i) / 10, 1e-4 * as_profile(big).max_radius(i));
    }

    // A thin surface reads none of it.
    create({boolean("thin", true, 2), strings("string", "subsurface", {"diffusion"}, 3)});
    EXPECT_FALSE(dict_->parameters()[1].looked_up);
}

TEST_F(DisneyMaterialTest, ErrorsPointAtTheParameter) {
    EXPECT_EQ(error_line({numbers("float", "metallic", {1.5}, 3)}), 3);
    EXPECT_EQ(error_line({numbers("float", "roughness", {-0.1}, 4)}), 4);
    EXPECT_EQ(error_line({numbers("float", "anisotropic", {NAN}, 5)}), 5);
    EXPECT_EQ(error_line({numbers("float", "sheen", {-1}, 6)}), 6);
    EXPECT_EQ(error_line({numbers("float", "clearcoatGloss", {2}, 7)}), 7);
    EXPECT_EQ(error_line({numbers("float", "specTrans", {1.01}, 8)}), 8);
    EXPECT_EQ(error_line({boolean("thin", true, 2), numbers("float", "diffTrans", {2.5}, 9)}), 9);
    EXPECT_EQ(error_line({numbers("float", "eta", {0}, 10)}), 10);
    EXPECT_EQ(error_line({numbers("spectrum", "scatterDistance", {-1}, 11)}), 11);
    EXPECT_EQ(error_line({numbers("spectrum", "transmittance", {0.5}, 2), numbers("float", "atDistance", {0}, 12)}), 12);
    EXPECT_EQ(error_line({strings("string", "subsurface", {"bssrdf"}, 13)}), 13);
    EXPECT_EQ(error_line({strings("string", "subsurface", {"dipole"}, 2), strings("string", "preset", {"jade"}, 14)}), 14);
    EXPECT_EQ(error_line({strings("string", "subsurface", {"dipole"}, 2), strings("string", "preset", {"apple"}, 3),
                          numbers("spectrum", "scatterDistance", {0.1}, 15)}),
              15);
    EXPECT_EQ(error_line({strings("string", "subsurface", {"dipole"}, 2), strings("string", "preset", {"apple"}, 3),
                          numbers("float", "scale", {0}, 16)}),
              16);
    EXPECT_EQ(error_line({strings("string", "subsurface", {"dipole"}, 2), numbers("spectrum", "scatterDistance", {0.1}, 3),
                          numbers("float", "eta", {0.8}, 17)}),
              17);
    // Every model takes a textured base colour (the random walk makes its volume per entry point).
    ParameterDictionary checks = dictionary({numbers("spectrum", "tex1", {0.2}, 2), numbers("spectrum", "tex2", {0.6}, 3)});
    textures_.albedo["tint"] =
        create_spectrum_texture("checkerboard", {}, checks, SpectrumType::Albedo, textures_, directive_location());
    EXPECT_EQ(error_line({numbers("spectrum", "scatterDistance", {0.1}, 3), strings("texture", "baseColor", {"tint"}, 18)}),
              -1);
    EXPECT_EQ(error_line({strings("string", "subsurface", {"dipole"}, 2), numbers("spectrum", "scatterDistance", {0.1}, 3),
                          strings("texture", "baseColor", {"tint"}, 4)}),
              -1);
    EXPECT_EQ(error_line({numbers("float", "sheen", {4}, 2), numbers("float", "clearcoat", {1}, 3),
                          boolean("thin", true, 4), numbers("float", "diffTrans", {2}, 5)}),
              -1);
}

} // namespace
} // namespace caustica
