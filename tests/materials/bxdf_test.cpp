// Deterministic and Monte Carlo properties of the BxDFs: reciprocity, the transport-mode
// relations, energy conservation, the smooth limits and dispersion.
#include "core/rng.h"
#include "materials/conductor_bxdf.h"
#include "materials/dielectric_bxdf.h"
#include "materials/diffuse_bxdf.h"
#include "materials/fresnel.h"
#include "materials/thin_dielectric_bxdf.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace caustica {
namespace {

const SampledSpectrum CuEta(0.27f, 0.68f, 1.1f, 1.2f), CuK(3.6f, 2.6f, 2.5f, 2.3f);

Vec3f random_direction(Rng &rng) {
    Vec2f u = rng.uniform2();
    float z = 1 - 2 * u.x, r = safe_sqrt(1 - z * z), phi = 2 * Pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

void expect_relative(float a, float b, float tolerance, const std::string &what) {
    EXPECT_LE(std::abs(a - b), tolerance * std::max(std::abs(a), std::abs(b)) + 1e-7f)
        << what << ": " << a << " vs " << b;
}

std::vector<std::pair<float, float>> rough_alphas() {
    return {{0.05f, 0.05f}, {0.3f, 0.3f}, {1, 1}, {0.1f, 0.6f}};
}

TEST(BxDF, ReflectionIsReciprocal) {
    // f(wo, wi) = f(wi, wo) for reflection in both modes (Helmholtz reciprocity).
    Rng rng(7, 1);
    DiffuseBxDF diffuse(SampledSpectrum(0.6f));
    for (auto [ax, ay] : rough_alphas()) {
        TrowbridgeReitzDistribution d(ax, ay);
        ConductorBxDF conductor(d, CuEta, CuK);
        DielectricBxDF dielectric(SampledSpectrum(1.5f), d);
        const BxDF *bxdfs[] = {&diffuse, &conductor, &dielectric};
        for (int n = 0; n < 2000; ++n) {
            Vec3f wo = random_direction(rng), wi = random_direction(rng);
            if (!same_hemisphere(wo, wi)) wi.z = -wi.z;
            for (const BxDF *b : bxdfs)
                for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                    SampledSpectrum a = b->f(wo, wi, mode), c = b->f(wi, wo, mode);
                    for (int i = 0; i < NumWavelengths; ++i) expect_relative(a[i], c[i], 1e-4f, "reflection");
                }
        }
    }
}

TEST(BxDF, RoughTransmissionReciprocityAndModes) {
    // Radiance mode obeys the generalised reciprocity f(wo, wi) / n_o^2 = f(wi, wo) / n_i^2,
    // where n_x is the index on the side of x (Veach 1997, eq. 5.15). Importance mode is its
    // adjoint, f_importance(wo, wi) = f_radiance(wi, wo), and the two modes differ exactly by
    // eta'^2 = (n_i / n_o)^2 on transmission and not at all on reflection.
    Rng rng(7, 2);
    for (float eta : {1.5f, 1 / 1.5f, 2.4f, 1.0001f})
        for (auto [ax, ay] : rough_alphas()) {
            DielectricBxDF b(SampledSpectrum(eta), TrowbridgeReitzDistribution(ax, ay));
            // The reversed pair recomputes the half vector from the other end; float rounding
            // of its direction (largest near eta = 1, about 1e-7 / |eta - 1| rad) stays well
            // inside a relative 2e-3 once facet-grazing pairs are skipped (below).
            const float tolerance = 2e-3f;
            int nonzero = 0;
            for (int n = 0; n < 4000; ++n) {
                Vec3f wo = random_direction(rng), wi = random_direction(rng);
                float n_o = wo.z > 0 ? 1 : eta, n_i = wi.z > 0 ? 1 : eta;
                // Skip pairs whose microfacet is within 0.02 of grazing for either direction:
                // there the refracted side is within 1e-3 rad of the critical angle, where
                // 1 - sin^2 cancels and a float cosine's rounding alone moves T by percents.
                Vec3f h = same_hemisphere(wo, wi) ? wo + wi : wo * n_o + wi * n_i;
                if (length(h) > 0 && std::min(abs_dot(wo, normalize(h)), abs_dot(wi, normalize(h))) < 0.02f)
                    continue;
                float rad = b.f(wo, wi, TransportMode::Radiance)[0];
                float rad_reverse = b.f(wi, wo, TransportMode::Radiance)[0];
                float imp = b.f(wo, wi, TransportMode::Importance)[0];
                if (rad > 0) ++nonzero;
                expect_relative(rad / sqr(n_o), rad_reverse / sqr(n_i), tolerance, "reciprocity");
                expect_relative(imp, rad_reverse, tolerance, "adjoint");
                float factor = same_hemisphere(wo, wi) ? 1 : sqr(n_i / n_o);
                expect_relative(rad * factor, imp, 1e-5f, "mode ratio");
            }
            EXPECT_GT(nonzero, 400) << "eta " << eta << " alpha " << ax;
        }
}

TEST(BxDF, SamplingDoesNotDependOnTransportMode) {
    // The chi-square suite alternates modes; this shows it may: same sample and pdf in both.
    Rng rng(7, 3);
    for (float eta : {1.5f, 1 / 1.5f})
        for (auto [ax, ay] : rough_alphas()) {
            DielectricBxDF b(SampledSpectrum(eta), TrowbridgeReitzDistribution(ax, ay));
            ConductorBxDF c(TrowbridgeReitzDistribution(ax, ay), CuEta, CuK);
            DiffuseBxDF d(SampledSpectrum(0.5f));
            const BxDF *bxdfs[] = {&b, &c, &d};
            for (int n = 0; n < 500; ++n) {
                Vec3f wo = random_direction(rng);
                float uc = rng.uniform();
                Vec2f u = rng.uniform2();
                for (const BxDF *x : bxdfs) {
                    auto r = x->sample_f(wo, uc, u, TransportMode::Radiance);
                    auto i = x->sample_f(wo, uc, u, TransportMode::Importance);
                    ASSERT_EQ(bool(r), bool(i));
                    if (!r) continue;
                    EXPECT_EQ(r->wi, i->wi);
                    EXPECT_EQ(r->pdf, i->pdf);
                    EXPECT_EQ(r->flags, i->flags);
                    EXPECT_EQ(x->pdf(wo, r->wi, TransportMode::Radiance),
                              x->pdf(wo, r->wi, TransportMode::Importance));
                }
            }
        }
}

TEST(BxDF, SampledValuesMatchEvaluation) {
    // For non-specular samples, sample_f's f and pdf are what f() and pdf() give for its wi.
    Rng rng(7, 4);
    for (float eta : {1.5f, 1 / 1.5f, 2.4f})
        for (auto [ax, ay] : rough_alphas()) {
            DielectricBxDF b(SampledSpectrum(eta), TrowbridgeReitzDistribution(ax, ay));
            ConductorBxDF c(TrowbridgeReitzDistribution(ax, ay), CuEta, CuK);
            const BxDF *bxdfs[] = {&b, &c};
            for (int n = 0; n < 2000; ++n) {
                Vec3f wo = random_direction(rng);
                for (const BxDF *x : bxdfs)
                    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                        auto s = x->sample_f(wo, rng.uniform(), rng.uniform2(), mode);
                        if (!s) continue;
                        expect_relative(s->pdf, x->pdf(wo, s->wi, mode), 1e-3f, "pdf");
                        SampledSpectrum f = x->f(wo, s->wi, mode);
                        for (int i = 0; i < NumWavelengths; ++i) expect_relative(s->f[i], f[i], 1e-3f, "f");
                    }
            }
        }
}

