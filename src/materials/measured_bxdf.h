// Measured reflectance from the RGL material database: Dupuy and Jakob 2018, "An Adaptive
// Parameterization for Efficient Material Acquisition and Rendering", read from their .bsdf files
// (a tensor file: materials/tensor_file.h) as pbrt-v4's MeasuredBxDF reads them.
//
// A file tabulates, for incident directions wo on a grid of (theta_i, phi_i):
//   ndf      the microfacet distribution D(wm);
//   sigma    the projected area of the microsurface seen from wo;
//   vndf     the distribution of normals visible from wo, a PiecewiseLinear2D warp from a
//            "sample space" [0,1]^2 to the normals' square u_wm (below);
//   spectra  the reflectance factor at each tabulated wavelength, over the sample space: where
//            the acquisition measured, the grid is dense in the sample space;
//   luminance a density over the sample space (the spectra's luminance) to sample by.
// Directions are mapped to the unit square by u = (sqrt(theta / (pi / 2)), phi / (2 pi) + 1/2);
// isotropic files (at most two phi_i) use the normal's azimuth relative to wo's. With wm the half
// vector of wo and wi, and u_s the sample-space point the vndf warp takes to u_wm,
//   f(wo, wi) = spectra(u_s; wo, lambda) D(wm) / (4 sigma(wo) cos theta_i).
// Sampling warps the 2D sample by the luminance and then by the vndf, and reflects wo about the
// normal found; its density is the two warps' densities over the Jacobian 4 (wo . wm) 2 pi^2
// u_wm.x sin theta_m from u_wm to wi (pbrt-v4's, which bounds it below by 1e-6).
//
// Transport modes. The tables are conditioned on one direction, wo, which sampling starts from.
// Measured reflectance is reciprocal only as far as the acquisition was exact, so the function of
// (wo, wi) tabulated is not quite symmetric. pbrt-v4 evaluates it with the camera-side direction
// as wo; so does Caustica on camera paths, and on light paths (where wo is the light side) it
// evaluates the same function with the directions exchanged, so that every integrator renders the
// same reflectance. Sampling starts from wo in both modes; its density is the same, and its
// samples carry the value of the mode's function. Reflection only, on the side of wo.
#pragma once

#include "core/piecewise_linear_2d.h"
#include "materials/bxdf.h"
#include "spectral/sampled_wavelengths.h"

#include <memory>
#include <string>
#include <vector>

namespace caustica {

class MeasuredBRDF {
  public:
    // Reads and checks the file at path; a file read before is shared. Throws InputError
    // (without a location) when it cannot be read, is not a tensor file, or lacks a field or has
    // one of the wrong type or shape, as pbrt-v4 checks them; also for anisotropic files that
    // cover only part of the azimuths (pbrt-v4 supports only whole turns), and for tables with
    // values that are not finite, or densities that are negative or zero everywhere.
    static std::shared_ptr<const MeasuredBRDF> read(const std::string &path);

    bool isotropic() const { return isotropic_; }

  private:
    friend class MeasuredBxDF;
    MeasuredBRDF(PiecewiseLinear2D ndf, PiecewiseLinear2D sigma, PiecewiseLinear2D vndf, PiecewiseLinear2D luminance,
                 PiecewiseLinear2D spectra, bool isotropic)
        : ndf_(std::move(ndf)), sigma_(std::move(sigma)), vndf_(std::move(vndf)), luminance_(std::move(luminance)),
          spectra_(std::move(spectra)), isotropic_(isotropic) {}

    PiecewiseLinear2D ndf_, sigma_, vndf_, luminance_, spectra_;
    bool isotropic_;
};

class MeasuredBxDF final : public BxDF {
  public:
    MeasuredBxDF(const MeasuredBRDF *brdf, const SampledWavelengths &lambda) : brdf_(brdf), lambda_(lambda) {}

    SampledSpectrum f(Vec3f wo, Vec3f wi, TransportMode mode) const override;
    std::optional<BSDFSample> sample_f(Vec3f wo, float uc, Vec2f u, TransportMode mode,
                                       SampleFlags flags = SampleFlags::All) const override;
    float pdf(Vec3f wo, Vec3f wi, TransportMode mode, SampleFlags flags = SampleFlags::All) const override;
    BxDFEvaluation evaluate(Vec3f wo, Vec3f wi, TransportMode mode) const override;
    BxDFFlags flags() const override { return BxDFGlossyReflection; }

  private:
    // A pair of directions (a the tables' wo, b the other) on a's side, as the tables see it.
    struct Pair {
        bool valid = false;
        Vec3f a, b, wm;
        float theta_a, phi_a;
        Vec2f u_wm;
        PiecewiseLinear2D::Sample sample_space;  // the vndf warp's inverse at u_wm
    };
    Pair pair(Vec3f a, Vec3f b) const;
    // The tabulated function f(a, b) and the density of sampling b from a.
    SampledSpectrum value(const Pair &p) const;
    float density(const Pair &p) const;

    const MeasuredBRDF *brdf_;
    SampledWavelengths lambda_;
};

} // namespace caustica
