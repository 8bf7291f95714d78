// Subsurface scattering profiles (normalized diffusion, the dipole) and the medium coefficients:
// integrals against the papers' closed forms, sampling against the pdf (Kolmogorov-Smirnov), the
// limits, and a volumetric random walk that checks the (albedo, scatterDistance) mapping against
// the physics it claims to reproduce.
#include "core/rng.h"
#include "core/sampling.h"
#include "materials/dipole_profile.h"
#include "materials/fresnel.h"
#include "materials/normalized_diffusion.h"
#include "materials/random_walk_albedo.h"
#include "materials/subsurface_coefficients.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace caustica {
namespace {

// int_0^r_end f(r) dr by composite Simpson in t, where r = scale t / (1 - t) maps [0, inf) onto
// [0, 1): the grid is fine near r = 0 (where the profiles are steep) and reaches any radius, so
// one rule serves profiles of any width and tails of any length.
double integrate_radial(const std::function<double(double)> &f, double scale,
                        double r_end = INFINITY, int intervals = 40000) {
    double t_end = std::isinf(r_end) ? 1 - 1e-9 : r_end / (r_end + scale);
    double h = t_end / intervals, sum = 0;
    for (int i = 0; i <= intervals; ++i) {
        double t = i * h;
        double r = scale * t / (1 - t), drdt = scale / sqr(1 - t);
        double w = (i == 0 || i == intervals) ? 1 : (i % 2 ? 4 : 2);
        sum += w * f(r) * drdt;
    }
    return sum * h / 3;
}

// The radial density 2 pi r pdf_area(r) of one channel.
std::function<double(double)> radial_pdf(const SubsurfaceProfile &profile, int c) {
    return [&profile, c](double r) { return 2 * Pi * r * profile.pdf_area(float(r))[c]; };
}
std::function<double(double)> radial_profile(const SubsurfaceProfile &profile, int c) {
    return [&profile, c](double r) { return 2 * Pi * r * profile.evaluate(float(r))[c]; };
}

// Kolmogorov-Smirnov distance between radii drawn by sample_radius() and the CDF obtained by
// integrating pdf_area() numerically (cumulative trapezoid on the same t grid as above).
double ks_distance(const SubsurfaceProfile &profile, int c, double scale, int n, uint64_t seed) {
    const int grid = 100000;
    std::vector<double> radii(grid + 1), cdf(grid + 1);
    auto density = radial_pdf(profile, c);
    double h = (1 - 1e-9) / grid, previous = 0;
    for (int i = 0; i <= grid; ++i) {
        double t = i * h;
        radii[i] = scale * t / (1 - t);
        double value = density(radii[i]) * scale / sqr(1 - t);
        cdf[i] = i == 0 ? 0 : cdf[i - 1] + 0.5 * h * (value + previous);
        previous = value;
    }
    auto cdf_at = [&](double r) {
        size_t i = std::upper_bound(radii.begin(), radii.end(), r) - radii.begin();
        if (i == 0) return 0.0;
        if (i > size_t(grid)) return cdf[grid];
        double f = (r - radii[i - 1]) / (radii[i] - radii[i - 1]);
        return cdf[i - 1] + f * (cdf[i] - cdf[i - 1]);
    };
    Rng rng(seed, 0);
    std::vector<double> samples(n);
    for (double &s : samples) s = profile.sample_radius(c, rng.uniform());
    std::sort(samples.begin(), samples.end());
    double d = 0;
    for (int i = 0; i < n; ++i) {
        double f = cdf_at(samples[i]);
        d = std::max({d, std::abs(f - double(i) / n), std::abs(f - double(i + 1) / n)});
    }
    return d;
}
// The distance exceeds 1.949 / sqrt(n) with probability 0.001 when the samples follow the CDF
// (the Kolmogorov distribution's 99.9% quantile; the seeds are fixed, so the tests are
// deterministic, and a wrong sampler or pdf fails by a wide margin).
double ks_bound(int n) { return 1.949 / std::sqrt(double(n)); }

// ---------------------------------------------------------------- normalized diffusion

const SampledSpectrum NdAlbedo(0.8f, 0.5f, 0.2f, 1.0f);
const SampledSpectrum NdDistance(0.1f, 1.0f, 3.0f, 0.01f);

// Energy beyond r of eq. 5 times 2 pi r, integrated by hand: e^{-r/d} / 4 + 3 e^{-r/(3d)} / 4.
double nd_tail(double r, double d) {
    return 0.25 * std::exp(-r / d) + 0.75 * std::exp(-r / (3 * d));
}

TEST(NormalizedDiffusion, IntegratesToTheAlbedo) {
    // Eq. 6: 2 pi int r R(r) dr = A exactly. The numerical rule is exact to ~1e-14 here; the
    // profile is evaluated in float (relative error ~1e-7 per value).
    NormalizedDiffusionProfile profile(NdAlbedo, NdDistance);
    for (int c = 0; c < NumWavelengths; ++c) {
        double integral = integrate_radial(radial_profile(profile, c), NdDistance[c]);
        EXPECT_NEAR(integral, NdAlbedo[c], 1e-5 * NdAlbedo[c]) << "channel " << c;
        EXPECT_FLOAT_EQ(profile.albedo()[c], NdAlbedo[c]);
    }
}

TEST(NormalizedDiffusion, PdfIsTheNormalisedProfile) {
    NormalizedDiffusionProfile profile(NdAlbedo, NdDistance);
    for (int c = 0; c < NumWavelengths; ++c) {
        EXPECT_NEAR(integrate_radial(radial_pdf(profile, c), NdDistance[c]), 1, 1e-5);
        for (float r : {1e-4f, 0.01f, 0.3f, 2.f, 10.f}) {
            float value = profile.evaluate(r)[c], pdf = profile.pdf_area(r)[c];
            EXPECT_NEAR(value, NdAlbedo[c] * pdf, 1e-6f * value) << "channel " << c << " r " << r;
        }
    }
}

TEST(NormalizedDiffusion, SamplingMatchesThePdf) {
    NormalizedDiffusionProfile profile(NdAlbedo, NdDistance);
    const int n = 20000;
    for (int c = 0; c < NumWavelengths; ++c)
        EXPECT_LT(ks_distance(profile, c, NdDistance[c], n, 11 + c), ks_bound(n))
            << "channel " << c;
}

TEST(NormalizedDiffusion, SamplingInvertsTheClosedFormCdf) {
    // The sampled radius for u is where the energy beyond it (closed form above) is 1 - u.
    NormalizedDiffusionProfile profile(NdAlbedo, NdDistance);
    for (int c = 0; c < NumWavelengths; ++c)
        for (float u : {0.f, 0.01f, 0.25f, 0.5f, 0.9f, 0.999f, OneMinusEpsilon}) {
            double r = profile.sample_radius(c, u);
            EXPECT_NEAR(nd_tail(r, NdDistance[c]), 1 - double(u), 2e-6)
                << "channel " << c << " u " << u;
        }
}

TEST(NormalizedDiffusion, MaxRadiusHoldsTheStatedEnergy) {
    NormalizedDiffusionProfile profile(NdAlbedo, NdDistance);
    for (int c = 0; c < NumWavelengths; ++c) {
        double r_max = profile.max_radius(c);
        double inside = integrate_radial(radial_profile(profile, c), NdDistance[c], r_max);
        EXPECT_NEAR(inside, ProfileEnergyWithinMaxRadius * NdAlbedo[c], 1e-5) << "channel " << c;
    }
}

TEST(NormalizedDiffusion, VanishingScatterDistanceConcentratesAtTheEntryPoint) {
    // As d -> 0 the profile tends to a delta at r = 0 (the BRDF limit, Burley 2015 Fig. 11):
    // 99% of the energy lies within 14 d (closed form: the tail at 14 d is 0.0071), so within
    // 1e-4 for d <= 7e-6, and the probe radius shrinks with d.
    SampledSpectrum albedo(0.9f, 0.6f, 0.3f, 0.7f);
    for (float d : {5e-6f, 1e-7f}) {
        NormalizedDiffusionProfile profile(albedo, SampledSpectrum(d));
        for (int c = 0; c < NumWavelengths; ++c) {
            double inside = integrate_radial(radial_profile(profile, c), d, 1e-4);
            EXPECT_GT(inside, 0.99 * albedo[c]) << "d " << d << " channel " << c;
            EXPECT_LT(profile.max_radius(c), 25 * d);
        }
    }
}

TEST(NormalizedDiffusion, ZeroScatterDistanceIsLeftToTheBrdf) {
    NormalizedDiffusionProfile profile(SampledSpectrum(0.5f),
                                       SampledSpectrum(0.2f, 0.f, 0.2f, 0.2f));
    EXPECT_EQ(profile.max_radius(1), 0.f);
    EXPECT_EQ(profile.albedo()[1], 0.f);
    EXPECT_EQ(profile.evaluate(0.01f)[1], 0.f);
    EXPECT_GT(profile.evaluate(0.01f)[0], 0.f);
    EXPECT_GT(profile.max_radius(0), 0.f);
}

// ---------------------------------------------------------------- dipole

// Jensen et al. 2001's total diffuse reflectance, written out here from the paper:
// R_d = (alpha' / 2) (1 + e^{-(4/3) A sqrt(3 (1 - alpha'))}) e^{-sqrt(3 (1 - alpha'))}.
double jensen_total_reflectance(double sigma_a, double sigma_s_reduced, double eta) {
    double fdr = -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
    double a = (1 + fdr) / (1 - fdr);
    double alpha = sigma_s_reduced / (sigma_a + sigma_s_reduced);
    double root = std::sqrt(3 * (1 - alpha));
    return alpha / 2 * (1 + std::exp(-4.0 / 3.0 * a * root)) * std::exp(-root);
}

DipoleProfile dipole_of(const MeasuredSubsurfaceMedium &m) {
    // Channels r, g, b and r again.
    return DipoleProfile(SampledSpectrum(m.sigma_a.r, m.sigma_a.g, m.sigma_a.b, m.sigma_a.r),
                         SampledSpectrum(m.sigma_s_reduced.r, m.sigma_s_reduced.g,
                                         m.sigma_s_reduced.b, m.sigma_s_reduced.r),
                         m.eta);
}

TEST(Dipole, IntegratesToJensensTotalDiffuseReflectance) {
    // Every measured medium of Jensen's table, every band: the numerical integral of the profile
    // over the plane (the rule is exact to ~3e-9 even for spectralon's 1 / r^2 tail) against the
    // closed form.
    for (const MeasuredSubsurfaceMedium &m : measured_subsurface_media()) {
        DipoleProfile profile = dipole_of(m);
        for (int c = 0; c < 3; ++c) {
            double expected = jensen_total_reflectance(m.sigma_a[c], m.sigma_s_reduced[c], m.eta);
            double scale = 1 / (m.sigma_a[c] + m.sigma_s_reduced[c]);
            double integral = integrate_radial(radial_profile(profile, c), scale);
            EXPECT_NEAR(integral, expected, 1e-4 * expected) << m.name << " band " << c;
            EXPECT_NEAR(profile.albedo()[c], expected, 1e-6) << m.name << " band " << c;
        }
    }
}

TEST(Dipole, NonAbsorbingMediumReflectsEverything) {
    // Spectralon has sigma_a = 0: alpha' = 1 and the closed form gives R_d = 1.
    DipoleProfile profile = dipole_of(*find_measured_subsurface_medium("spectralon"));
    for (int c = 0; c < NumWavelengths; ++c) EXPECT_NEAR(profile.albedo()[c], 1, 1e-6);
}

TEST(Dipole, SamplingMatchesThePdf) {
    const int n = 20000;
    for (const char *name : {"skin1", "marble", "ketchup", "spectralon"}) {
        const MeasuredSubsurfaceMedium m = *find_measured_subsurface_medium(name);
        DipoleProfile profile = dipole_of(m);
        for (int c = 0; c < 3; ++c) {
            double scale = 1 / (m.sigma_a[c] + m.sigma_s_reduced[c]);
            EXPECT_NEAR(integrate_radial(radial_pdf(profile, c), scale), 1, 1e-4)
                << name << " band " << c;
            EXPECT_LT(ks_distance(profile, c, scale, n, 100 + c), ks_bound(n))
                << name << " band " << c;
        }
    }
}

TEST(Dipole, MaxRadiusHoldsTheStatedEnergy) {
    for (const char *name : {"skin1", "apple", "cream"}) {
        const MeasuredSubsurfaceMedium m = *find_measured_subsurface_medium(name);
        DipoleProfile profile = dipole_of(m);
        for (int c = 0; c < 3; ++c) {
            double scale = 1 / (m.sigma_a[c] + m.sigma_s_reduced[c]);
            double inside =
                integrate_radial(radial_profile(profile, c), scale, profile.max_radius(c));
            EXPECT_NEAR(inside / profile.albedo()[c], ProfileEnergyWithinMaxRadius, 1e-5)
                << name << " band " << c;
        }
    }
}

TEST(Dipole, ChannelWithoutScatteringIsEmpty) {
    DipoleProfile profile(SampledSpectrum(0.1f), SampledSpectrum(1.f, 0.f, 1.f, 1.f), 1.3f);
    EXPECT_EQ(profile.albedo()[1], 0.f);
    EXPECT_EQ(profile.max_radius(1), 0.f);
    EXPECT_EQ(profile.evaluate(0.5f)[1], 0.f);
    EXPECT_GT(profile.albedo()[0], 0.f);
}

TEST(Dipole, DiffuseFresnelFitMatchesTheFresnelEquations) {
    // F_dr is the cosine-weighted hemispherical average of the exact Fresnel reflectance for light
    // inside the medium: int_0^1 F(-mu) d(mu^2), midpoint rule in mu^2 (the integrand has a kink
    // at the critical angle, so 1e5 points give ~1e-6). Egan and Hilgeman's fit is good to
    // about 1e-3 over this range; the bound allows 3e-3.
    for (float eta : {1.1f, 1.3f, 1.5f, 2.0f}) {
        const int n = 100000;
        double sum = 0;
        for (int i = 0; i < n; ++i) sum += fresnel_dielectric(-std::sqrt((i + 0.5f) / n), eta);
        EXPECT_NEAR(diffuse_fresnel_reflectance(eta), sum / n, 3e-3) << "eta " << eta;
    }
}

// ---------------------------------------------------------------- coefficients

TEST(SubsurfaceCoefficients, ChristensenBurleyScaling) {
    // The fit's values at its anchor: s(0.8) = 1.1; and it stays positive on [0, 1].
    EXPECT_NEAR(christensen_burley_scaling(0.8f), 1.1f, 1e-6f);
    for (int i = 0; i <= 100; ++i) EXPECT_GT(christensen_burley_scaling(i / 100.f), 0.9f);
}

// Isotropic random walk in the half-space z < 0 with the mapped coefficients, under the Disney
// material's boundary (disney_bxdf.h): entered at the origin in a cosine-distributed direction
// (diffuse surface transmission), leaving with probability 41/42 where it reaches the surface and
// reflected back in, cosine-distributed, otherwise. The fraction of walks that leave, and their
// exit radii.
struct WalkResult {
    double reflectance = 0;
    std::vector<double> exit_radii;
};
WalkResult random_walk(float sigma_s, float sigma_a, int walks, uint64_t seed) {
    Rng rng(seed, 7);
    float sigma_t = sigma_s + sigma_a, alpha = sigma_s / sigma_t;
    WalkResult result;
    for (int i = 0; i < walks; ++i) {
        Vec3f p{0, 0, 0};
        Vec3f w = sample_cosine_hemisphere(rng.uniform2());
        w.z = -w.z;
        while (true) {
            float t = -std::log(1 - rng.uniform()) / sigma_t;
            Vec3f next = p + w * t;
            if (next.z >= 0) {
                Vec3f exit = p + w * (-p.z / w.z);
                if (rng.uniform() < 41.f / 42) {
                    result.exit_radii.push_back(std::hypot(exit.x, exit.y));
                    break;
                }
                p = exit;
                w = sample_cosine_hemisphere(rng.uniform2());
                w.z = -w.z;
                continue;
            }
            p = next;
            if (rng.uniform() >= alpha) break; // absorbed
            w = sample_uniform_sphere(rng.uniform2());
        }
    }
    result.reflectance = double(result.exit_radii.size()) / walks;
    return result;
}

TEST(SubsurfaceCoefficients, RandomWalkReproducesAlbedoAndProfileScale) {
    // The Disney material's mapping (random_walk_albedo.h) claims that the walk reflects
    // A 41/42 in total (what the BRDF's Lambertian part reflects; exact up to the table's
    // Monte Carlo error, < 4e-4, and its interpolation) and that its exit radii follow the
    // normalized diffusion profile of scale d (Christensen and Burley's fit, which places the
    // median exit radius within about 2% of the profile's CDF). Bounds: 4 binomial standard
    // errors (<= 0.0063 for 1e5 walks) plus the approximation's error: 0.003 for the albedo;
    // 0.05 for the fraction of exits within the profile's median radius.
    const float d = 1;
    for (float a : {0.2f, 0.5f, 0.8f}) {
        float sigma_t = 1 / random_walk_mean_free_path(d, a);
        float alpha = random_walk_single_scattering_albedo(a * 41 / 42);
        WalkResult walk = random_walk(alpha * sigma_t, (1 - alpha) * sigma_t, 100000, uint64_t(a * 100));
        EXPECT_NEAR(walk.reflectance, a * 41 / 42, 0.0063 + 0.003) << "A " << a;
        // Median of the normalized diffusion profile: nd_tail(r) = 0.5, by bisection.
        double lo = 0, hi = 20 * d;
        for (int i = 0; i < 100; ++i)
            ((nd_tail(0.5 * (lo + hi), d) > 0.5) ? lo : hi) = 0.5 * (lo + hi);
        double median = 0.5 * (lo + hi);
        double within = std::count_if(walk.exit_radii.begin(), walk.exit_radii.end(),
                                      [&](double r) { return r < median; });
        EXPECT_NEAR(within / walk.exit_radii.size(), 0.5, 0.05) << "A " << a;
    }
}

TEST(SubsurfaceCoefficients, MeasuredMediaByName) {
    for (const char *name : {"apple", "chicken1", "chicken2", "cream", "ketchup", "marble",
                             "potato", "skimmilk", "skin1", "skin2", "spectralon", "wholemilk"}) {
        auto m = find_measured_subsurface_medium(name);
        ASSERT_TRUE(m) << name;
        EXPECT_EQ(m->eta, 1.3f);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GT(m->sigma_s_reduced[c], 0) << name;
            EXPECT_GE(m->sigma_a[c], 0) << name;
        }
    }
    EXPECT_TRUE(find_measured_subsurface_medium("Skin1"));
    EXPECT_TRUE(find_measured_subsurface_medium("WholeMilk"));
    EXPECT_FALSE(find_measured_subsurface_medium("skin3"));
    EXPECT_EQ(measured_subsurface_media().size(), 12u);
}

} // namespace
} // namespace caustica
