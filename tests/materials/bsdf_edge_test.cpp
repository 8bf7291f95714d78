// BxDF-level numerical stress tests (issue #7): every BxDF over a grid of edge cases -- grazing
// directions (cos theta down to 1e-7, both hemispheres, axis-aligned and generic azimuths),
// relative indices exactly 1, 1 +/- 1e-6 and far from 1 on both sides, GGX alphas from 1e-4 to
// 1 plus anisotropic pairs, both transport modes, and sample_f's uniform inputs including 0 and
// the largest float below 1. A value that is not finite or is negative is a bug at its source
// (the integrator-level suite, tests/integrators/numerical_stress_test.cpp, only sees the
// dropped samples), and so is a single-sample weight f |cos| / pdf above the lobe's bound.
#include <gtest/gtest.h>

#include <functional>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/rng.h"
#include "materials/conductor_bxdf.h"
#include "materials/dielectric_bxdf.h"
#include "materials/diffuse_bxdf.h"
#include "materials/disney_bxdf.h"
#include "materials/fresnel.h"
#include "materials/thin_dielectric_bxdf.h"

namespace caustica {
namespace {

// ---------------------------------------------------------------------------------------------
// The grid.

constexpr float EdgeCosines[] = {1e-7f, 1e-6f, 1e-4f, 0.01f, 0.5f};

// Azimuths as (cos phi, sin phi): the two axes exactly (where anisotropic lobes are narrowest
// and widest, and where one coordinate is exactly zero) and three generic angles.
std::vector<Vec2f> edge_azimuths() {
    std::vector<Vec2f> a = {{1, 0}, {0, 1}};
    for (double phi : {0.7, 2.9, 4.4}) a.push_back({float(std::cos(phi)), float(std::sin(phi))});
    return a;
}

// Directions with |cos theta| in EdgeCosines (sin theta computed in double so that it keeps the
// precision float cannot give 1 - cos^2 near 1), at every azimuth, in both hemispheres; plus the
// two normals (cos theta = +/-1).
std::vector<Vec3f> edge_directions() {
    std::vector<Vec3f> dirs = {{0, 0, 1}, {0, 0, -1}};
    for (float c : EdgeCosines) {
        float s = float(std::sqrt(1 - double(c) * double(c)));
        for (Vec2f phi : edge_azimuths())
            for (float sign : {1.f, -1.f}) dirs.push_back({s * phi.x, s * phi.y, sign * c});
    }
    return dirs;
}

// Uniform sample values: both ends of [0, 1) and interior points.
constexpr float EdgeUniforms[] = {0, 0.25f, 0.5f, OneMinusEpsilon};
constexpr float LobeUniforms[] = {0, 0.3f, 0.7f, OneMinusEpsilon};

// Relative indices (inside over outside): exactly 1, a millionth either side of 1 (inside the
// index-matched band of DielectricBxDF), just outside the band on both sides, and glass and
// diamond with the dense side inside or outside.
std::vector<float> edge_etas() {
    return {1, 1 + 1e-6f, 1 - 1e-6f, 1.0002f, 0.9998f, 1.5f, 1 / 1.5f, 2.4f};
}

// GGX alphas: smooth, below the smooth threshold (1e-4), at it (1e-3), up to 1, and anisotropic
// pairs up to the extreme aspect 1e-4 : 1 (one of them with a zero alpha, floored inside the
// distribution).
std::vector<std::pair<float, float>> edge_alphas() {
    return {{0, 0}, {1e-4f, 1e-4f}, {1e-3f, 1e-3f}, {0.01f, 0.01f}, {0.1f, 0.1f}, {0.5f, 0.5f},
            {1, 1}, {1e-4f, 1},     {1, 1e-4f},     {0.01f, 0.5f},  {0, 0.3f},    {1e-3f, 2e-3f}};
}

// Dispersive indices: glass over the visible range with the hero at either end, two that cross
// 1 (as an index-matching liquid's does) with the hero inside and outside the index-matched
// band, and a hero just outside the band with the other lanes far from 1 (the hero barely
// reflects while they do).
std::vector<SampledSpectrum> dispersive_etas() {
    return {SampledSpectrum(1.50f, 1.52f, 1.54f, 1.56f),
            SampledSpectrum(1.56f, 1.54f, 1.52f, 1.50f),
            SampledSpectrum(1.0f, 1.0002f, 0.9998f, 1.0005f),
            SampledSpectrum(1.0002f, 1.0f, 1.0005f, 0.99999f),
            SampledSpectrum(1.001f, 1.2f, 1.5f, 2.4f)};
}

std::string describe(Vec3f w) {
    std::ostringstream s;
    s << std::setprecision(9) << "(" << w.x << ", " << w.y << ", " << w.z << ")";
    return s.str();
}
const char *describe(TransportMode mode) {
    return mode == TransportMode::Radiance ? "radiance" : "importance";
}
const char *describe(SampleFlags flags) {
    return flags == SampleFlags::All ? "all" : flags == SampleFlags::Reflection ? "R" : "T";
}

// ---------------------------------------------------------------------------------------------
// The checks.

// Largest allowed f[lane] |cos wi| / pdf for a sample of wo; each BxDF family states its own.
using WeightBound =
    std::function<float(Vec3f wo, const BSDFSample &s, TransportMode mode, int lane)>;

struct EdgeCase {
    std::string name;
    std::shared_ptr<const BxDF> bxdf;
    WeightBound bound;
};

// Collects one BxDF's failures, reporting the first few in full.
class Reporter {
  public:
    explicit Reporter(std::string name) : name_(std::move(name)) {}
    ~Reporter() {
        if (failures_ > MaxReported)
            ADD_FAILURE() << name_ << ": " << failures_ << " failures in total";
    }
    void fail(const std::string &message) {
        if (++failures_ <= MaxReported) ADD_FAILURE() << name_ << ": " << message;
    }

