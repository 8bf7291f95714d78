// The BxDF interface: scattering functions in a local shading frame where the normal is +z.
//
// Every query takes a TransportMode: Radiance when the path was started at the camera,
// Importance when it was started at a light. The two differ for refraction (the 1/eta^2 radiance
// spreading factor applies to radiance only: Veach 1997 section 5.2, Burley 2015 section 2.2)
// and for shading normals (handled by the integrators, Veach 1997 section 5.3).
#pragma once

#include "core/scratch_buffer.h"
#include "core/vecmath.h"
#include "spectral/sampled_spectrum.h"

#include <optional>

namespace caustica {

struct Reradiation;

enum class TransportMode { Radiance, Importance };

// The mode of the other end's subpath: densities of the reverse direction are its.
inline TransportMode adjoint(TransportMode mode) {
    return mode == TransportMode::Radiance ? TransportMode::Importance : TransportMode::Radiance;
}

enum BxDFFlags : unsigned {
    BxDFUnset = 0,
    BxDFReflection = 1 << 0,
    BxDFTransmission = 1 << 1,
    BxDFDiffuse = 1 << 2,
    BxDFGlossy = 1 << 3,
    BxDFSpecular = 1 << 4,
    BxDFDiffuseReflection = BxDFDiffuse | BxDFReflection,
    BxDFDiffuseTransmission = BxDFDiffuse | BxDFTransmission,
    BxDFGlossyReflection = BxDFGlossy | BxDFReflection,
    BxDFGlossyTransmission = BxDFGlossy | BxDFTransmission,
    BxDFSpecularReflection = BxDFSpecular | BxDFReflection,
    BxDFSpecularTransmission = BxDFSpecular | BxDFTransmission,
    BxDFAll = BxDFDiffuse | BxDFGlossy | BxDFSpecular | BxDFReflection | BxDFTransmission,
};
inline BxDFFlags operator|(BxDFFlags a, BxDFFlags b) { return BxDFFlags(unsigned(a) | unsigned(b)); }
inline bool is_reflective(unsigned f) { return f & BxDFReflection; }
inline bool is_transmissive(unsigned f) { return f & BxDFTransmission; }
inline bool is_diffuse(unsigned f) { return f & BxDFDiffuse; }
inline bool is_glossy(unsigned f) { return f & BxDFGlossy; }
inline bool is_specular(unsigned f) { return f & BxDFSpecular; }
inline bool is_non_specular(unsigned f) { return f & (BxDFDiffuse | BxDFGlossy); }

// Which hemispheres a sampling or pdf query may consider.
enum class SampleFlags : unsigned { Reflection = 1, Transmission = 2, All = 3 };
inline bool allows(SampleFlags f, SampleFlags bit) { return unsigned(f) & unsigned(bit); }

struct BSDFSample {
    SampledSpectrum f;
    Vec3f wi;
    float pdf = 0;
    BxDFFlags flags = BxDFUnset;
    // Relative IOR across the boundary for transmission (1 for reflection): lets integrators
    // undo the eta^2 factor in Russian roulette throughput.
    float eta = 1;
    // True when the scattering direction depends on wavelength (refraction through a dispersive
    // medium, or a near-specular rough one): the integrator must call terminate_secondary().
    bool dispersive = false;
    // True when pdf is the density of a strategy other than the BxDF's own (never in practice
    // for the BxDFs here, kept so integrators can skip MIS with such samples).
    bool pdf_is_proportional = false;
    // From BxDF::sample_f_as (a BxDF with lane lobes): per wavelength, the density with which
    // sample_f_as(that lane, wo, ...) returns wi. pdf is the sampling lane's entry. Empty when
    // every lane samples wi alike (reflections, and every other BxDF).
    std::optional<SampledSpectrum> lane_pdf;

    bool is_reflection() const { return caustica::is_reflective(flags); }
    bool is_transmission() const { return caustica::is_transmissive(flags); }
    bool is_specular() const { return caustica::is_specular(flags); }
};

// What a connection or a merge needs of a scattering function at once: its value for (wo, wi),
// the density of sampling wi from wo in the path's transport mode, and that of sampling wo from
// wi in the adjoint mode (the other subpath's direction).
struct BxDFEvaluation {
    SampledSpectrum f;
    float pdf_forward = 0, pdf_reverse = 0;
};

class BxDF {
  public:
    // Value of the BxDF for the pair (wo, wi), both in the local frame, pointing away from the
    // surface. Zero for specular lobes.
    virtual SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode mode) const = 0;
    // Samples wi given wo; uc selects the lobe, u2 the direction. Empty when no sample exists.
    virtual std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u2, TransportMode mode,
                                               SampleFlags flags = SampleFlags::All) const = 0;
    // Solid-angle density with which sample_f(wo, ...) returns wi. Zero for specular lobes.
    virtual float pdf(Vec3f wo, Vec3f wi, TransportMode mode,
                      SampleFlags flags = SampleFlags::All) const = 0;
    virtual BxDFFlags flags() const = 0;

    // Lane lobes: the glossy lobes differ between the carried wavelengths (rough refraction
    // through a dispersive index), so that no one wavelength's sampling suits them all. Such a
    // BxDF samples as any one lane would (sample_f_as) and reports every lane's density of the
    // result (BSDFSample::lane_pdf), for the spectral MIS of the whole subpath
    // (integrators/common/spectral_mis.h). Its sample_f draws the lane from uc, and its pdf is
    // the lanes' mean: the density of sampling with a lane chosen uniformly at each call.
    virtual bool has_lane_lobes() const { return false; }
    virtual std::optional<BSDFSample> sample_f_as(int lane, Vec3f wo, float uc, Vec2f u, TransportMode mode) const {
        (void)lane;
        return sample_f(wo, uc, u, mode);
    }

    // The BxDF with its microfacet lobes widened by path regularisation
    // (TrowbridgeReitzDistribution::regularized), made in scratch; itself when it has none to
    // widen (diffuse, measured, hair and Disney lobes, as pbrt-v4 leaves its non-microfacet
    // BxDFs).
    virtual const BxDF *regularized(ScratchBuffer &scratch) const {
        (void)scratch;
        return this;
    }

    // A fluorescent surface's wavelength-shifting part (fluorescent_bxdf.h), which the walk
    // samples itself; null for every other BxDF.
    virtual const Reradiation *reradiation() const { return nullptr; }
    // f and both densities in one call, for BxDFs that share work between them (the default
    // makes the three calls).
    virtual BxDFEvaluation evaluate(Vec3f wo, Vec3f wi, TransportMode mode) const {
        return {f(wo, wi, mode), pdf(wo, wi, mode), pdf(wi, wo, adjoint(mode))};
    }

  protected:
    // BxDFs live in a ScratchBuffer and are never destroyed through a base pointer.
    ~BxDF() = default;
};

} // namespace caustica
