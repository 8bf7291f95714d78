#include "materials/layered_bxdf.h"

#include "core/rng.h"
#include "core/sampling.h"

#include <bit>
#include <cmath>
#include <limits>

namespace caustica {

namespace {

uint32_t bits(float v) { return std::bit_cast<uint32_t>(v); }

uint64_t direction_hash(Vec3f w) { return hash_values(bits(w.x), bits(w.y), bits(w.z)); }

// Usable as an interface sample: a direction off the plane with a positive density.
bool usable(const std::optional<BSDFSample> &s) {
    return s && !s->f.is_black() && s->pdf > 0 && s->wi.z != 0;
}

// Russian roulette inside the walks starts after a few events, once the throughput is low
// (pbrt-v4 14.3.2).
constexpr int RouletteDepth = 3;
constexpr float RouletteThroughput = 0.25f;

// A walk's f and pdf are products of one factor per event, each often well below 1 (a phase
// function is 1 / (4 pi) on average): over a long walk both would underflow in float, though
// their ratio, the weight, stays near 1. Only the ratio is used (the sample's pdf is
// proportional), so both are scaled up together when the pdf gets small.
void keep_in_range(SampledSpectrum &f, float &pdf) {
    constexpr float Small = 1e-10f, Scale = 1e10f;
    if (pdf < Small) {
        f *= Scale;
        pdf *= Scale;
    }
}

// Weight of the estimated density in pdf(); the rest is uniform over the sphere (pbrt-v4 14.3.3).
constexpr float EstimateWeight = 0.9f;

} // namespace

LayeredBxDF::LayeredBxDF(const DielectricBxDF *top, const BxDF *bottom, const LayerMedium &medium,
                         int max_depth, int n_samples, bool dispersive_coat)
    : top_(top), bottom_(bottom), medium_(medium), phase_(medium.g), max_depth_(max_depth),
      n_samples_(n_samples), dispersive_coat_(dispersive_coat) {
    medium_.thickness = std::max(medium_.thickness, std::numeric_limits<float>::min());
}

float LayeredBxDF::virtual_light_pdf(Vec3f wi, Vec3f w, TransportMode mode) const {
    return top_->pdf(wi, -w, adjoint(mode), SampleFlags::Transmission);
}

float LayeredBxDF::transmittance(float dz, Vec3f w) {
    if (std::abs(dz) <= std::numeric_limits<float>::min()) return 1;
    return std::exp(-std::abs(dz / w.z));
}

BxDFFlags LayeredBxDF::flags() const {
    const BxDFFlags top = top_->flags(), bottom = bottom_->flags();
    BxDFFlags f = BxDFReflection;
    if (is_specular(top)) f = f | BxDFSpecular;
    if (is_diffuse(top) || is_diffuse(bottom) || !medium_.albedo.is_black())
        f = f | BxDFDiffuse;
    else if (is_glossy(top) || is_glossy(bottom))
        f = f | BxDFGlossy;
    return f;
}

SampledSpectrum LayeredBxDF::f(Vec3f wo, Vec3f wi, TransportMode mode) const {
    if (wo.z < 0) {
        wo = -wo;
        wi = -wi;
    }
    // The base is opaque: light leaves on the side it came from, through the coat.
    if (!same_hemisphere(wo, wi)) return {};
    const float thickness = medium_.thickness;
    const bool scattering_slab = !medium_.albedo.is_black();
    const bool top_specular = !is_non_specular(top_->flags());
    const bool bottom_specular = !is_non_specular(bottom_->flags());

    // Reflection by the coat itself (zero for a smooth coat, whose delta f does not represent).
    SampledSpectrum result = top_->f(wo, wi, mode) * float(n_samples_);

    Rng rng(direction_hash(wo), direction_hash(wi));
    auto r = [&rng] { return rng.uniform(); };
    for (int s = 0; s < n_samples_; ++s) {
        // The walk enters through the coat from wo; the exit towards wi is met by next-event
        // estimation along wis, a direction sampled through the coat from wi with the adjoint
        // transport mode (light arriving from wi, Guo et al. 2018 section 5.2).
        std::optional<BSDFSample> wos = top_->sample_f(wo, r(), Vec2f(r(), r()), mode, SampleFlags::Transmission);
        if (!usable(wos)) continue;
        std::optional<BSDFSample> wis =
            top_->sample_f(wi, r(), Vec2f(r(), r()), adjoint(mode), SampleFlags::Transmission);
        if (!usable(wis)) continue;

        SampledSpectrum beta = wos->f * (std::abs(wos->wi.z) / wos->pdf);
        float z = thickness;
        Vec3f w = wos->wi;
        for (int depth = 0; depth < max_depth_; ++depth) {
            if (depth > RouletteDepth && beta.max_value() < RouletteThroughput) {
                const float q = std::max(0.f, 1 - beta.max_value());
                if (r() < q) break;
                beta /= 1 - q;
            }
            if (!scattering_slab) {
                z = z == thickness ? 0.f : thickness;
                beta *= transmittance(thickness, w);
            } else {
                // Free flight with unit extinction: the distance along w is exponential, its
                // height change that times |w.z|.
                const float dz = -std::log(1 - r()) * std::abs(w.z);
                const float zp = w.z > 0 ? z + dz : z - dz;
                if (0 < zp && zp < thickness) {
                    // Scattering inside the slab: connect to the virtual light through the coat,
                    // then continue by the phase function, whose direction may itself leave
                    // through a rough coat (both strategies MIS-weighted).
                    float wt = 1;
                    if (!top_specular) wt = power_heuristic(1, wis->pdf, 1, phase_.pdf(-w, -wis->wi));
                    result += beta * medium_.albedo * (phase_.p(-w, -wis->wi) * wt) *
                              transmittance(zp - thickness, wis->wi) * wis->f / wis->pdf;
                    const PhaseSample ps = phase_.sample_p(-w, Vec2f(r(), r()));
                    if (!(ps.p > 0) || ps.wi.z == 0) break;
                    beta *= medium_.albedo;  // p / pdf = 1: the phase function is sampled exactly
                    w = ps.wi;
                    z = zp;
                    if (w.z > 0 && !top_specular) {
                        const SampledSpectrum f_exit = top_->f(-w, wi, mode);
                        if (!f_exit.is_black()) {
                            result += beta * transmittance(zp - thickness, w) * f_exit *
                                      power_heuristic(1, ps.p, 1, virtual_light_pdf(wi, w, mode));
                        }
                    }
                    continue;
                }
                z = clamp(zp, 0.f, thickness);
            }
            if (z == thickness) {
                // Back at the coat from below: only its internal reflection keeps the walk inside
                // (leaving towards wi is counted by the connections).
                std::optional<BSDFSample> bs =
                    top_->sample_f(-w, r(), Vec2f(r(), r()), mode, SampleFlags::Reflection);
                if (!usable(bs)) break;
                beta *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
                w = bs->wi;
                continue;
            }
            // At the base: connect to the virtual light, then scatter by sampling the base.
            if (!bottom_specular) {
                float wt = 1;
                if (!top_specular) wt = power_heuristic(1, wis->pdf, 1, bottom_->pdf(-w, -wis->wi, mode));
                result += beta * bottom_->f(-w, -wis->wi, mode) * (std::abs(wis->wi.z) * wt) *
                          transmittance(thickness, wis->wi) * wis->f / wis->pdf;
            }
            std::optional<BSDFSample> bs = bottom_->sample_f(-w, r(), Vec2f(r(), r()), mode, SampleFlags::Reflection);
            if (!usable(bs)) break;
            beta *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
            w = bs->wi;
            if (!top_specular) {
                // The sampled direction may leave through the rough coat towards wi directly.
                const SampledSpectrum f_exit = top_->f(-w, wi, mode);
                if (!f_exit.is_black()) {
                    float wt = 1;
                    if (!bottom_specular)
                        wt = power_heuristic(1, bs->pdf, 1, virtual_light_pdf(wi, w, mode));
                    result += beta * transmittance(thickness, bs->wi) * f_exit * wt;
                }
            }
        }
    }
    return result / float(n_samples_);
}

std::optional<BSDFSample> LayeredBxDF::sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                                SampleFlags flags) const {
    if (!allows(flags, SampleFlags::Reflection)) return {};
    const bool flip = wo.z < 0;
    if (flip) wo = -wo;

    std::optional<BSDFSample> bs = top_->sample_f(wo, uc, u, mode);
    if (!usable(bs)) return {};
    if (bs->is_reflection()) {
        // Reflected by the coat: its own f and density. pdf() estimates the whole BSDF's density
        // for MIS; a delta needs none.
        if (flip) bs->wi = -bs->wi;
        bs->pdf_is_proportional = !bs->is_specular();
        return bs;
    }

    // The walk's throughput is kept as f / pdf, both accumulated along it (Guo et al. 2018,
    // section 4): the sample reports their ratio as its weight.
    Rng rng(direction_hash(wo), hash_values(bits(uc), bits(u.x), bits(u.y)));
    auto r = [&rng] { return rng.uniform(); };
    const float thickness = medium_.thickness;
    const bool scattering_slab = !medium_.albedo.is_black();
    SampledSpectrum f = bs->f * std::abs(bs->wi.z);
    float pdf = bs->pdf;
    bool specular_path = bs->is_specular();
    Vec3f w = bs->wi;
    float z = thickness;
    for (int depth = 0; depth < max_depth_; ++depth) {
        const float rr_beta = f.max_value() / pdf;
        if (depth > RouletteDepth && rr_beta < RouletteThroughput) {
            const float q = std::max(0.f, 1 - rr_beta);
            if (r() < q) return {};
            pdf *= 1 - q;
        }
        if (w.z == 0) return {};
        if (scattering_slab) {
            const float dz = -std::log(1 - r()) * std::abs(w.z);
            const float zp = w.z > 0 ? z + dz : z - dz;
            if (zp == z) return {};
            if (0 < zp && zp < thickness) {
                const PhaseSample ps = phase_.sample_p(-w, Vec2f(r(), r()));
                if (!(ps.p > 0) || ps.wi.z == 0) return {};
                f *= medium_.albedo * ps.p;
                pdf *= ps.p;
                keep_in_range(f, pdf);
                specular_path = false;
                w = ps.wi;
                z = zp;
                continue;
            }
            z = clamp(zp, 0.f, thickness);
        } else {
            z = z == thickness ? 0.f : thickness;
            f *= transmittance(thickness, w);
        }
        const BxDF *interface = z == 0 ? static_cast<const BxDF *>(bottom_) : top_;
        std::optional<BSDFSample> s = interface->sample_f(-w, r(), Vec2f(r(), r()), mode);
        if (!usable(s)) return {};
        f *= s->f;
        pdf *= s->pdf;
        keep_in_range(f, pdf);
        specular_path = specular_path && s->is_specular();
        w = s->wi;
        if (s->is_transmission()) {
            // Out through the coat, on wo's side (the base transmits nothing).
            BSDFSample out;
            out.f = f;
            out.wi = flip ? -w : w;
            out.pdf = pdf;
            out.flags = specular_path ? BxDFSpecularReflection : BxDFGlossyReflection;
            out.pdf_is_proportional = !specular_path;
            out.dispersive = dispersive_coat_;
            return out;
        }
        f *= std::abs(s->wi.z);
    }
    return {};
}