  private:
    static constexpr int MaxReported = 6;
    std::string name_;
    int failures_ = 0;
};

bool finite_non_negative(const SampledSpectrum &s) {
    for (int i = 0; i < NumWavelengths; ++i)
        if (!std::isfinite(s[i]) || s[i] < 0) return false;
    return true;
}

// Float rounding allowance on the weight bounds: the weights are ratios of a handful of float
// operations on both sides, each within a few ulps.
constexpr float BoundRounding = 1e-4f;

// Directions a few ulps to 1e-4 away from the mirror direction of wo, from -wo and from wo: the
// pairs whose half vectors are differences of nearly opposite vectors (for grazing wo the
// mirror direction is nearly -wo too), where rounding decides orientations and signs.
std::vector<Vec3f> near_singular_directions(Vec3f wo) {
    std::vector<Vec3f> dirs;
    for (Vec3f base : {Vec3f(-wo.x, -wo.y, wo.z), -wo, wo})
        for (Vec3f delta :
             {Vec3f(2e-7f, -3e-7f, 1e-7f), Vec3f(-1e-6f, 1e-6f, -2e-5f), Vec3f(5e-6f, 0, 1e-4f)}) {
            Vec3f w = base + delta;
            if (w.z != 0) dirs.push_back(normalize(w));
        }
    return dirs;
}

// f and pdf at every pair of grid directions, and at the near-singular pairs.
void check_evaluation(const EdgeCase &c, Reporter &report) {
    std::vector<Vec3f> dirs = edge_directions();
    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance})
        for (Vec3f wo : dirs) {
            std::vector<Vec3f> wis = dirs, near = near_singular_directions(wo);
            wis.insert(wis.end(), near.begin(), near.end());
            for (Vec3f wi : wis) {
                SampledSpectrum f = c.bxdf->f(wo, wi, mode);
                if (!finite_non_negative(f))
                    report.fail("f not finite and >= 0 at wo " + describe(wo) + " wi " +
                                describe(wi) + " " + describe(mode) + ": " + std::to_string(f[0]) +
                                " ...");
                for (SampleFlags flags :
                     {SampleFlags::All, SampleFlags::Reflection, SampleFlags::Transmission}) {
                    float pdf = c.bxdf->pdf(wo, wi, mode, flags);
                    if (!std::isfinite(pdf) || pdf < 0)
                        report.fail("pdf " + std::to_string(pdf) + " at wo " + describe(wo) +
                                    " wi " + describe(wi) + " " + describe(mode) + " " +
                                    describe(flags));
                }
            }
        }
}

// Every lane's weight f_i |cos| / pdf within the case's bound.
template <typename Context>
bool check_weights(const EdgeCase &c, Vec3f wo, const BSDFSample &s, float pdf, TransportMode mode, Reporter &report,
                   const Context &at) {
    for (int lane = 0; lane < NumWavelengths; ++lane) {
        float weight = s.f[lane] * std::abs(s.wi.z) / pdf;
        float bound = c.bound(wo, s, mode, lane) * (1 + BoundRounding);
        if (!std::isfinite(weight) || weight > bound) {
            report.fail("weight " + std::to_string(weight) + " of lane " + std::to_string(lane) +
                        " above its bound " + std::to_string(bound) + at());
            return false;
        }
    }
    return true;
}

// Sampling as each lane of a BxDF with lane lobes (sample_f_as): the lanes' densities are finite,
// the sampling lane's is the sample's pdf, and each lane's weight over the lanes' mean density,
// the spectral MIS's (integrators/common/spectral_mis.h), is within the bound.
void check_lane_samples(const EdgeCase &c, Vec3f wo, float uc, Vec2f u, TransportMode mode, Reporter &report) {
    for (int sampling_lane = 0; sampling_lane < NumWavelengths; ++sampling_lane) {
        std::optional<BSDFSample> s = c.bxdf->sample_f_as(sampling_lane, wo, uc, u, mode);
        if (!s) continue;
        auto at = [&] {
            std::ostringstream where;
            where << std::setprecision(9) << " sampling as lane " << sampling_lane << " for wo " << describe(wo)
                  << " uc " << uc << " u (" << u.x << ", " << u.y << ") " << describe(mode) << ": wi "
                  << describe(s->wi);
            return where.str();
        };
        if (!s->lane_pdf) return report.fail("no lane densities" + at());
        if (!finite_non_negative(*s->lane_pdf) || (*s->lane_pdf)[sampling_lane] != s->pdf || !(s->pdf > 0))
            return report.fail("lane densities not finite, or not the sample's own" + at());
        if (!check_weights(c, wo, *s, s->lane_pdf->average(), mode, report, at)) return;
    }
}

