#include "materials/hair_bxdf.h"

#include "materials/fresnel.h"

#include <cmath>

namespace caustica {

namespace {

// The modified Bessel function I0 by its power series, sum over i of (x^2 / 4)^i / (i!)^2,
// summed until the terms no longer change the double result (x <= 20 here: under 60 terms).
double bessel_i0(double x) {
    const double q = x * x / 4;
    double term = 1, sum = 1;
    for (int i = 1; i < 80 && term > 1e-17 * sum; ++i) {
        term *= q / (double(i) * i);
        sum += term;
    }
    return sum;
}

// log I0(x): the series up to x = 20, Hankel's asymptotic expansion beyond,
// I0(x) ~ e^x / sqrt(2 pi x) (1 + t + 9/2 t^2 + 75/2 t^3 + ...) with t = 1 / (8 x), whose next
// term is below 1e-6 of the sum there. pbrt-v4 sums 10 series terms up to x = 12 and keeps one
// asymptotic term beyond, which is up to 2% low just below 12; Mp here is exact to float.
double log_bessel_i0(double x) {
    if (x <= 20) return std::log(bessel_i0(x));
    const double t = 1 / (8 * x);
    return x - 0.5 * std::log(2 * double(Pi) * x) + std::log1p(t * (1 + t * (4.5 + t * 37.5)));
}

// The longitudinal lobe Mp of d'Eon et al. 2011 (equation 6), a density in theta_i with respect
// to cos(theta_i) d theta_i: the von Mises-Fisher lobe of concentration 1 / v about the specular
// direction (sin theta = -sin theta_o), integrated over the azimuth about the fibre,
//   Mp = csch(1 / v) / (2 v) exp(-sin theta_i sin theta_o / v) I0(cos theta_i cos theta_o / v).
// In logs, since sinh(1 / v) and I0 overflow for the narrow lobes (v down to 5e-5);
// log csch(1 / v) = log 2 - 1 / v - log(1 - exp(-2 / v)).
float longitudinal(float cos_i, float cos_o, float sin_i, float sin_o, float v) {
    const double a = double(cos_i) * cos_o / v, b = double(sin_i) * sin_o / v;
    const double log_csch = std::log(2.0) - 1 / double(v) - std::log1p(-std::exp(-2 / double(v)));
    return float(std::exp(log_csch - std::log(2 * double(v)) - b + log_bessel_i0(a)));
}

// The logistic distribution of scale s, its cdf, and its restriction to [-pi, pi], which is
// the azimuthal lobe Np (Chiang et al. 2016 section 4.1).
float logistic(float x, float s) {
    const float e = std::exp(-std::abs(x) / s);
    return e / (s * sqr(1 + e));
}
float logistic_cdf(float x, float s) { return 1 / (1 + std::exp(-x / s)); }
float trimmed_logistic(float x, float s) {
    return logistic(x, s) / (logistic_cdf(Pi, s) - logistic_cdf(-Pi, s));
}
// Inverts the trimmed cdf.
float sample_trimmed_logistic(float u, float s) {
    u = lerp(u, logistic_cdf(-Pi, s), logistic_cdf(Pi, s));
    return clamp(-s * std::log(1 / u - 1), -Pi, Pi);
}

// Chooses an index with probability weights[i] / sum and rescales u to [0, 1) within it.
int sample_discrete(const std::array<float, HairBxDF::PMax + 1> &weights, float *u) {
    float sum = 0;
    for (float w : weights) sum += w;
    float up = *u * sum;
    if (up >= sum) up = std::nextafter(sum, 0.f);
    int i = 0;
    float below = 0;
    while (i < HairBxDF::PMax && below + weights[i] <= up) below += weights[i++];
    *u = std::min((up - below) / weights[i], OneMinusEpsilon);
    return i;
}

} // namespace

HairBxDF::HairBxDF(float h, float eta, const SampledSpectrum &sigma_a, float beta_m, float beta_n, float alpha)
    : h_(clamp(h, -1.f, 1.f)), eta_(eta), gamma_o_(safe_asin(h_)), sigma_a_(sigma_a) {
    // Longitudinal variances from beta_m (Chiang et al. 2016 equation 7); the roughness seen by
    // TT is half that of R and by TRT twice it (Marschner et al. 2003's widths), and the
    // residual orders take TRT's.
    v_[0] = sqr(0.726f * beta_m + 0.812f * sqr(beta_m) + 3.7f * std::pow(beta_m, 20.f));
    v_[1] = 0.25f * v_[0];
    v_[2] = 4 * v_[0];
    for (int p = 3; p <= PMax; ++p) v_[p] = v_[2];
    // Logistic scale from beta_n (Chiang et al. 2016 equation 8).
    const float sqrt_pi_over_8 = 0.626657069f;
    s_ = sqrt_pi_over_8 * (0.265f * beta_n + 1.194f * sqr(beta_n) + 5.372f * std::pow(beta_n, 22.f));
    // The scales tilt R by -2 alpha, TT by alpha and TRT by 4 alpha (Chiang et al. 2016
    // section 4.3): the sines and cosines of alpha, 2 alpha and 4 alpha by the double-angle
    // formulas.
    sin_2k_alpha_[0] = std::sin(radians(alpha));
    cos_2k_alpha_[0] = safe_sqrt(1 - sqr(sin_2k_alpha_[0]));
    for (int k = 1; k < PMax; ++k) {
        sin_2k_alpha_[k] = 2 * cos_2k_alpha_[k - 1] * sin_2k_alpha_[k - 1];
        cos_2k_alpha_[k] = sqr(cos_2k_alpha_[k - 1]) - sqr(sin_2k_alpha_[k - 1]);
    }
}

HairBxDF::Outgoing HairBxDF::outgoing(Vec3f wo) const {
    Outgoing o;
    o.sin_theta = clamp(wo.x, -1.f, 1.f);
    o.cos_theta = safe_sqrt(1 - sqr(o.sin_theta));
    o.phi = std::atan2(wo.z, wo.y);

    // The refracted ray: its longitudinal angle by Snell's law, and its azimuthal offset gamma_t
    // from Bravais' modified index eta' for the projection onto the normal plane.
    const float sin_theta_t = o.sin_theta / eta_;
    const float cos_theta_t = safe_sqrt(1 - sqr(sin_theta_t));
    const float etap = o.cos_theta > 0 ? safe_sqrt(sqr(eta_) - sqr(o.sin_theta)) / o.cos_theta : Infinity;
    const float sin_gamma_t = etap > 0 ? h_ / etap : 0.f;
    const float cos_gamma_t = safe_sqrt(1 - sqr(sin_gamma_t));
    o.gamma_t = safe_asin(sin_gamma_t);

    // Transmittance of one crossing of the interior: a chord of length 2 cos(gamma_t) in the
    // normal plane, lengthened by 1 / cos(theta_t) along the fibre.
    const SampledSpectrum t = exp(-sigma_a_ * (2 * cos_gamma_t / cos_theta_t));

    // Ap (Chiang et al. 2016 equation 3): Fresnel at the entry angle for R, two transmissions for
    // TT, one internal reflection more per order after that, and the geometric series of all the
    // orders from PMax on in the residual term.
    const float fr = fresnel_dielectric(o.cos_theta * safe_sqrt(1 - sqr(h_)), eta_);
    o.ap[0] = SampledSpectrum(fr);
    o.ap[1] = sqr(1 - fr) * t;
    for (int p = 2; p < PMax; ++p) o.ap[p] = o.ap[p - 1] * t * fr;
    for (int i = 0; i < NumWavelengths; ++i) {
        const float remaining = 1 - t[i] * fr;
        o.ap[PMax][i] = remaining > 0 ? o.ap[PMax - 1][i] * fr * t[i] / remaining : 0.f;
    }

    // Orders are sampled in proportion to their mean over the lanes.
    float sum = 0;
    for (const SampledSpectrum &a : o.ap) sum += a.average();
    for (int p = 0; p <= PMax; ++p) o.ap_pdf[p] = sum > 0 ? o.ap[p].average() / sum : 0.f;

    // theta_o tilted by the scales for R, TT and TRT. The cosine is taken as its magnitude,
    // as pbrt-v4 does, when a large tilt carries the direction over the pole.
    const float c = o.cos_theta, s = o.sin_theta;
    o.sin_tilted[0] = s * cos_2k_alpha_[1] - c * sin_2k_alpha_[1];
    o.cos_tilted[0] = c * cos_2k_alpha_[1] + s * sin_2k_alpha_[1];
    o.sin_tilted[1] = s * cos_2k_alpha_[0] + c * sin_2k_alpha_[0];
    o.cos_tilted[1] = c * cos_2k_alpha_[0] - s * sin_2k_alpha_[0];
    o.sin_tilted[2] = s * cos_2k_alpha_[2] + c * sin_2k_alpha_[2];
    o.cos_tilted[2] = c * cos_2k_alpha_[2] - s * sin_2k_alpha_[2];
    for (float &x : o.cos_tilted) x = std::abs(x);
    return o;
}

std::array<float, HairBxDF::PMax + 1> HairBxDF::lobes(const Outgoing &o, float sin_theta_i, float dphi) const {
    std::array<float, PMax + 1> l;
    const float cos_theta_i = safe_sqrt(1 - sqr(sin_theta_i));
    for (int p = 0; p < PMax; ++p) {
        // The exit azimuth of order p relative to the entry (Chiang et al. 2016 equation 4 with
        // d'Eon et al. 2011's gamma): p refractions through 2 gamma_t each, p half turns and the
        // reflection about the entry normal.
        float d = dphi - (2 * p * o.gamma_t - 2 * gamma_o_ + p * Pi);
        while (d > Pi) d -= 2 * Pi;
        while (d < -Pi) d += 2 * Pi;
        l[p] = longitudinal(cos_theta_i, o.cos_tilted[p], sin_theta_i, o.sin_tilted[p], v_[p]) *
               trimmed_logistic(d, s_);
    }
    // The residual orders: untilted, and uniform in azimuth.
    l[PMax] = longitudinal(cos_theta_i, o.cos_theta, sin_theta_i, o.sin_theta, v_[PMax]) * Inv2Pi;
    return l;
}

std::array<float, HairBxDF::PMax + 1> HairBxDF::lobes(const Outgoing &o, Vec3f wi) const {
    return lobes(o, clamp(wi.x, -1.f, 1.f), std::atan2(wi.z, wi.y) - o.phi);
}

namespace {

// f from the lobes: the sum of Mp Np Ap, divided by the cosine the integrators multiply by
// (left out at wi.z = 0, as pbrt-v4 does; BSDF rejects such directions).
SampledSpectrum hair_value(const std::array<float, HairBxDF::PMax + 1> &l,
                           const std::array<SampledSpectrum, HairBxDF::PMax + 1> &ap, Vec3f wi) {
    SampledSpectrum sum(0.f);
    for (int p = 0; p <= HairBxDF::PMax; ++p) sum += ap[p] * l[p];
    if (wi.z != 0) sum /= std::abs(wi.z);
    return sum;
}

float hair_pdf(const std::array<float, HairBxDF::PMax + 1> &l, const std::array<float, HairBxDF::PMax + 1> &ap_pdf) {
    float pdf = 0;
    for (int p = 0; p <= HairBxDF::PMax; ++p) pdf += ap_pdf[p] * l[p];
    return pdf;
}

} // namespace

SampledSpectrum HairBxDF::f(Vec3f wo, Vec3f wi, TransportMode) const {
    const Outgoing o = outgoing(wo);
    return hair_value(lobes(o, wi), o.ap, wi);
}

float HairBxDF::pdf(Vec3f wo, Vec3f wi, TransportMode, SampleFlags) const {
    const Outgoing o = outgoing(wo);
    return hair_pdf(lobes(o, wi), o.ap_pdf);
}

BxDFEvaluation HairBxDF::evaluate(Vec3f wo, Vec3f wi, TransportMode) const {
    const Outgoing o = outgoing(wo), i = outgoing(wi);
    const std::array<float, PMax + 1> l = lobes(o, wi);
    return {hair_value(l, o.ap, wi), hair_pdf(l, o.ap_pdf), hair_pdf(lobes(i, wo), i.ap_pdf)};
}

std::optional<BSDFSample> HairBxDF::sample_f(Vec3f wo, float uc, Vec2f u, TransportMode, SampleFlags) const {
    const Outgoing o = outgoing(wo);
    if (o.ap_pdf[0] + o.ap_pdf[1] + o.ap_pdf[2] + o.ap_pdf[3] == 0) return {};
    // The order, in proportion to Ap; uc is then reused for the azimuth.
    const int p = sample_discrete(o.ap_pdf, &uc);
    const float sin_o = p < PMax ? o.sin_tilted[p] : o.sin_theta;
    const float cos_o = p < PMax ? o.cos_tilted[p] : o.cos_theta;

    // Mp exactly (d'Eon et al. 2011 section 4.3 and Chiang et al. 2016): a direction from the von
    // Mises-Fisher lobe about the specular direction, at cos psi from it by inverting its cdf and
    // at azimuth 2 pi u1 about it, projected onto the fibre axis. pbrt-v4 clamps u0 to 1e-5,
    // which moves 1e-5 of the lobe's mass; u0 = 0 is the antipode, cos psi = -1, which the
    // logarithm reaches as -infinity when exp(-2 / v) underflows.
    const float v = v_[p];
    const float cos_psi = std::max(-1.f, 1 + v * std::log(u[0] + (1 - u[0]) * std::exp(-2 / v)));
    const float sin_psi = safe_sqrt(1 - sqr(cos_psi));
    const float sin_theta_i = clamp(-cos_psi * sin_o + sin_psi * std::cos(2 * Pi * u[1]) * cos_o, -1.f, 1.f);
    const float cos_theta_i = safe_sqrt(1 - sqr(sin_theta_i));

    // Np exactly: the order's exit azimuth plus a trimmed logistic offset; the residual orders
    // are uniform in azimuth.
    const float dphi = p < PMax ? 2 * p * o.gamma_t - 2 * gamma_o_ + p * Pi + sample_trimmed_logistic(uc, s_)
                                : 2 * Pi * uc;
    const float phi_i = o.phi + dphi;

    BSDFSample s;
    s.wi = Vec3f(sin_theta_i, cos_theta_i * std::cos(phi_i), cos_theta_i * std::sin(phi_i));
    // Value and density from wi itself, so that they equal f() and pdf() at it exactly.
    const std::array<float, PMax + 1> l = lobes(o, s.wi);
    s.f = hair_value(l, o.ap, s.wi);
    s.pdf = hair_pdf(l, o.ap_pdf);
    s.flags = BxDFGlossyReflection;
    if (!(s.pdf > 0)) return {};
    return s;
}

RGB HairBxDF::sigma_a_rgb_from_concentration(float ce, float cp) {
    const RGB eumelanin{0.419f, 0.697f, 1.37f}, pheomelanin{0.187f, 0.4f, 1.05f};
    return eumelanin * ce + pheomelanin * cp;
}

RGBUnboundedSpectrum HairBxDF::sigma_a_from_concentration(float ce, float cp) {
    return RGBUnboundedSpectrum(RGBColorSpace::srgb(), sigma_a_rgb_from_concentration(ce, cp));
}

SampledSpectrum HairBxDF::sigma_a_from_reflectance(const SampledSpectrum &c, float beta_n) {
    // A fit of log(c) against sqrt(sigma_a) over the renders of a white furnace: a fifth-degree
    // polynomial in beta_n.
    const float b = beta_n;
    const float d = 5.969f - 0.215f * b + 2.532f * sqr(b) - 10.73f * std::pow(b, 3.f) + 5.574f * std::pow(b, 4.f) +
                    0.245f * std::pow(b, 5.f);
    SampledSpectrum sigma_a;
    for (int i = 0; i < NumWavelengths; ++i) sigma_a[i] = sqr(std::log(c[i]) / d);
    return sigma_a;
}

} // namespace caustica