// Monte Carlo directional albedo: mean of f |cos wi| / pdf over samples, with its standard error.
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

TEST(BxDF, DirectionalAlbedoAtMostOne) {
    // A bound with Monte Carlo tolerance: albedo <= 1 + 5 standard errors + 1e-4 (a one-sided
    // 5 sigma band is exceeded by chance with probability below 1e-6 per case). Dielectrics are
    // checked in Importance mode, where f |cos| / pdf is the fraction of the particle's energy
    // that is scattered; Radiance mode transmission into a denser medium legitimately exceeds 1
    // by eta^2 (radiance compression).
    std::vector<std::pair<float, float>> alphas = {{1e-3f, 1e-3f}, {0.05f, 0.05f}, {0.3f, 0.3f},
                                                   {1, 1}, {0.1f, 0.6f}, {0, 0}};
    int seed = 0;
    for (auto [ax, ay] : alphas)
        for (float theta : {0.f, 40.f, 75.f, 89.f, 120.f, 170.f}) {
            float t = radians(theta);
            Vec3f wo(std::sin(t) * 0.8f, std::sin(t) * 0.6f, std::cos(t));
            TrowbridgeReitzDistribution d(ax, ay);
            DiffuseBxDF diffuse(SampledSpectrum(1));
            ConductorBxDF conductor(d, SampledSpectrum(0.05f), SampledSpectrum(6));  // silver-like
            ThinDielectricBxDF thin(SampledSpectrum(1.5f));
            std::vector<std::pair<const BxDF *, TransportMode>> cases = {
                {&diffuse, TransportMode::Radiance}, {&conductor, TransportMode::Radiance},
                {&conductor, TransportMode::Importance}, {&thin, TransportMode::Radiance}};
            std::vector<std::unique_ptr<DielectricBxDF>> dielectrics;
            for (float eta : {1.5f, 1 / 1.5f, 2.4f, 1.0001f}) {
                dielectrics.push_back(std::make_unique<DielectricBxDF>(SampledSpectrum(eta), d));
                cases.push_back({dielectrics.back().get(), TransportMode::Importance});
            }
            for (auto [b, mode] : cases) {
                Albedo a = directional_albedo(*b, wo, mode, 8000, ++seed);
                EXPECT_LE(a.mean, 1 + 5 * a.standard_error + 1e-4)
                    << "alpha " << ax << "," << ay << " theta " << theta;
            }
        }
}