// One sample's checks.
void check_sample(const EdgeCase &c, Vec3f wo, float uc, Vec2f u, TransportMode mode,
                  SampleFlags flags, Reporter &report) {
    if (flags == SampleFlags::All && c.bxdf->has_lane_lobes()) check_lane_samples(c, wo, uc, u, mode, report);
    std::optional<BSDFSample> s = c.bxdf->sample_f(wo, uc, u, mode, flags);
    if (!s) return;
    // The failure's context, built only when needed (the grid has millions of samples).
    auto at = [&] {
        std::ostringstream where;
        where << std::setprecision(9) << " for wo " << describe(wo) << " uc " << uc << " u (" << u.x
              << ", " << u.y << ") " << describe(mode) << " flags " << describe(flags) << ": wi "
              << describe(s->wi) << " pdf " << s->pdf << " f " << s->f[0] << " " << s->f[1] << " "
              << s->f[2] << " " << s->f[3];
        return where.str();
    };
    if (!is_finite(s->wi) || std::abs(length(s->wi) - 1) > 1e-5f)
        return report.fail("direction not unit" + at());
    if (!std::isfinite(s->pdf) || !(s->pdf > 0))
        return report.fail("pdf not finite and > 0" + at());
    if (!finite_non_negative(s->f)) return report.fail("f not finite and >= 0" + at());
    if (!std::isfinite(s->eta) || !(s->eta > 0))
        return report.fail("eta not finite and > 0" + at());
    // The sample's flags name one lobe the BxDF has, on the side of the surface wi is on.
    unsigned lobe = s->flags;
    if ((lobe & ~unsigned(c.bxdf->flags())) || is_reflective(lobe) == is_transmissive(lobe))
        return report.fail("flags " + std::to_string(lobe) + " not one of the BxDF's lobes" + at());
    bool same_side = s->wi.z != 0 && (s->wi.z > 0) == (wo.z > 0);
    bool other_side = s->wi.z != 0 && (s->wi.z > 0) != (wo.z > 0);
    if (s->is_reflection() ? !same_side : !other_side)
        return report.fail("direction on the wrong side for its lobe" + at());
    if (!allows(flags, s->is_reflection() ? SampleFlags::Reflection : SampleFlags::Transmission))
        return report.fail("lobe not allowed by the sample flags" + at());
    // A sample that terminates the secondary wavelengths carries the hero alone.
    if (s->dispersive && (s->f[1] != 0 || s->f[2] != 0 || s->f[3] != 0))
        return report.fail("dispersive sample with non-zero secondary lanes" + at());
    if (!check_weights(c, wo, *s, s->pdf, mode, report, at)) return;
    // Multiple importance sampling evaluates pdf() at the directions sample_f returns: for a
    // non-delta sample it must be positive and finite there. (It need not equal the sample's pdf
    // exactly: at grazing angles the float wi keeps the sampled facet's tilt only to about 1%.)
    if (!s->is_specular()) {
        float pdf = c.bxdf->pdf(wo, s->wi, mode, flags);
        if (!std::isfinite(pdf) || !(pdf > 0))
            return report.fail("pdf() " + std::to_string(pdf) + " at a sampled direction" + at());
    }
}

// sample_f at every grid direction: all combinations of the edge uniforms, the restricted
// sample flags, and a few interior points from a fixed seed.
void check_sampling(const EdgeCase &c, Reporter &report) {
    Rng rng(0x1dea, 7);
    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance})
        for (Vec3f wo : edge_directions()) {
            for (float uc : LobeUniforms)
                for (float u0 : EdgeUniforms)
                    for (float u1 : EdgeUniforms)
                        check_sample(c, wo, uc, {u0, u1}, mode, SampleFlags::All, report);
            for (SampleFlags flags : {SampleFlags::Reflection, SampleFlags::Transmission})
                for (float u0 : EdgeUniforms)
                    for (float u1 : EdgeUniforms)
                        check_sample(c, wo, 0.5f, {u0, u1}, mode, flags, report);
            for (int n = 0; n < 16; ++n)
                check_sample(c, wo, rng.uniform(), rng.uniform2(), mode, SampleFlags::All, report);
        }
}

void check_all(const std::vector<EdgeCase> &cases) {
    for (const EdgeCase &c : cases) {
        Reporter report(c.name);
        check_evaluation(c, report);
        check_sampling(c, report);
    }
}

// ---------------------------------------------------------------------------------------------
// The BxDFs.

std::string alpha_name(std::pair<float, float> a) {
    std::ostringstream s;
    s << "alpha " << a.first << "," << a.second;
    return s.str();
}

// Relative index across the boundary for a transmission leaving wo's side (inside over outside
// for light from outside), 1 for an invisible interface.
float expected_etap(Vec3f wo, float eta) { return wo.z > 0 ? eta : 1 / eta; }

TEST(BxDFEdges, Diffuse) {
    // Cosine-weighted sampling of a Lambertian lobe gives every sample the weight R (<= 1 after
    // the constructor's clamp), exactly.
    std::vector<EdgeCase> cases;
    for (SampledSpectrum r : {SampledSpectrum(1), SampledSpectrum(0.5f), SampledSpectrum(0),
                              SampledSpectrum(0.3f, 0.6f, 1.4f, -0.2f)})
        cases.push_back({"diffuse R " + std::to_string(r[0]), std::make_shared<DiffuseBxDF>(r),
                         [](Vec3f, const BSDFSample &, TransportMode, int) { return 1.f; }});
    check_all(cases);
}

