// Probe-ray sampling of subsurface exit points (integrators/common/subsurface_probe.h): the mean
// weight must be the profile's integral over the surface within reach, on geometry where that
// integral has a closed form: a plane, two parallel planes (a slab), and a sphere traced through
// the scene's Embree geometry.
#include "core/rng.h"
#include "geometry/sphere.h"
#include "integrators/common/subsurface_probe.h"
#include "materials/dipole_profile.h"
#include "materials/normalized_diffusion.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace caustica {
namespace {

// Materials are compared by identity only.
class ProbeTestMaterial final : public Material {
  public:
    BSDF get_bsdf(const SurfaceInteraction &, const SampledWavelengths &,
                  ScratchBuffer &) const override {
        return {};
    }
};

struct Plane {
    Vec3f point, normal; // unit normal
    const Material *material;
};

SurfaceInteraction plane_interaction(const Plane &plane, Vec3f p) {
    SurfaceInteraction si;
    si.p = p;
    si.n = plane.normal;
    coordinate_system(plane.normal, &si.dpdu, &si.dpdv);
    si.shading.n = plane.normal;
    si.shading.dpdu = si.dpdu;
    si.shading.dpdv = si.dpdv;
    si.material = plane.material;
    return si;
}

// Exact ray/plane intersections: every plane the segment crosses.
ProbeHitGatherer planes_gatherer(std::vector<Plane> planes) {
    return [planes](const Ray &segment, std::vector<SurfaceInteraction> &hits) {
        for (const Plane &plane : planes) {
            float cosine = dot(segment.d, plane.normal);
            if (cosine == 0) continue;
            float t = dot(plane.point - segment.o, plane.normal) / cosine;
            if (t > 0 && t <= segment.t_max) {
                SurfaceInteraction si = plane_interaction(plane, segment.at(t));
                si.t = t;
                si.wo = -segment.d;
                hits.push_back(si);
            }
        }
    };
}

// Mean and standard error of each channel's weight over n probes (failed probes weigh 0).
struct WeightStatistics {
    double mean[NumWavelengths] = {}, standard_error[NumWavelengths] = {};
};
using ProbeFunction =
    std::function<std::optional<SubsurfaceExit>(SubsurfaceProbeSampler &, float, Vec2f)>;
WeightStatistics probe_statistics(const ProbeFunction &sample, int n, uint64_t seed) {
    Rng rng(seed, 3);
    SubsurfaceProbeSampler sampler;
    double sum[NumWavelengths] = {}, sum2[NumWavelengths] = {};
    for (int i = 0; i < n; ++i) {
        float u_strategy = rng.uniform();
        Vec2f u = rng.uniform2();
        std::optional<SubsurfaceExit> exit = sample(sampler, u_strategy, u);
        if (!exit) continue;
        for (int c = 0; c < NumWavelengths; ++c) {
            sum[c] += exit->weight[c];
            sum2[c] += sqr(double(exit->weight[c]));
        }
    }
    WeightStatistics s;
    for (int c = 0; c < NumWavelengths; ++c) {
        s.mean[c] = sum[c] / n;
        s.standard_error[c] = std::sqrt(std::max(0.0, sum2[c] / n - sqr(s.mean[c])) / n);
    }
    return s;
}

WeightStatistics probe_statistics(const SurfaceInteraction &entry, const SubsurfaceProfile &profile,
                                  const ProbeHitGatherer &gather, int n, uint64_t seed) {
    return probe_statistics(
        [&](SubsurfaceProbeSampler &sampler, float u_strategy, Vec2f u) {
            return sampler.sample(entry, profile, u_strategy, u, gather);
        },
        n, seed);
}

// The estimate is unbiased, so it lies within 4 standard errors of the expectation except with
// probability ~6e-5 per channel (the seeds are fixed, so each test is deterministic). The
// standard error itself must be small for the comparison to mean anything.
void expect_unbiased(const WeightStatistics &s, const double expected[NumWavelengths],
                     const char *what) {
    for (int c = 0; c < NumWavelengths; ++c) {
        EXPECT_NEAR(s.mean[c], expected[c], 4 * s.standard_error[c]) << what << " channel " << c;
        EXPECT_LT(s.standard_error[c], 0.01 * std::max(expected[c], 0.05))
            << what << " channel " << c;
    }
}

// Normalized diffusion: energy beyond distance r, e^{-r/d} / 4 + 3 e^{-r/(3d)} / 4 (Burley
// 2015, eq. 5 integrated); a distance-s shell of a plane or sphere has area 2 pi s ds.
double nd_tail(double r, double d) {
    return 0.25 * std::exp(-r / d) + 0.75 * std::exp(-r / (3 * d));
}

const SampledSpectrum Albedo(0.8f, 0.5f, 0.9f, 0.3f);
const SampledSpectrum ScatterDistance(0.01f, 0.03f, 0.05f, 0.02f);

float reach(const SubsurfaceProfile &profile) {
    float r = 0;
    for (int c = 0; c < NumWavelengths; ++c) r = std::max(r, profile.max_radius(c));
    return r;
}

TEST(SubsurfaceProbe, PlaneGivesTheAlbedo) {
    // A tilted plane, entered off the origin: the frame is not axis-aligned.
    ProbeTestMaterial material;
    Plane plane{{0.3f, -0.2f, 0.1f}, normalize(Vec3f{0.2f, -0.3f, 1}), &material};
    SurfaceInteraction entry = plane_interaction(plane, plane.point);
    NormalizedDiffusionProfile profile(Albedo, ScatterDistance);
    ProbeHitGatherer gather = planes_gatherer({plane});
    WeightStatistics s = probe_statistics(entry, profile, gather, 200000, 1);
    // Within reach of the entry: the albedo less the energy beyond the longest reach.
    double expected[NumWavelengths];
    for (int c = 0; c < NumWavelengths; ++c)
        expected[c] = Albedo[c] * (1 - nd_tail(reach(profile), ScatterDistance[c]));
    expect_unbiased(s, expected, "plane");
}

TEST(SubsurfaceProbe, SlabGivesTheIntegralOverBothFaces) {
    // Faces z = 0 (entered) and z = -h. On the far face, the points at planar distance rho are at
    // distance s = sqrt(rho^2 + h^2), and rho drho = s ds, so that face receives
    // 2 pi int_h^reach s R(s) ds = A (tail(h) - tail(reach)). h is within reach of some channels
    // only.
    ProbeTestMaterial material;
    const float h = 0.15f;
    Plane top{{0, 0, 0}, {0, 0, 1}, &material}, bottom{{0, 0, -h}, {0, 0, -1}, &material};
    SurfaceInteraction entry = plane_interaction(top, {0.05f, 0.02f, 0});
    NormalizedDiffusionProfile profile(Albedo, ScatterDistance);
    ProbeHitGatherer gather = planes_gatherer({top, bottom});
    WeightStatistics s = probe_statistics(entry, profile, gather, 200000, 2);
    double r = reach(profile);
    ASSERT_GT(r, h);
    double expected[NumWavelengths];
    for (int c = 0; c < NumWavelengths; ++c) {
        double d = ScatterDistance[c];
        expected[c] = Albedo[c] * ((1 - nd_tail(r, d)) + (nd_tail(h, d) - nd_tail(r, d)));
    }
    expect_unbiased(s, expected, "slab");
    // The far face matters: it holds over 2% of the widest channel's energy.
    EXPECT_GT(nd_tail(h, ScatterDistance[2]), 0.02);
}

TEST(SubsurfaceProbe, OtherMaterialsAreNotExits) {
    // The same slab with a different material on the far face: only the entered face counts.
    ProbeTestMaterial material, other;
    const float h = 0.15f;
    Plane top{{0, 0, 0}, {0, 0, 1}, &material}, bottom{{0, 0, -h}, {0, 0, -1}, &other};
    SurfaceInteraction entry = plane_interaction(top, {0, 0, 0});
    NormalizedDiffusionProfile profile(Albedo, ScatterDistance);
    ProbeHitGatherer gather = planes_gatherer({top, bottom});
    WeightStatistics s = probe_statistics(entry, profile, gather, 200000, 3);
    double expected[NumWavelengths];
    for (int c = 0; c < NumWavelengths; ++c)
        expected[c] = Albedo[c] * (1 - nd_tail(reach(profile), ScatterDistance[c]));
    expect_unbiased(s, expected, "slab of two materials");
}

TEST(SubsurfaceProbe, DipoleOnAPlane) {
    // Skin-like coefficients per mm. The dipole's energy beyond r, from Jensen et al. 2001's
    // profile integrated by hand: (alpha' / 2) sum_poles (z / d) e^{-sigma_tr d},
    // d = sqrt(r^2 + z^2).
    ProbeTestMaterial material;
    Plane plane{{0, 0, 0}, {0, 0, 1}, &material};
    SurfaceInteraction entry = plane_interaction(plane, {0, 0, 0});
    SampledSpectrum sigma_a(0.032f, 0.17f, 0.48f, 0.05f), sigma_s(0.74f, 0.88f, 1.01f, 0.8f);
    const float eta = 1.3f;
    DipoleProfile profile(sigma_a, sigma_s, eta);
    ProbeHitGatherer gather = planes_gatherer({plane});
    WeightStatistics s = probe_statistics(entry, profile, gather, 200000, 4);
    double fdr = -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
    double boundary = (1 + fdr) / (1 - fdr), r = reach(profile);
    double expected[NumWavelengths];
    for (int c = 0; c < NumWavelengths; ++c) {
        double st = sigma_a[c] + sigma_s[c], alpha = sigma_s[c] / st;
        double tr = std::sqrt(3 * sigma_a[c] * st), zr = 1 / st, zv = zr * (1 + 4 * boundary / 3);
        auto beyond = [&](double radius) {
            double dr = std::hypot(radius, zr), dv = std::hypot(radius, zv);
            return alpha / 2 * (zr / dr * std::exp(-tr * dr) + zv / dv * std::exp(-tr * dv));
        };
        expected[c] = beyond(0) - beyond(r);
    }
    expect_unbiased(s, expected, "dipole plane");
}

TEST(SubsurfaceProbe, SphereThroughTheScene) {
    // A unit sphere in Embree, entered at its north pole. By Archimedes' hat-box theorem, the
    // points of a sphere of radius rho at chord distance s from a surface point have area
    // 2 pi s ds for s <= 2 rho, as on a plane, so the surface within reach receives
    // A (1 - tail(min(2 rho, reach))). The profile reaches across the sphere in some channels:
    // probes along the normal cross it twice, tangent probes cut chords.
    ProbeTestMaterial material;
    Scene scene;
    auto sphere = std::make_shared<Sphere>(Transform{}, false, 1.f, -1.f, 1.f, 360.f);
    auto group = std::make_shared<ShapeGroup>();
    group->type = "sphere";
    group->analytic = sphere;
    PrimitiveAttributes attributes;
    attributes.material = &material;
    scene.geometry.add(group, attributes);
    scene.geometry.commit();
    SurfaceInteraction entry;
    ASSERT_TRUE(scene.intersect(Ray{{0, 0, 3}, {0, 0, -1}}, &entry));
    ASSERT_NEAR(entry.p.z, 1, 1e-5);

    SampledSpectrum scatter_distance(0.02f, 0.05f, 0.12f, 0.03f);
    NormalizedDiffusionProfile profile(Albedo, scatter_distance);
    double r = reach(profile);
    ASSERT_GT(r, 2.0); // the widest channel reaches the antipode
    WeightStatistics s = probe_statistics(
        [&](SubsurfaceProbeSampler &sampler, float u_strategy, Vec2f u) {
            return sampler.sample(entry, profile, u_strategy, u, scene);
        },
        100000, 5);
    double expected[NumWavelengths];
    for (int c = 0; c < NumWavelengths; ++c)
        expected[c] = Albedo[c] * (1 - nd_tail(std::min(2.0, r), scatter_distance[c]));
    expect_unbiased(s, expected, "sphere");
}

TEST(SubsurfaceProbe, ChannelsWithoutEnergyAreNeverChosen) {
    // Zero albedo in channel 1 and zero scatter distance (the BRDF limit) in channel 3.
    ProbeTestMaterial material;
    Plane plane{{0, 0, 0}, {0, 0, 1}, &material};
    SurfaceInteraction entry = plane_interaction(plane, {0, 0, 0});
    NormalizedDiffusionProfile profile(SampledSpectrum(0.5f, 0.f, 0.5f, 0.5f),
                                       SampledSpectrum(0.1f, 0.1f, 0.2f, 0.f));
    ProbeHitGatherer gather = planes_gatherer({plane});
    SubsurfaceProbeSampler sampler;
    Rng rng(6, 0);
    for (int i = 0; i < 1000; ++i) {
        auto exit = sampler.sample(entry, profile, rng.uniform(), rng.uniform2(), gather);
        if (!exit) continue;
        EXPECT_TRUE(exit->channel == 0 || exit->channel == 2);
        EXPECT_EQ(exit->weight[1], 0.f);
        EXPECT_EQ(exit->weight[3], 0.f);
        EXPECT_EQ(exit->candidates, 1);
    }
}

} // namespace
} // namespace caustica