TEST(BxDF, DiffuseAlbedoEqualsReflectance) {
    // Cosine sampling makes every weight exactly R, so the albedo is R without noise.
    DiffuseBxDF b(SampledSpectrum(0.3f, 0.6f, 1.4f, -0.2f));
    Rng rng(3, 3);
    for (int n = 0; n < 1000; ++n) {
        Vec3f wo = random_direction(rng);
        auto s = b.sample_f(wo, 0.5f, rng.uniform2(), TransportMode::Radiance);
        ASSERT_TRUE(s);
        SampledSpectrum w = s->f * std::abs(s->wi.z) / s->pdf;
        EXPECT_NEAR(w[0], 0.3f, 1e-5f);
        EXPECT_NEAR(w[1], 0.6f, 1e-5f);
        EXPECT_NEAR(w[2], 1.f, 1e-5f);  // clamped to [0, 1]
        EXPECT_NEAR(w[3], 0.f, 1e-5f);
        EXPECT_TRUE(same_hemisphere(wo, s->wi));
    }
}

TEST(BxDF, SmoothDielectricReflectionPlusTransmissionIsOne) {
    // In Importance mode each sampled weight is exactly 1 (the branch is chosen with probability
    // R or T and carries R or T), and the weights of the two branches alone are R and T.
    Rng rng(5, 5);
    for (float eta : {1.5f, 1 / 1.5f, 2.4f, 1.33f}) {
        DielectricBxDF b(SampledSpectrum(eta), TrowbridgeReitzDistribution(0, 0));
        EXPECT_EQ(b.flags(), BxDFReflection | BxDFTransmission | BxDFSpecular);
        for (int n = 0; n < 500; ++n) {
            Vec3f wo = random_direction(rng);
            float cos_o = std::abs(wo.z);
            auto s = b.sample_f(wo, rng.uniform(), {}, TransportMode::Importance);
            ASSERT_TRUE(s);
            EXPECT_NEAR(s->f[0] * std::abs(s->wi.z) / s->pdf, 1, 1e-5f);
            auto r = b.sample_f(wo, 0.5f, {}, TransportMode::Importance, SampleFlags::Reflection);
            auto t = b.sample_f(wo, 0.5f, {}, TransportMode::Importance, SampleFlags::Transmission);
            ASSERT_TRUE(r);
            float rw = r->f[0] * std::abs(r->wi.z) / r->pdf;
            float tw = t ? t->f[0] * std::abs(t->wi.z) / t->pdf : 0;
            EXPECT_NEAR(rw + tw, 1, 1e-5f);
            EXPECT_NEAR(rw, fresnel_dielectric(wo.z, eta), 1e-6f);
            EXPECT_NEAR(r->wi.z, wo.z, 1e-7f);
            if (t) {
                // Snell's law: n_o sin(theta_o) = n_i sin(theta_i).
                float n_o = wo.z > 0 ? 1 : eta, n_i = wo.z > 0 ? eta : 1;
                EXPECT_NEAR(n_o * std::sqrt(1 - sqr(cos_o)), n_i * sin_theta(t->wi), 1e-5f);
                EXPECT_LT(t->wi.z * wo.z, 0);
                EXPECT_FLOAT_EQ(t->eta, n_i / n_o);
                // Radiance mode divides by eta'^2 exactly, Importance mode does not.
                auto tr = b.sample_f(wo, 0.5f, {}, TransportMode::Radiance, SampleFlags::Transmission);
                EXPECT_FLOAT_EQ(tr->f[0] * sqr(n_i / n_o), t->f[0]);
            }
        }
    }
}