TEST(BxDFEdges, Conductor) {
    // Bound 1: a smooth mirror's weight is F; a rough one's is F G(wo, wi) / G1(wo) with visible-
    // normal sampling (Heitz 2018, section 2), and both F <= 1 (the complex Fresnel reflectance)
    // and G <= G1 (the height-correlated G = 1 / (1 + Lambda_o + Lambda_i), Lambda >= 0).
    std::vector<std::pair<SampledSpectrum, SampledSpectrum>> indices = {
        {SampledSpectrum(0.27f, 0.68f, 1.1f, 1.2f),
         SampledSpectrum(3.6f, 2.6f, 2.5f, 2.3f)},        // copper
        {SampledSpectrum(0.05f), SampledSpectrum(6)},     // silver-like
        {SampledSpectrum(1), SampledSpectrum(0)},         // no interface: black
        {SampledSpectrum(1 / 1.5f), SampledSpectrum(0)},  // total reflection beyond 41.8 degrees
        {SampledSpectrum(2.4f), SampledSpectrum(0)}};
    std::vector<EdgeCase> cases;
    for (auto [eta, k] : indices)
        for (auto a : edge_alphas()) {
            std::ostringstream name;
            name << "conductor eta " << eta[0] << " k " << k[0] << " " << alpha_name(a);
            cases.push_back({name.str(),
                             std::make_shared<ConductorBxDF>(
                                 TrowbridgeReitzDistribution(a.first, a.second), eta, k),
                             [](Vec3f, const BSDFSample &, TransportMode, int) { return 1.f; }});
        }
    check_all(cases);
}

TEST(BxDFEdges, Dielectric) {
    // In Importance mode the bound is 1: the smooth interface picks reflection or refraction
    // with probability R or T and weighs it by R or T (weight exactly 1); the rough one picks
    // them with the facet's F and 1 - F and weighs them by F G / G1 and (1 - F) G / G1 (Walter
    // et al. 2007 with visible normals, Heitz 2018), so G <= G1 bounds it. Radiance mode
    // multiplies transmission by 1 / eta'^2 (radiance compression), so the bound is 1 / eta'^2
    // there, with eta' the index on wi's side over wo's; an index-matched interface has
    // eta' = 1.
    std::vector<EdgeCase> cases;
    for (float eta : edge_etas())
        for (auto a : edge_alphas()) {
            auto b = std::make_shared<DielectricBxDF>(
                SampledSpectrum(eta), TrowbridgeReitzDistribution(a.first, a.second));
            bool matched = b->is_index_matched();
            std::ostringstream name;
            name << std::setprecision(9) << "dielectric eta " << eta << " " << alpha_name(a);
            cases.push_back(
                {name.str(), b,
                 [eta, matched](Vec3f wo, const BSDFSample &s, TransportMode mode, int) {
                     float etap = matched ? 1 : expected_etap(wo, eta);
                     bool compressed = mode == TransportMode::Radiance && s.is_transmission();
                     return compressed ? 1 / sqr(etap) : 1.f;
                 }});
        }
    check_all(cases);
}

TEST(BxDFEdges, DispersiveDielectric) {
    // Where the hero is followed alone (a smooth interface, or a lane in the index-matched band),
    // the lobe choice uses the lanes' average Fresnel reflectance F (selection_reflectance), so on
    // reflection lane i weighs F_i / F times G / G1 (1 when smooth): at most NumWavelengths, one
    // lane's share of a sum over lanes. The hero's refraction weighs (1 - F_0) / (1 - F) times
    // G / G1 by the same argument: at most NumWavelengths, over eta'^2 in Radiance mode; a hero in
    // the index-matched band passes straight through with weight 1. Rough refraction otherwise
    // keeps every lane (lane lobes): sampled as lane k, with lane k's own Fresnel term choosing
    // the lobe, lane i's weight over its own density is G / G1 (over eta_i'^2 for radiance), and
    // over the lanes' mean at most NumWavelengths times that. check_sample applies the same bound
    // to sample_f_as over the lanes' mean.
    std::vector<EdgeCase> cases;
    for (const SampledSpectrum &eta : dispersive_etas())
        for (auto a : edge_alphas()) {
            auto b = std::make_shared<DielectricBxDF>(
                eta, TrowbridgeReitzDistribution(a.first, a.second));
            bool hero_matched = b->is_matched_lane(0);
            std::ostringstream name;
            name << std::setprecision(9) << "dispersive dielectric eta " << eta[0] << "," << eta[1]
                 << "," << eta[2] << "," << eta[3] << " " << alpha_name(a);
            cases.push_back(
                {name.str(), b,
                 [eta, hero_matched](Vec3f wo, const BSDFSample &s, TransportMode mode, int lane) {
                     if (s.is_reflection()) return float(NumWavelengths);
                     float etap = hero_matched ? 1 : expected_etap(wo, eta[lane]);
                     return NumWavelengths * (mode == TransportMode::Radiance ? 1 / sqr(etap) : 1.f);
                 }});
        }
    check_all(cases);
}

