#include "materials/photon_beam_diffusion.h"

#include "core/catmull_rom.h"
#include "core/vecmath.h"
#include "materials/fresnel.h"

#include <algorithm>
#include <cmath>

namespace caustica {
namespace {

// Points along the beam per radius in both terms, at the midpoints of 100 equal-probability
// strata of the exponential attenuation (pbrt-v4's count; the table is made of these numbers).
// Exponentials are std::exp throughout: pbrt-v4's CPU build uses a cubic approximation of 2^x
// there (its GPU build __expf), which moves its table by up to 8e-4 relative to this one.
constexpr int BeamSamples = 100;

float beam_depth(int i, float sigma) { return -std::log(1 - (i + 0.5f) / BeamSamples) / sigma; }

// Henyey-Greenstein density for scattering by an angle of cosine cos_theta, with g limited to
// +-0.99 as pbrt-v4 limits it (the lobe tends to a delta as |g| -> 1).
float henyey_greenstein(float cos_theta, float g) {
    g = clamp(g, -0.99f, 0.99f);
    float denominator = 1 + sqr(g) - 2 * g * cos_theta;
    return Inv4Pi * (1 - sqr(g)) / (denominator * safe_sqrt(denominator));
}

} // namespace

float fresnel_moment1(float eta) {
    float e2 = eta * eta, e3 = e2 * eta, e4 = e3 * eta, e5 = e4 * eta;
    if (eta < 1)
        return 0.45966f - 1.73965f * eta + 3.37668f * e2 - 3.904945f * e3 + 2.49277f * e4 -
               0.68441f * e5;
    return -4.61686f + 11.1136f * eta - 10.4646f * e2 + 5.11455f * e3 - 1.27198f * e4 +
           0.12746f * e5;
}

float fresnel_moment2(float eta) {
    float e2 = eta * eta, e3 = e2 * eta, e4 = e3 * eta, e5 = e4 * eta;
    if (eta < 1)
        return 0.27614f - 0.87350f * eta + 1.12077f * e2 - 0.65095f * e3 + 0.07883f * e4 +
               0.04860f * e5;
    float r = 1 / eta, r2 = r * r, r3 = r2 * r;
    return -547.033f + 45.3087f * r3 - 218.725f * r2 + 458.843f * r + 404.557f * eta -
           189.519f * e2 + 54.9327f * e3 - 9.00603f * e4 + 0.63942f * e5;
}

float beam_diffusion_single_scattering(float sigma_a, float sigma_s, float g, float eta, float r) {
    // Light scattered once at depth t leaves through the surface point at distance r along a
    // straight segment of length d = sqrt(r^2 + t^2), meeting the boundary with cosine t / d. It
    // gets out only if that cosine exceeds the critical one, sqrt(1 - 1 / eta^2), that is for
    // t >= t_crit = r sqrt(eta^2 - 1); shallower scattering is totally reflected. So the term is
    //   int_tcrit^inf sigma_s e^{-sigma_t t} p(-t / d) e^{-sigma_t d} (1 - F) (t / d) / d^2 dt
    // (power scattered in dt, the phase function for the beam's downward direction turning to
    // the upward segment, attenuation on the way, the part transmitted, and the solid angle of a
    // unit area at distance d seen at cosine t / d), with t - t_crit drawn from the exponential
    // of rate sigma_t.
    const float sigma_t = sigma_a + sigma_s, rho = sigma_s / sigma_t;
    const float t_crit = r * safe_sqrt(sqr(eta) - 1);
    float sum = 0;
    for (int i = 0; i < BeamSamples; ++i) {
        float t = t_crit + beam_depth(i, sigma_t);
        float d = std::sqrt(sqr(r) + sqr(t)), cos_exit = t / d;
        float transmitted = 1 - fresnel_dielectric(-cos_exit, eta);
        sum += rho * std::exp(-sigma_t * (d + t_crit)) / sqr(d) *
               henyey_greenstein(-cos_exit, g) * transmitted * cos_exit;
    }
    return sum / BeamSamples;
}

float beam_diffusion_multiple_scattering(float sigma_a, float sigma_s, float g, float eta,
                                         float r) {
    // After the first scattering event the light is taken to be diffuse, so the medium is
    // replaced by its similarity-reduced one (sigma_s' = sigma_s (1 - g), isotropic), and the
    // beam by point sources at depths z_r distributed as the reduced beam's first collisions.
    const float sigma_s_reduced = sigma_s * (1 - g);
    const float sigma_t_reduced = sigma_a + sigma_s_reduced;
    const float rho_reduced = sigma_s_reduced / sigma_t_reduced;
    // Grosjean's non-classical diffusion coefficient, which PBD uses instead of 1 / (3 sigma_t')
    // for its better accuracy near the sources, where most of the reflected light comes from.
    const float diffusion = (2 * sigma_a + sigma_s_reduced) / (3 * sqr(sigma_t_reduced));
    const float sigma_tr = safe_sqrt(sigma_a / diffusion);
    // The index mismatch: the fluence is extrapolated to vanish at height z_b above the surface
    // (the image source is mirrored about it), and the light leaving is the combination
    // c_phi phi + c_e E.n of fluence and flux given by the Fresnel moments (PBD's boundary
    // conditions, after d'Eon and Irving 2011).
    const float c1 = fresnel_moment1(eta), c2 = fresnel_moment2(eta);
    const float z_b = 2 * diffusion * (1 + 3 * c2) / (1 - 2 * c1);
    const float c_phi = (1 - 2 * c1) / 4, c_e = (1 - 3 * c2) / 2;
    float sum = 0;
    for (int i = 0; i < BeamSamples; ++i) {
        float z_r = beam_depth(i, sigma_t_reduced), z_v = -z_r - 2 * z_b;
        float d_r = std::sqrt(sqr(r) + sqr(z_r)), d_v = std::sqrt(sqr(r) + sqr(z_v));
        float e_r = std::exp(-sigma_tr * d_r), e_v = std::exp(-sigma_tr * d_v);
        float fluence = Inv4Pi / diffusion * (e_r / d_r - e_v / d_v);
        float flux_normal = Inv4Pi * (z_r * (1 + sigma_tr * d_r) * e_r / (d_r * d_r * d_r) -
                                      z_v * (1 + sigma_tr * d_v) * e_v / (d_v * d_v * d_v));
        // kappa damps sources for which z_r + d_r, the way down to the source and up to the exit
        // point, is short against a reduced mean free path, where diffusion is least accurate;
        // it and the squared reduced albedo weighting each source are as pbrt-v3 and pbrt-v4
        // have them (Physically Based Rendering, 3rd ed., section 15.5).
        float kappa = 1 - std::exp(-2 * sigma_t_reduced * (d_r + z_r));
        sum += kappa * sqr(rho_reduced) * (c_phi * fluence + c_e * flux_normal);
    }
    return sum / BeamSamples;
}

BeamDiffusionTable compute_beam_diffusion_table(float g, float eta) {
    constexpr int NRho = BeamDiffusionTable::RhoCount, NRadius = BeamDiffusionTable::RadiusCount;
    BeamDiffusionTable t;
    t.radius.resize(NRadius);
    t.radius[0] = 0;
    t.radius[1] = 2.5e-3f;
    for (int j = 2; j < NRadius; ++j) t.radius[j] = t.radius[j - 1] * 1.2f;
    t.rho.resize(NRho);
    for (int i = 0; i < NRho; ++i)
        t.rho[i] = (1 - std::exp(-8.f * i / (NRho - 1))) / (1 - std::exp(-8.f));
    t.profile.resize(NRho * NRadius);
    t.profile_cdf.resize(NRho * NRadius);
    t.rho_eff.resize(NRho);
    for (int i = 0; i < NRho; ++i) {
        const float rho = t.rho[i];
        for (int j = 0; j < NRadius; ++j) {
            const float r = t.radius[j];
            t.profile[i * NRadius + j] =
                2 * Pi * r *
                (beam_diffusion_single_scattering(1 - rho, rho, g, eta, r) +
                 beam_diffusion_multiple_scattering(1 - rho, rho, g, eta, r));
        }
        t.rho_eff[i] = integrate_catmull_rom(
            t.radius, std::span(t.profile).subspan(i * NRadius, NRadius),
            std::span(t.profile_cdf).subspan(i * NRadius, NRadius));
    }
    return t;
}

void beam_diffusion_from_diffuse(const BeamDiffusionTable &table,
                                 const SampledSpectrum &reflectance, const SampledSpectrum &mfp,
                                 SampledSpectrum *sigma_a, SampledSpectrum *sigma_s) {
    for (int c = 0; c < NumWavelengths; ++c) {
        float rho = invert_catmull_rom(table.rho, table.rho_eff, reflectance[c]);
        (*sigma_s)[c] = rho / mfp[c];
        (*sigma_a)[c] = (1 - rho) / mfp[c];
    }
}

BeamDiffusionProfile::BeamDiffusionProfile(const BeamDiffusionTable &table,
                                           const SampledSpectrum &sigma_a,
                                           const SampledSpectrum &sigma_s)
    : table_(&table) {
    for (int c = 0; c < NumWavelengths; ++c) {
        const float sa = std::max(0.f, sigma_a[c]), ss = std::max(0.f, sigma_s[c]);
        sigma_t_[c] = sa + ss;
        rho_[c] = sigma_t_[c] > 0 ? ss / sigma_t_[c] : 0;
        std::optional<CatmullRomWeights> w = catmull_rom_weights(table.rho, rho_[c]);
        if (!w || !(sigma_t_[c] > 0)) continue;
        float albedo = 0;
        for (int k = 0; k < 4; ++k)
            if (w->weights[k] != 0) albedo += w->weights[k] * table.rho_eff[w->offset + k];
        // A channel that reflects nothing (no scattering) is never sampled.
        if (!(albedo > 0)) continue;
        albedo_[c] = albedo;
        max_radius_[c] = sample_radius(c, float(ProfileEnergyWithinMaxRadius));
    }
}

float BeamDiffusionProfile::profile_per_area(int c, float r) const {
    const float r_optical = r * sigma_t_[c];
    std::optional<CatmullRomWeights> wr = catmull_rom_weights(table_->rho, rho_[c]);
    std::optional<CatmullRomWeights> wx = catmull_rom_weights(table_->radius, r_optical);
    if (!wr || !wx) return 0;
    float radial = 0;
    for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k)
            if (float w = wr->weights[j] * wx->weights[k]; w != 0)
                radial += w * table_->profile[(wr->offset + j) * BeamDiffusionTable::RadiusCount +
                                              wx->offset + k];
    // The table holds the radial density 2 pi r R(r) for sigma_t = 1; at r = 0 it is 0, and
    // pbrt-v4 returns that rather than dividing.
    float per_area = r_optical != 0 ? radial / (2 * Pi * r_optical) : radial;
    return per_area * sqr(sigma_t_[c]);
}

SampledSpectrum BeamDiffusionProfile::evaluate(float r) const {
    SampledSpectrum value;
    for (int c = 0; c < NumWavelengths; ++c)
        if (albedo_[c] > 0) value[c] = std::max(0.f, profile_per_area(c, r));
    return value;
}

SampledSpectrum BeamDiffusionProfile::pdf_area(float r) const {
    SampledSpectrum pdf;
    for (int c = 0; c < NumWavelengths; ++c)
        if (albedo_[c] > 0) pdf[c] = std::max(0.f, profile_per_area(c, r) / albedo_[c]);
    return pdf;
}

float BeamDiffusionProfile::sample_radius(int c, float u) const {
    if (!(albedo_[c] > 0)) return 0;
    return sample_catmull_rom_2d(table_->rho, table_->radius, table_->profile,
                                 table_->profile_cdf, rho_[c], u) /
           sigma_t_[c];
}

SampledSpectrum BeamDiffusionProfile::albedo() const {
    SampledSpectrum a;
    for (int c = 0; c < NumWavelengths; ++c) a[c] = albedo_[c];
    return a;
}

float BeamDiffusionProfile::max_radius(int c) const { return max_radius_[c]; }

} // namespace caustica