TEST(BxDF, SmoothDielectricFrequenciesFollowFresnel) {
    // The reflected fraction of samples is binomial with p = R; 5 sigma bound.
    float eta = 1.5f;
    DielectricBxDF b(SampledSpectrum(eta), TrowbridgeReitzDistribution(0, 0));
    Rng rng(5, 6);
    for (float theta : {0.f, 60.f, 85.f, 160.f}) {
        float t = radians(theta);
        Vec3f wo(std::sin(t), 0, std::cos(t));
        float r = fresnel_dielectric(wo.z, eta);
        int n = 100000, reflected = 0;
        for (int i = 0; i < n; ++i)
            reflected += b.sample_f(wo, rng.uniform(), {}, TransportMode::Radiance)->is_reflection();
        EXPECT_NEAR(double(reflected) / n, r, 5 * std::sqrt(r * (1 - r) / n) + 1e-9) << theta;
    }
    // From inside at 45 degrees, beyond the critical angle asin(1 / 1.5) = 41.8 degrees, every
    // sample reflects.
    Vec3f beyond(std::sin(radians(135.f)), 0, std::cos(radians(135.f)));
    for (int i = 0; i < 100; ++i) {
        auto s = b.sample_f(beyond, rng.uniform(), {}, TransportMode::Radiance);
        ASSERT_TRUE(s);
        EXPECT_TRUE(s->is_reflection());
        EXPECT_NEAR(s->f[0] * std::abs(s->wi.z) / s->pdf, 1, 1e-6f);
    }
    EXPECT_FALSE(b.sample_f(beyond, 0.5f, {}, TransportMode::Radiance, SampleFlags::Transmission));
}

TEST(BxDF, RoughDielectricApproachesSmooth) {
    // With alpha = 1e-3 (just rough) the reflected and transmitted energies approach the smooth
    // interface's Fresnel R and T, and the directions cluster at the specular ones. Weights of the
    // rough model are F G / G1 with G / G1 within 1e-3 of 1 at these angles, and the Fresnel
    // factor varies by O(alpha) over the lobe, so 0.01 bounds both plus the Monte Carlo noise
    // (the weights' spread is itself O(alpha)).
    for (float eta : {1.5f, 1 / 1.5f, 2.4f})
        for (float theta : {0.f, 30.f, 60.f, 150.f}) {
            float t = radians(theta);
            Vec3f wo(std::sin(t), 0, std::cos(t));
            DielectricBxDF rough(SampledSpectrum(eta), TrowbridgeReitzDistribution(1e-3f, 1e-3f));
            DielectricBxDF smooth(SampledSpectrum(eta), TrowbridgeReitzDistribution(0, 0));
            auto sr = smooth.sample_f(wo, 0, {}, TransportMode::Importance, SampleFlags::Reflection);
            auto st = smooth.sample_f(wo, 0, {}, TransportMode::Importance, SampleFlags::Transmission);
            Rng rng(11, 1);
            double reflected = 0, transmitted = 0;
            int n = 4000, near = 0, total = 0;
            for (int i = 0; i < n; ++i) {
                auto s = rough.sample_f(wo, rng.uniform(), rng.uniform2(), TransportMode::Importance);
                if (!s) continue;
                double w = s->f[0] * std::abs(s->wi.z) / s->pdf;
                const auto &ref = s->is_reflection() ? sr : st;
                ASSERT_TRUE(ref);
                (s->is_reflection() ? reflected : transmitted) += w;
                ++total;
                if (std::acos(clamp(dot(s->wi, ref->wi), -1.f, 1.f)) < 0.05f) ++near;
            }
            float r = fresnel_dielectric(wo.z, eta);
            EXPECT_NEAR(reflected / n, r, 0.01) << eta << " " << theta;
            EXPECT_NEAR(transmitted / n, 1 - r, 0.01) << eta << " " << theta;
            // GGX tails: the fraction of normals more than 0.025 rad (25 alpha) off is about
            // (alpha / 0.025)^2 = 1.6e-3; allow 1%.
            EXPECT_GT(near, 0.99 * total);
        }
}