// Disney parameter sets, each over the roughnesses below and the relative indices it uses:
// those of issue #7 (the index-matched band's edges are the dielectric's concern, which the
// Dielectric case covers), and one for a metal, whose index plays no part in the model.
struct DisneySet {
    std::string name;
    DisneyParameters p;
    std::vector<float> etas = {1, 1 + 1e-6f, 1 - 1e-6f, 1.5f, 1 / 1.5f, 2.4f};
};
std::vector<DisneySet> disney_sets() {
    auto base = [](SampledSpectrum c) {
        DisneyParameters p;
        p.base_color = c;
        p.base_luminance = c.average();
        return p;
    };
    const SampledSpectrum coloured(0.7f, 0.45f, 0.2f, 0.6f);
    std::vector<DisneySet> sets;
    sets.push_back({"diffuse", base(SampledSpectrum(0.8f))});
    {
        DisneyParameters p = base(SampledSpectrum(1));
        p.metallic = 1;
        sets.push_back({"metal", p, {1.5f}});
    }
    {
        DisneyParameters p = base(SampledSpectrum(0.9f, 0.6f, 0.3f, 0.1f));
        p.metallic = 1, p.anisotropic = 1;
        sets.push_back({"anisotropic metal", p, {1.5f}});
    }
    {
        DisneyParameters p = base(SampledSpectrum(1));
        p.spec_trans = 1;
        sets.push_back({"glass", p});
    }
    {
        DisneyParameters p = base(coloured);
        p.spec_trans = 0.5f, p.clearcoat = 1, p.clearcoat_gloss = 1, p.sheen = 1, p.sheen_tint = 1;
        p.specular_tint = 1;
        sets.push_back({"half glass, clearcoat, sheen, tints", p});
    }
    {
        DisneyParameters p = base(SampledSpectrum(1));
        p.thin = true, p.spec_trans = 1, p.anisotropic = 0.5f;
        sets.push_back({"thin glass", p});
    }
    {
        DisneyParameters p = base(coloured);
        p.thin = true, p.spec_trans = 0.5f, p.diff_trans = 1, p.flatness = 1, p.sheen = 1,
        p.clearcoat = 1;
        p.clearcoat_gloss = 0;
        sets.push_back({"thin, diffuse transmission, flat, sheen, clearcoat", p});
    }
    {
        DisneyParameters p = base(SampledSpectrum(0.5f));
        p.metallic = 0.3f, p.spec_trans = 0.6f, p.anisotropic = 0.8f, p.clearcoat = 0.5f;
        p.clearcoat_gloss = 0.3f, p.sheen = 0.5f, p.specular_tint = 0.5f;
        sets.push_back({"everything", p});
    }
    return sets;
}

// Disney roughness r gives alpha = r^2: these give the alphas 1e-4 ... 1 of edge_alphas().
constexpr float DisneyRoughnesses[] = {0, 0.01f, 0.0316227766f, 0.1f, 0.316227766f, 0.707106781f,
                                       1};

TEST(BxDFEdges, Disney) {
    // A generous bound that still catches blow-ups: 1e5, plus the pole of the thin diffuse
    // lobe's flatness term. Disney's non-delta weight is f |cos| / sum_k p_k pdf_k over the lobes
    // k, at most max_k (f_k |cos| / pdf_k) / p_k. Each lobe's own weight f_k |cos| / pdf_k is at
    // most c_k times its blend weight: c = 1 for the microfacet lobes (F <= 1, G <= G1), 5.8 for
    // refraction into a denser side in Radiance mode (1 / eta'^2, eta' >= 1 / 2.4 on this grid),
    // 7 for the diffuse lobe (Lambert <= 1, retro-reflection <= 6), under 5 for the sheen, and
    // 128 for the clearcoat (its own weight F G1(wo) G1(wi) wo.wm / (|cos_o| wm.z) is at most
    // 32 clearcoat: G1(w) / |cos w| <= 2 / 0.25 for the masking alpha 0.25, and the reflection
    // geometry gives wo.wm / wm.z <= 2 / (|cos_i| + |cos_o|)). Lobe selection gives every present
    // lobe at least MinimumSelectionFraction = 1% of its blend weight over the total of the
    // selection weights, which is below 6.5 for parameters in their ranges. So the weight is at
    // most 100 * 6.5 * 128 < 1e5. The flatness term 1.25 (F_ss (1 / (|cos_o| + |cos_i|) - 0.5)
    // + 0.5) (Burley 2012's Hanrahan-Krueger shape) has a pole at grazing pairs by design, which
    // adds at most 100 * 6.5 * 1.25 / (|cos_o| + |cos_i|) < 1e5 flatness / (|cos_o| + |cos_i|).
    std::vector<EdgeCase> cases;
    for (const DisneySet &set : disney_sets())
        for (float roughness : DisneyRoughnesses)
            for (float eta : set.etas) {
                DisneyParameters p = set.p;
                p.roughness = roughness, p.eta = SampledSpectrum(eta), p.reference_eta = eta;
                std::ostringstream name;
                name << std::setprecision(9) << "disney " << set.name << " roughness " << roughness
                     << " eta " << eta;
                float flatness = p.thin ? p.flatness : 0;
                cases.push_back({name.str(), std::make_shared<DisneyBxDF>(p),
                                 [flatness](Vec3f wo, const BSDFSample &s, TransportMode, int) {
                                     return 1e5f *
                                            (1 + flatness / (std::abs(wo.z) + std::abs(s.wi.z)));
                                 }});
            }
    check_all(cases);
}

TEST(BxDFEdges, ThinDielectric) {
    // Reflection and transmission are chosen with the lane-average probabilities R' and T' and
    // weigh R'_i / R' and T'_i / T': 1 for a non-dispersive slab, at most NumWavelengths for any
    // (one lane's share of a sum of non-negative lanes).
    std::vector<EdgeCase> cases;
    for (float eta : edge_etas())
        cases.push_back({"thin dielectric eta " + std::to_string(eta),
                         std::make_shared<ThinDielectricBxDF>(SampledSpectrum(eta)),
                         [](Vec3f, const BSDFSample &, TransportMode, int) { return 1.f; }});
    for (const SampledSpectrum &eta : dispersive_etas())
        cases.push_back(
            {"thin dielectric dispersive eta " + std::to_string(eta[0]) + "," +
                 std::to_string(eta[1]),
             std::make_shared<ThinDielectricBxDF>(eta),
             [](Vec3f, const BSDFSample &, TransportMode, int) { return float(NumWavelengths); }});
    check_all(cases);
}

// ---------------------------------------------------------------------------------------------
// Total internal reflection and invisible interfaces.

Vec3f mirror(Vec3f wo) { return {-wo.x, -wo.y, wo.z}; }