float LayeredBxDF::pdf(Vec3f wo, Vec3f wi, TransportMode mode, SampleFlags flags) const {
    if (!allows(flags, SampleFlags::Reflection)) return 0;
    if (wo.z < 0) {
        wo = -wo;
        wi = -wi;
    }
    if (!same_hemisphere(wo, wi)) return 0;
    // The coat's reflection, plus the paths that cross the coat, reflect once at the base and
    // leave: the density of the latter is the integral over the two internal directions, which
    // one sample of each interface estimates (pbrt-v4 14.3.3); higher orders are left to the
    // uniform share.
    float sum = n_samples_ * top_->pdf(wo, wi, mode, SampleFlags::Reflection);
    Rng rng(direction_hash(wi), direction_hash(wo));
    auto r = [&rng] { return rng.uniform(); };
    const bool top_specular = !is_non_specular(top_->flags());
    const bool bottom_specular = !is_non_specular(bottom_->flags());
    for (int s = 0; s < n_samples_; ++s) {
        std::optional<BSDFSample> wos = top_->sample_f(wo, r(), Vec2f(r(), r()), mode, SampleFlags::Transmission);
        std::optional<BSDFSample> wis =
            top_->sample_f(wi, r(), Vec2f(r(), r()), adjoint(mode), SampleFlags::Transmission);
        if (!usable(wos) || !usable(wis)) continue;
        if (top_specular) {
            sum += bottom_->pdf(-wos->wi, -wis->wi, mode);
            continue;
        }
        std::optional<BSDFSample> rs = bottom_->sample_f(-wos->wi, r(), Vec2f(r(), r()), mode);
        if (!usable(rs)) continue;
        if (bottom_specular) {
            sum += top_->pdf(-rs->wi, wi, mode);
            continue;
        }
        // Both interfaces rough: the base's density at the direction sampled from wi, and the
        // coat's at the direction sampled from the base, combined by MIS.
        const float r_pdf = bottom_->pdf(-wos->wi, -wis->wi, mode);
        sum += power_heuristic(1, wis->pdf, 1, r_pdf) * r_pdf;
        const float t_pdf = top_->pdf(-rs->wi, wi, mode);
        sum += power_heuristic(1, rs->pdf, 1, t_pdf) * t_pdf;
    }
    return lerp(EstimateWeight, Inv4Pi, sum / n_samples_);
}

} // namespace caustica
