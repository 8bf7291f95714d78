#include "materials/dipole_profile.h"

#include "core/vecmath.h"

#include <cmath>

namespace caustica {

float diffuse_fresnel_reflectance(float eta) {
    return -1.440f / sqr(eta) + 0.710f / eta + 0.668f + 0.0636f * eta;
}

DipoleProfile::DipoleProfile(const SampledSpectrum &sigma_a, const SampledSpectrum &sigma_s_reduced,
                             float eta) {
    double fdr = diffuse_fresnel_reflectance(eta);
    double boundary = (1 + fdr) / (1 - fdr); // Jensen's A
    for (int c = 0; c < NumWavelengths; ++c) {
        double sa = std::max(0.f, sigma_a[c]), ss = std::max(0.f, sigma_s_reduced[c]);
        double st = sa + ss;
        Channel &ch = channels_[c];
        if (!(ss > 0) || !std::isfinite(st)) continue; // no scattering: no diffuse reflection
        double reduced_albedo = ss / st;
        ch.sigma_tr = std::sqrt(3 * sa * st);
        ch.z[0] = 1 / st;
        ch.z[1] = ch.z[0] * (1 + 4 * boundary / 3);
        for (int p = 0; p < 2; ++p)
            ch.pole_total[p] = reduced_albedo / 2 * std::exp(-ch.sigma_tr * ch.z[p]);
        ch.total = ch.pole_total[0] + ch.pole_total[1];
        ch.max_radius = radius_with_tail(ch, 1 - ProfileEnergyWithinMaxRadius);
    }
}

DipoleProfile::PoleSums DipoleProfile::evaluate_poles(const Channel &ch, double r) {
    // A pole at depth z has energy (alpha' / 2) (z / d) e^{-sigma_tr d} beyond r, that is its
    // total times (z / d) e^{-sigma_tr (d - z)} (the form that cannot underflow before the tail
    // is negligible), and density alpha' / (4 pi) z (sigma_tr d + 1) e^{-sigma_tr d} / d^3, which
    // is that tail times (sigma_tr d + 1) / (2 pi d^2): one exponential serves both.
    PoleSums sums;
    for (int p = 0; p < 2; ++p) {
        double z = ch.z[p], d = std::sqrt(r * r + z * z);
        double tail = ch.pole_total[p] * z / d * std::exp(-ch.sigma_tr * (d - z));
        sums.tail += tail;
        sums.density += tail * (ch.sigma_tr * d + 1) / (2 * Pi * d * d);
    }
    return sums;
}

double DipoleProfile::radius_with_tail(const Channel &ch, double tail) {
    if (tail >= 1) return 0;
    // Bracket: a pole's relative tail (z / d) e^{-sigma_tr (d - z)} is at most z / d and at most
    // e^{-sigma_tr (d - z)}, so at the larger of the poles' radii where either bound reaches
    // `tail`, their weighted sum is at most `tail`.
    double lo = 0, hi = 0;
    for (double z : ch.z) {
        double d = z / tail;
        if (ch.sigma_tr > 0) d = std::min(d, z - std::log(tail) / ch.sigma_tr);
        hi = std::max(hi, std::sqrt(std::max(0.0, d * d - z * z)));
    }
    // Newton on the logarithm of the energy beyond r, which is nearly linear in r where an
    // exponential dominates (its derivative is -2 pi r R_d(r) / energy beyond r); bisection keeps
    // the iterate inside the bracket.
    double r = 0.5 * hi, log_target = std::log(tail * ch.total);
    for (int iteration = 0; iteration < 100; ++iteration) {
        PoleSums sums = evaluate_poles(ch, r);
        double f = std::log(sums.tail) - log_target;
        if (std::abs(f) <= 1e-12) break;
        (f > 0 ? lo : hi) = r;
        double slope = -2 * Pi * r * sums.density / sums.tail;
        double next = slope < 0 ? r - f / slope : lo;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (hi - lo <= 1e-12 * hi) break;
        r = next;
    }
    return r;
}

SampledSpectrum DipoleProfile::evaluate(float r) const {
    SampledSpectrum value;
    for (int c = 0; c < NumWavelengths; ++c)
        if (channels_[c].total > 0) value[c] = float(evaluate_poles(channels_[c], r).density);
    return value;
}

SampledSpectrum DipoleProfile::pdf_area(float r) const {
    SampledSpectrum pdf;
    for (int c = 0; c < NumWavelengths; ++c)
        if (channels_[c].total > 0)
            pdf[c] = float(evaluate_poles(channels_[c], r).density / channels_[c].total);
    return pdf;
}

float DipoleProfile::sample_radius(int c, float u) const {
    if (!(channels_[c].total > 0)) return 0;
    return float(radius_with_tail(channels_[c], 1 - double(u)));
}

SampledSpectrum DipoleProfile::albedo() const {
    SampledSpectrum a;
    for (int c = 0; c < NumWavelengths; ++c) a[c] = float(channels_[c].total);
    return a;
}

float DipoleProfile::max_radius(int c) const { return float(channels_[c].max_radius); }

} // namespace caustica