TEST(BxDFEdges, TotalInternalReflection) {
    // From the dense side beyond the critical angle a smooth interface reflects everything:
    // every sample is the mirror direction with weight exactly F = 1 on every lane (in both
    // modes: reflection has no radiance compression), and transmission alone has no sample.
    // The edge cosines up to 0.5 are all beyond the critical angles (cos 0.745 for eta 1.5,
    // 0.768 for 1.56, 0.909 for 2.4).
    DisneyParameters glass;
    glass.base_color = SampledSpectrum(1), glass.base_luminance = 1, glass.spec_trans = 1,
    glass.roughness = 0;
    struct Dense {
        std::string name;
        std::shared_ptr<const BxDF> bxdf;
        float inside;  // the sign of cos theta on the dense side
    };
    std::vector<Dense> cases;
    for (float eta : {1.5f, 2.4f}) {
        cases.push_back({"glass " + std::to_string(eta),
                         std::make_shared<DielectricBxDF>(SampledSpectrum(eta),
                                                          TrowbridgeReitzDistribution(0, 0)),
                         -1});
        cases.push_back({"glass " + std::to_string(1 / eta) + " (dense outside)",
                         std::make_shared<DielectricBxDF>(
                             SampledSpectrum(1 / eta), TrowbridgeReitzDistribution(1e-4f, 1e-4f)),
                         1});
        glass.eta = SampledSpectrum(eta), glass.reference_eta = eta;
        cases.push_back(
            {"disney glass " + std::to_string(eta), std::make_shared<DisneyBxDF>(glass), -1});
    }
    cases.push_back(
        {"dispersive glass",
         std::make_shared<DielectricBxDF>(dispersive_etas()[0], TrowbridgeReitzDistribution(0, 0)),
         -1});
    for (const Dense &c : cases)
        for (float cos_o : EdgeCosines)
            for (Vec2f phi : edge_azimuths()) {
                float sin_o = float(std::sqrt(1 - double(cos_o) * double(cos_o)));
                Vec3f wo(sin_o * phi.x, sin_o * phi.y, c.inside * cos_o);
                for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                    for (float uc : LobeUniforms) {
                        auto s = c.bxdf->sample_f(wo, uc, {0.5f, 0.5f}, mode);
                        ASSERT_TRUE(s) << c.name << " cos " << cos_o;
                        EXPECT_TRUE(s->is_reflection() && s->is_specular())
                            << c.name << " cos " << cos_o;
                        EXPECT_EQ(s->wi, mirror(wo)) << c.name;
                        for (int i = 0; i < NumWavelengths; ++i)
                            EXPECT_NEAR(s->f[i] * std::abs(s->wi.z) / s->pdf, 1, 1e-6f)
                                << c.name << " cos " << cos_o;
                    }
                    EXPECT_FALSE(
                        c.bxdf->sample_f(wo, 0.5f, {0.5f, 0.5f}, mode, SampleFlags::Transmission))
                        << c.name;
                }
            }
}

TEST(BxDFEdges, RoughTotalInternalReflection) {
    // A just-rough interface (alpha 1e-3) seen from inside at 60 degrees, 18 degrees beyond the
    // critical angle of eta 1.5: light refracts only through facets tilted more than 18 degrees
    // (tan 0.33) towards wo, a GGX fraction of about alpha^2 / tan^2 = 1e-5 (times at most 2
    // for visibility), so of 256 samples at most one transmits except with probability below
    // 1e-4 (fixed seed). In Importance mode every sample weighs G / G1 = 1 - 1e-6 at this angle,
    // whichever way it goes: the energy is conserved up to the masking term.
    DielectricBxDF b(SampledSpectrum(1.5f), TrowbridgeReitzDistribution(1e-3f, 1e-3f));
    Vec3f wo(std::sqrt(0.75f) * 0.6f, std::sqrt(0.75f) * 0.8f, -0.5f);
    Rng rng(0x7e1, 3);
    int transmitted = 0;
    for (int n = 0; n < 256; ++n) {
        auto s = b.sample_f(wo, rng.uniform(), rng.uniform2(), TransportMode::Importance);
        ASSERT_TRUE(s);
        transmitted += s->is_transmission();
        EXPECT_NEAR(s->f[0] * std::abs(s->wi.z) / s->pdf, 1, 1e-4f);
    }
    EXPECT_LE(transmitted, 1);
}

