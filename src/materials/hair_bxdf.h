// Scattering from a hair or fur fibre: Chiang, Bitterli, Tappan and Burley 2016, "A Practical and
// Controllable Hair and Fur Model for Production Path Tracing", as pbrt-v4's HairBxDF (4th ed.
// section 9.9). The fibre is a dielectric cylinder (index eta) with an absorbing interior
// (sigma_a per unit of fibre radius) whose surface scales are tilted by alpha degrees.
//
// Light leaving the fibre has taken p internal paths: p = 0 reflects at the surface (R), p = 1
// is transmitted twice (TT), p = 2 is reflected once inside (TRT), and the orders from pMax = 3
// on are lumped into one residual term. Each order is a product of
//   Mp  the longitudinal lobe, a distribution of theta_i about the specular cone of the tilted
//       theta_o, with variance v[p] (d'Eon, Francois, Hill, Letteri and Aubry 2011, "An Energy-
//       Conserving Hair Reflectance Model": the marginal of a von Mises-Fisher lobe on the cone);
//   Ap  the attenuation by Fresnel reflection and absorption along the p-th path;
//   Np  the azimuthal lobe, a logistic distribution (scale s) about the exit angle of the path
//       through the cylinder, trimmed to [-pi, pi].
//
// Local frame (pbrt-v4's, which the BSDF's Frame::from_xz(dpdu, n) gives for a curve): x runs
// along the fibre, so sin(theta) = w.x, and the azimuth about it is phi = atan2(w.z, w.y). h in
// [-1, 1] is where the ray met the fibre across its width (h = -1 + 2 v on pbrt-v4's curves).
//
// f(wo, wi) |cos theta_n(wi)| = sum_p Mp Ap Np, with cos theta_n(wi) = wi.z the cosine to the
// shading normal that the integrators multiply by. Sampling picks an order in proportion to the
// lanes' mean Ap and then samples Mp and Np exactly, so pdf(wo, wi) = sum_p Mp Np Ap / sum Ap:
// without absorption (sigma_a = 0, sum Ap = 1) every sample's weight f |cos| / pdf is 1.
//
// As in pbrt-v4, the model is the same in both transport modes and reports itself as glossy
// reflection (for every sample, whichever side of the shading normal wi lies on); sampling and
// pdf ignore SampleFlags, as pbrt-v4's do. It is not reciprocal: Ap and the azimuthal shift
// depend on theta_o alone, and the scale tilts differ between the lobes. With no tilt and
// |sin theta_i| = |sin theta_o|, f(wo, wi; h) |wi.z| = f(wi, wo; -h) |wo.z| exactly.
//
// Differences from pbrt-v4: I0 in Mp is exact to float (pbrt-v4's 10-term series is up to 2%
// low for arguments near 12, so its f is on average 0.06% lower, at most 2%), and sampling Mp
// uses the first random number as it is, where pbrt-v4 clamps it to 1e-5. Everything else,
// including the frame and the per-lobe tilts, is pbrt-v4's.
#pragma once

#include "materials/bxdf.h"
#include "spectral/rgb_spectrum.h"

#include <array>

namespace caustica {

class HairBxDF final : public BxDF {
  public:
    // h in [-1, 1], beta_m and beta_n in (0, 1] (longitudinal and azimuthal roughness), alpha the
    // scale tilt in degrees; sigma_a >= 0 per wavelength.
    HairBxDF(float h, float eta, const SampledSpectrum &sigma_a, float beta_m, float beta_n, float alpha);

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode mode) const override;
    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override;
    float pdf(Vec3f wo, Vec3f wi, TransportMode mode, SampleFlags flags = SampleFlags::All) const override;
    BxDFEvaluation evaluate(Vec3f wo, Vec3f wi, TransportMode mode) const override;
    BxDFFlags flags() const override { return BxDFGlossyReflection; }

    // Absorption of a fibre with eumelanin concentration ce and pheomelanin concentration cp
    // (Chiang et al. 2016 section 4.2, after d'Eon et al. 2011): sRGB coefficients, upsampled
    // as an unbounded spectrum as pbrt-v4 does.
    static RGB sigma_a_rgb_from_concentration(float ce, float cp);
    static RGBUnboundedSpectrum sigma_a_from_concentration(float ce, float cp);
    // The absorption that gives a fibre the multiply-scattered colour c (per wavelength, in
    // [0, 1]) for azimuthal roughness beta_n: Chiang et al. 2016 section 4.2, equation 9.
    static SampledSpectrum sigma_a_from_reflectance(const SampledSpectrum &c, float beta_n);

    static constexpr int PMax = 3;

  private:
    // Everything f and pdf need that depends on wo alone.
    struct Outgoing {
        float sin_theta, cos_theta, phi, gamma_t;
        std::array<SampledSpectrum, PMax + 1> ap;
        std::array<float, PMax + 1> ap_pdf;  // order-selection probabilities; all 0 if none
        // sin and cos of theta_o tilted by the scales, for the orders 0 to PMax - 1.
        std::array<float, PMax> sin_tilted, cos_tilted;
    };
    Outgoing outgoing(Vec3f wo) const;
    // Mp Np for each order (the residual order's Np is 1 / (2 pi)), for wi seen from o.
    std::array<float, PMax + 1> lobes(const Outgoing &o, Vec3f wi) const;
    std::array<float, PMax + 1> lobes(const Outgoing &o, float sin_theta_i, float dphi) const;

    float h_, eta_, gamma_o_;
    SampledSpectrum sigma_a_;
    float v_[PMax + 1];  // longitudinal variances
    float s_;            // logistic scale of the azimuthal lobes
    // sin and cos of 2^k alpha for k = 0, 1, 2.
    float sin_2k_alpha_[PMax], cos_2k_alpha_[PMax];
};

} // namespace caustica