TEST(BxDF, IndexMatchedInterfaceIsInvisible) {
    for (float eta : {1.f, 1.00005f, 0.99995f})
        for (float alpha : {0.f, 0.3f}) {
            DielectricBxDF b(SampledSpectrum(eta), TrowbridgeReitzDistribution(alpha, alpha));
            EXPECT_EQ(b.flags(), BxDFSpecularTransmission);
            Vec3f wo = normalize(Vec3f(0.3f, -0.4f, 0.5f));
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                auto s = b.sample_f(wo, 0.9f, {0.3f, 0.7f}, mode);
                ASSERT_TRUE(s);
                EXPECT_EQ(s->wi, -wo);
                EXPECT_FLOAT_EQ(s->f[0] * std::abs(s->wi.z) / s->pdf, 1);
                EXPECT_TRUE(s->is_specular());
                EXPECT_FALSE(b.sample_f(wo, 0.9f, {}, mode, SampleFlags::Reflection));
                EXPECT_TRUE(b.f(wo, -wo, mode).is_black());
            }
        }
}

TEST(BxDF, DispersiveSmoothDielectric) {
    SampledSpectrum eta(1.50f, 1.52f, 1.54f, 1.56f);
    DielectricBxDF b(eta, TrowbridgeReitzDistribution(0, 0));
    EXPECT_TRUE(b.is_dispersive());
    Vec3f wo = normalize(Vec3f(0.5f, 0.1f, 0.8f));
    // Transmission: the hero's direction, secondaries dropped.
    auto t = b.sample_f(wo, 0.5f, {}, TransportMode::Radiance, SampleFlags::Transmission);
    ASSERT_TRUE(t);
    EXPECT_TRUE(t->dispersive);
    float expected_t = (1 - fresnel_dielectric(wo.z, eta[0])) / sqr(eta[0]) / std::abs(t->wi.z);
    EXPECT_FLOAT_EQ(t->f[0], expected_t);
    for (int i = 1; i < NumWavelengths; ++i) EXPECT_EQ(t->f[i], 0);
    Vec3f hero_dir;
    float etap;
    ASSERT_TRUE(refract(wo, Vec3f(0, 0, 1), eta[0], &etap, &hero_dir));
    EXPECT_EQ(t->wi, hero_dir);
    // Reflection: the same direction for all wavelengths, each with its own Fresnel term.
    auto r = b.sample_f(wo, 0.5f, {}, TransportMode::Radiance, SampleFlags::Reflection);
    ASSERT_TRUE(r);
    EXPECT_FALSE(r->dispersive);
    for (int i = 0; i < NumWavelengths; ++i)
        EXPECT_FLOAT_EQ(r->f[i] * std::abs(r->wi.z), fresnel_dielectric(wo.z, eta[i]));
    // A constant eta is never dispersive.
    DielectricBxDF plain(SampledSpectrum(1.5f), TrowbridgeReitzDistribution(0, 0));
    EXPECT_FALSE(plain.is_dispersive());
    auto p = plain.sample_f(wo, 0.5f, {}, TransportMode::Radiance, SampleFlags::Transmission);
    EXPECT_FALSE(p->dispersive);
    EXPECT_EQ(p->f[3], p->f[0]);
}