TEST(BxDFEdges, IndexMatchedInterfacePassesStraightThrough) {
    // eta exactly 1, and within the index-matched band (1 +/- 1e-6), smooth or at any roughness:
    // at every grid direction including cos theta = 1e-7, in both modes and for every uniform
    // sample, light continues along -wo with weight exactly 1 and relative index 1, there is no
    // reflection, and f and pdf are zero (the delta is the whole BSDF). The same holds for a
    // thin slab of index 1 (its reflectance is 0: every sample transmits) and for Disney glass of
    // index 1 and white base (its specular BSDF is the index-matched interface).
    std::vector<std::pair<std::string, std::shared_ptr<const BxDF>>> cases;
    for (float eta : {1.f, 1 + 1e-6f, 1 - 1e-6f})
        for (auto a : edge_alphas())
            cases.push_back(
                {"dielectric " + std::to_string(eta) + " " + alpha_name(a),
                 std::make_shared<DielectricBxDF>(SampledSpectrum(eta),
                                                  TrowbridgeReitzDistribution(a.first, a.second))});
    cases.push_back(
        {"thin dielectric 1", std::make_shared<ThinDielectricBxDF>(SampledSpectrum(1))});
    for (float roughness : DisneyRoughnesses) {
        DisneyParameters p;
        p.base_color = SampledSpectrum(1), p.base_luminance = 1, p.spec_trans = 1,
        p.roughness = roughness;
        p.eta = SampledSpectrum(1), p.reference_eta = 1;
        cases.push_back({"disney glass 1 roughness " + std::to_string(roughness),
                         std::make_shared<DisneyBxDF>(p)});
    }
    std::vector<Vec3f> dirs = edge_directions();
    for (const auto &[name, b] : cases)
        for (Vec3f wo : dirs)
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                for (float uc : LobeUniforms)
                    for (float u : EdgeUniforms) {
                        auto s = b->sample_f(wo, uc, {u, 1 - u}, mode);
                        ASSERT_TRUE(s) << name << " wo " << describe(wo);
                        EXPECT_TRUE(s->is_transmission() && s->is_specular())
                            << name << " wo " << describe(wo);
                        EXPECT_EQ(s->wi, -wo) << name;
                        EXPECT_EQ(s->eta, 1) << name;
                        for (int i = 0; i < NumWavelengths; ++i)
                            EXPECT_NEAR(s->f[i] * std::abs(s->wi.z) / s->pdf, 1, 1e-6f)
                                << name << " wo " << describe(wo);
                    }
                EXPECT_FALSE(b->sample_f(wo, 0.5f, {0.5f, 0.5f}, mode, SampleFlags::Reflection))
                    << name;
                for (Vec3f wi : dirs) {
                    EXPECT_TRUE(b->f(wo, wi, mode).is_black()) << name;
                    EXPECT_EQ(b->pdf(wo, wi, mode), 0) << name;
                }
            }
}

TEST(BxDFEdges, UnitIndexReflectsNothingAtGrazingAngles) {
    // Regression: Snell's cos^2 theta_t computed as 1 - (1 - cos^2) / eta^2 rounds to 0 for
    // cos below about 2.4e-4, so fresnel_dielectric(cos, 1) returned 1 (total reflection) at
    // grazing angles, and a thin slab or a Disney specular lobe of index 1 became a mirror there.
    for (float c : EdgeCosines) {
        EXPECT_EQ(fresnel_dielectric(c, 1), 0) << c;
        EXPECT_EQ(fresnel_dielectric(-c, 1), 0) << c;
    }
    // Just off 1 the interface still reflects nearly everything at grazing incidence: to first
    // order in cos_i, 1 - F = 2 (1 + eta^2) cos_i / sqrt(eta^2 - 1) (averaging the two
    // polarisations' 1 - r^2 = 4 cos_i / (eta cos_t) and 4 eta cos_i / cos_t at cos_t =
    // sqrt(eta^2 - 1) / eta), 2.9e-4 for eta = 1 + 1e-6 and cos_i = 1e-7; the next order is
    // below 1e-8 here.
    float eta = 1 + 1e-6f;
    EXPECT_NEAR(fresnel_dielectric(1e-7f, eta),
                1 - 2 * (1 + sqr(eta)) * 1e-7f / std::sqrt(sqr(eta) - 1), 1e-6f);
    // And below 1 it totally reflects beyond the critical angle, cos_c = sqrt(1 - eta^2) = 1.4e-3.
    EXPECT_EQ(fresnel_dielectric(1e-3f, 1 - 1e-6f), 1);
    EXPECT_LT(fresnel_dielectric(2e-3f, 1 - 1e-6f), 1);
}

// ---------------------------------------------------------------------------------------------
// Regressions: the grid cases that failed before their fixes, kept by name.

TEST(BxDFEdges, GrazingReflectionSampleHasADensity) {
    // pdf() recomputed the visible-normal density with wo.wm, which for nearly opposite grazing
    // directions is a cancellation that rounding made negative, and returned 0 at a direction
    // sample_f had just returned with a density of 1e8 (reflection_pdf now divides it out).
    TrowbridgeReitzDistribution d(1e-3f, 1e-3f);
    ConductorBxDF conductor(d, SampledSpectrum(0.05f), SampledSpectrum(6));
    DielectricBxDF dielectric(SampledSpectrum(1.5f), d);
    Vec3f wo(-0.970958173f, 0.239249334f, -1e-4f);
    for (const BxDF *b : std::initializer_list<const BxDF *>{&conductor, &dielectric}) {
        auto s = b->sample_f(wo, 0.419617206f, {0.985307157f, 0.181955606f},
                             TransportMode::Importance, SampleFlags::Reflection);
        ASSERT_TRUE(s);
        EXPECT_GT(b->pdf(wo, s->wi, TransportMode::Importance, SampleFlags::Reflection), 0);
    }
}

TEST(BxDFEdges, GrazingRefractionSampleHasADensity) {
    // A facet nearly edge-on to a grazing wo (wo.wm = 3e-8) refracts with 1 - F = 6e-6, but the
    // half vector recovered from (wo, wi) has wo.wm = 2e-11, where 1 - F rounds to 0, so pdf()
    // was 0 at the returned direction. sample_f now evaluates at the recovered half vector and
    // rejects what pdf() rejects.
    for (float eta : {1.5f, 1.0002f}) {
        DielectricBxDF b(SampledSpectrum(eta), TrowbridgeReitzDistribution(1e-4f, 1));
        Vec3f wo(1, 0, 1e-7f);
        for (float u1 : EdgeUniforms) {
            auto s = b.sample_f(wo, 0.5f, {OneMinusEpsilon, u1}, TransportMode::Radiance,
                                SampleFlags::Transmission);
            if (s) {
                EXPECT_GT(b.pdf(wo, s->wi, TransportMode::Radiance, SampleFlags::Transmission), 0)
                    << eta;
            }
        }
    }
}