TEST(BxDF, DispersiveRoughDielectric) {
    // However narrow the lobes, rough refraction keeps every wavelength: each lane's f is that
    // wavelength's own BSDF value for the sampled pair, as a single-wavelength BxDF computes it.
    // Sampled as lane k (sample_f_as), the sample's density is lane k's entry of lane_pdf, which
    // holds every lane's (their distributions are checked in chi_square_test.cpp); sample_f's
    // density is their mean, pdf()'s.
    SampledSpectrum eta(1.50f, 1.52f, 1.54f, 1.56f);
    Vec3f wo = normalize(Vec3f(0.5f, 0.1f, 0.8f));
    Rng rng(13, 1);
    for (float alpha : {0.003f, 0.01f, 0.3f}) {
        DielectricBxDF b(eta, TrowbridgeReitzDistribution(alpha, alpha));
        EXPECT_TRUE(b.has_lane_lobes());
        int transmissions = 0;
        for (int n = 0; n < 200; ++n) {
            const int sampling_lane = n % NumWavelengths;
            const float uc = rng.uniform();
            const Vec2f u = rng.uniform2();
            auto s = b.sample_f_as(sampling_lane, wo, uc, u, TransportMode::Radiance);
            if (!s) continue;
            EXPECT_FALSE(s->dispersive);
            ASSERT_TRUE(s->lane_pdf);
            EXPECT_EQ((*s->lane_pdf)[sampling_lane], s->pdf);
            if (s->is_reflection()) continue;
            ++transmissions;
            for (int i = 0; i < NumWavelengths; ++i) {
                DielectricBxDF lane(SampledSpectrum(eta[i]), TrowbridgeReitzDistribution(alpha, alpha));
                expect_relative(s->f[i], lane.f(wo, s->wi, TransportMode::Radiance)[0], 1e-3f, "lane f");
            }
            expect_relative(b.pdf(wo, s->wi, TransportMode::Radiance), s->lane_pdf->average(), 1e-5f, "mean pdf");
            // sample_f draws the lane from uc; its density is the mean.
            auto mixed = b.sample_f(wo, rng.uniform(), rng.uniform2(), TransportMode::Radiance);
            if (mixed) {
                EXPECT_FALSE(mixed->lane_pdf);
                expect_relative(mixed->pdf, b.pdf(wo, mixed->wi, TransportMode::Radiance), 1e-3f, "sample_f pdf");
            }
        }
        EXPECT_GT(transmissions, 100);
    }
    // Smooth, it stays the hero's: one direction per wavelength.
    EXPECT_FALSE(DielectricBxDF(eta, TrowbridgeReitzDistribution(0, 0)).has_lane_lobes());
    // A lane in the index-matched band has a delta lobe: the hero is followed alone.
    EXPECT_FALSE(DielectricBxDF(SampledSpectrum(1.3f, 1.0f, 1.2f, 1.1f), TrowbridgeReitzDistribution(0.3f, 0.3f))
                     .has_lane_lobes());
}

TEST(BxDF, SmoothConductorReflectsFresnel) {
    ConductorBxDF b(TrowbridgeReitzDistribution(0, 0), CuEta, CuK);
    EXPECT_EQ(b.flags(), BxDFSpecularReflection);
    Vec3f wo = normalize(Vec3f(-0.3f, 0.2f, 0.6f));
    auto s = b.sample_f(wo, 0.3f, {0.1f, 0.2f}, TransportMode::Radiance);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->wi, Vec3f(-wo.x, -wo.y, wo.z));
    SampledSpectrum expected = fresnel_conductor(wo.z, CuEta, CuK);
    for (int i = 0; i < NumWavelengths; ++i) EXPECT_FLOAT_EQ(s->f[i] * wo.z / s->pdf, expected[i]);
    EXPECT_TRUE(b.f(wo, s->wi, TransportMode::Radiance).is_black());
    EXPECT_EQ(b.pdf(wo, s->wi, TransportMode::Radiance), 0);
}

TEST(BxDF, ThinDielectricSumsInternalReflections) {
    // Independent check of the closed form: trace the slab's internal bounces explicitly.
    float eta = 1.5f;
    ThinDielectricBxDF b{SampledSpectrum(eta)};
    for (float theta : {0.f, 45.f, 80.f}) {
        float cos_o = std::cos(radians(theta));
        float r = fresnel_dielectric(cos_o, eta), t = 1 - r;
        double reflected = r, inside = t;  // energy travelling inside after entering
        for (int bounce = 0; bounce < 200; ++bounce) {
            // At each inner face the internal reflectance equals r (Stokes); the rest leaves.
            double leaving = inside * (1 - r);
            // Even bounces leave through the far face (transmitted), odd ones through the near
            // face (reflected).
            if (bounce % 2 == 1) reflected += leaving;
            inside *= r;
        }
        EXPECT_NEAR(b.reflectance(cos_o)[0], reflected, 1e-5) << theta;
        // Sampling weights: R' and T' sum to one, and transmission goes straight through.
        auto sr = b.sample_f(Vec3f(std::sqrt(1 - sqr(cos_o)), 0, cos_o), 0, {}, TransportMode::Radiance,
                             SampleFlags::Reflection);
        auto st = b.sample_f(Vec3f(std::sqrt(1 - sqr(cos_o)), 0, cos_o), 0, {}, TransportMode::Radiance,
                             SampleFlags::Transmission);
        ASSERT_TRUE(sr && st);
        EXPECT_NEAR(sr->f[0] * cos_o / sr->pdf + st->f[0] * cos_o / st->pdf, 1, 1e-6f);
        EXPECT_FLOAT_EQ(st->wi.z, -cos_o);
        EXPECT_FALSE(st->dispersive);
    }
}

} // namespace
} // namespace caustica