TEST(BxDFEdges, AnisotropicDispersiveRefractionKeepsBoundedLanes) {
    // A lobe of alphas 0.01 x 0.5 is narrow along one axis: weighing the secondaries by the
    // hero's density, f_i / pdf_0, reached 1e7 on the grid. Over the lanes' mean density, every
    // lane stays within NumWavelengths / eta'^2 (DispersiveDielectric above).
    const SampledSpectrum eta = dispersive_etas()[0];
    DielectricBxDF b(eta, TrowbridgeReitzDistribution(0.01f, 0.5f));
    const Vec3f wo = normalize(Vec3f(0.6f, 0.2f, 0.7f));
    Rng rng(0xa415, 1);
    int transmissions = 0, all_lanes = 0;
    for (int n = 0; n < 400; ++n) {
        auto s = b.sample_f_as(n % NumWavelengths, wo, rng.uniform(), rng.uniform2(), TransportMode::Radiance);
        if (!s || s->is_reflection()) continue;
        ++transmissions;
        EXPECT_FALSE(s->dispersive);
        all_lanes += s->f.min_value() > 0;
        for (int i = 0; i < NumWavelengths; ++i) {
            EXPECT_LE(s->f[i] * std::abs(s->wi.z) / s->lane_pdf->average(),
                      NumWavelengths / sqr(eta[i]) * 1.0001f);
        }
    }
    EXPECT_GT(transmissions, 200);
    // Mostly every lane is kept (a lane whose facet would face away has none).
    EXPECT_GT(all_lanes, transmissions / 2);
}

TEST(BxDFEdges, DispersiveLobeChoiceBoundsSecondaryReflection) {
    // A hero with an index near 1 barely reflects (F_0 = 2.5e-7 at normal incidence) while the
    // other lanes do (up to 0.17 for eta 2.4): choosing reflection with the hero's F gave them
    // weights F_i / F_0 up to 7e5. The choice now uses the lanes' average, so F_i / F <= 4.
    SampledSpectrum eta(1.001f, 1.2f, 1.5f, 2.4f);
    for (float alpha : {0.f, 0.3f}) {
        DielectricBxDF b(eta, TrowbridgeReitzDistribution(alpha, alpha));
        auto s = b.sample_f(Vec3f(0, 0, 1), 0, {0.5f, 0.5f}, TransportMode::Importance);
        ASSERT_TRUE(s);
        ASSERT_TRUE(s->is_reflection());
        for (int i = 0; i < NumWavelengths; ++i)
            EXPECT_LE(s->f[i] * s->wi.z / s->pdf, NumWavelengths * 1.0001f);
        // The lanes' weights keep the ratio of their Fresnel reflectances (Born and Wolf's
        // ((n - 1) / (n + 1))^2 at normal incidence, up to the masking and the facet tilt).
        float r3 = sqr((2.4f - 1) / (2.4f + 1)), r2 = sqr((1.5f - 1) / (1.5f + 1));
        EXPECT_NEAR(s->f[3] / s->f[2], r3 / r2, alpha == 0 ? 1e-4f : 0.2f);
    }
}

TEST(BxDFEdges, PartlyIndexMatchedDispersiveInterface) {
    // A dispersive index crossing 1: the rough model of a lane in the index-matched band is
    // degenerate (f grows as 1 / |wi + wo|^2 around wi = -wo, not integrable), and with the hero
    // there sample_f returned garbage with zero density. Lanes in the band now see no interface.
    Vec3f wo = normalize(Vec3f(0.3f, -0.5f, 0.8f));
    Rng rng(0x1d, 2);
    {
        // Hero in the band: the straight-through delta, alone.
        DielectricBxDF b(SampledSpectrum(1, 1.5f, 1.5f, 1.5f),
                         TrowbridgeReitzDistribution(0.3f, 0.3f));
        EXPECT_TRUE(b.flags() & BxDFSpecular);
        for (int n = 0; n < 50; ++n) {
            auto s = b.sample_f(wo, rng.uniform(), rng.uniform2(), TransportMode::Radiance);
            ASSERT_TRUE(s);
            EXPECT_TRUE(s->is_specular() && s->is_transmission() && s->dispersive);
            EXPECT_EQ(s->wi, -wo);
            EXPECT_NEAR(s->f[0] * std::abs(s->wi.z) / s->pdf, 1, 1e-6f);
        }
        // The hero samples only the delta, so pdf() is zero; the other lanes keep their lobes
        // for light sampling, and the matched lane has no value off the delta.
        Vec3f wi = normalize(Vec3f(-0.2f, 0.3f, -0.9f));
        EXPECT_EQ(b.pdf(wo, wi, TransportMode::Radiance), 0);
        SampledSpectrum f = b.f(wo, wi, TransportMode::Radiance);
        EXPECT_EQ(f[0], 0);
        EXPECT_GT(f[1], 0);
    }
    {
        // Secondary in the band: it reflects nothing and its light goes straight through, which
        // the hero's rough refraction samples do not estimate, so they terminate it.
        DielectricBxDF b(SampledSpectrum(1.5f, 1, 1.5f, 1.5f),
                         TrowbridgeReitzDistribution(0.3f, 0.3f));
        int transmissions = 0;
        for (int n = 0; n < 100; ++n) {
            auto s = b.sample_f(wo, rng.uniform(), rng.uniform2(), TransportMode::Radiance);
            if (!s) continue;
            EXPECT_EQ(s->f[1], 0);
            if (s->is_transmission()) {
                ++transmissions;
                EXPECT_TRUE(s->dispersive);
            }
        }
        EXPECT_GT(transmissions, 50);
    }
}

}  // namespace
}  // namespace caustica
