// Media whose coefficients vary in space, inside an axis-aligned box of the medium's own space
// (pbrt-v4's "p0"/"p1", placed by the transform in effect at MakeNamedMedium); outside the box
// they are empty. What the concrete media (grid_media.h, cloud_medium.h, nanovdb_medium.h) define
// is the coefficients at a point and a majorant grid; this base does the sampling, once for all:
//
// - Free-flight distances by delta tracking (Woodcock et al. 1965; Novák et al. 2018, "Monte Carlo
//   Methods for Physically Based Volume Rendering"): tentative collisions at the rate of the
//   majorant sigma_maj of the lane's wavelength, each real with probability sigma_t / sigma_maj
//   and null otherwise. Every tentative collision is a vertex of the null-scattering path
//   integral (Miller et al. 2019, "A Null-Scattering Path Integral Formulation of Light
//   Transport"), so the chain of null collisions has an exact density under every wavelength's
//   coefficients: the product of T_maj sigma_n over the nulls, times T_maj sigma_t at the real
//   collision (or T_maj at the end). MediumEvent reports that chain's contribution and density
//   per wavelength, and the path's spectral MIS (SpectralMIS) weighs it as it weighs a
//   homogeneous free flight: this is pbrt-v4's r_u bookkeeping in VolPathIntegrator. A real
//   collision scatters with weight sigma_s / sigma_t, as in the homogeneous media (absorption is
//   not sampled as an event). In an emissive medium it also reports the emission there,
//   T sigma_a Le (MediumEvent::emitted): the collision estimator of the emission along the ray.
// - Transmittance by ratio tracking (Cramer 1978; Novák et al. 2014, "Residual Ratio Tracking for
//   Estimating Attenuation in Participating Media"): the product of sigma_n / sigma_maj over
//   tentative collisions at the rate of the largest majorant over the carried wavelengths, an
//   unbiased estimate for every wavelength at once, with Russian roulette once it falls below
//   0.05 (as pbrt-v4 does).
//
// The random numbers beyond the one the path's sampler provides come from a PCG32 stream seeded
// by that number and the ray, so a render stays reproducible and independent of thread count.
//
// Light paths that start in an emissive medium (lt, sppm) choose their start by the emission
// integrated over the cells of the majorant grid: each cell's sigma_a Le, averaged over 4^3
// points at eight wavelengths drawn by the visible density, gives 90% of the choice, and every cell where sigma_t
// can be non-zero shares the other 10% alike, so that no emitting cell the averages missed has
// zero density. Within the cell the point is uniform.
#pragma once

#include "core/sampling.h"
#include "core/transform.h"
#include "media/majorant_grid.h"
#include "media/medium.h"
#include "spectral/spectrum.h"

#include <mutex>
#include <optional>
#include <vector>

namespace caustica {

class HeterogeneousMedium : public Medium {
  public:
    MediumProperties properties(Vec3f p, const SampledWavelengths &lambda) const override;
    SampledSpectrum max_sigma_t(const SampledWavelengths &lambda) const override {
        return majorant_scale(lambda) * majorants_.max_bound();
    }
    const HenyeyGreenstein &phase() const override { return phase_; }
    SampledSpectrum transmittance(const Ray &ray, float distance, const SampledWavelengths &lambda) const override;
    MediumEvent sample_distance(const Ray &ray, float t_max, const SampledWavelengths &lambda, int lane,
                                float u_distance) const override;
    SampledSpectrum Le(Vec3f p, const SampledWavelengths &lambda) const override;
    bool has_emission_sampling() const override { return is_emissive(); }
    std::optional<EmissionPoint> sample_emission_point(float u_cell, Vec3f u_within) const override;
    float emission_point_pdf(Vec3f p) const override;
    SampledSpectrum emitted_power(const SampledWavelengths &lambda) const override;

  protected:
    // bounds: the box of the medium's space the coefficients fill; majorants: over that box as
    // the unit cube, cell bounds b such that b * majorant_scale(lambda) >= sigma_t anywhere in
    // the cell, at every wavelength.
    HeterogeneousMedium(const Transform &render_from_medium, const Bounds3f &bounds, float g, MajorantGrid majorants);
    ~HeterogeneousMedium() = default;

    // The coefficients at point u of the unit cube over the bounds.
    virtual MediumProperties local(Vec3f u, const SampledWavelengths &lambda) const = 0;
    // Per wavelength, the factor that turns a majorant cell's bound into sigma_maj.
    virtual SampledSpectrum majorant_scale(const SampledWavelengths &lambda) const = 0;
    // Whether sigma_s can be non-zero at any of the first `carried` wavelengths anywhere.
    virtual bool may_scatter(const SampledWavelengths &lambda, int carried) const = 0;
    // Emissive media: the emitted radiance Le at point u of the unit cube.
    virtual SampledSpectrum local_Le(Vec3f u, const SampledWavelengths &lambda) const {
        (void)u;
        (void)lambda;
        return SampledSpectrum(0.f);
    }

  private:
    // The ray in unit-cube coordinates (the same parameter t, as d is only scaled).
    void to_unit_cube(const Ray &ray, Vec3f *o, Vec3f *d) const;
    // Point p in unit-cube coordinates, or nullopt outside the box.
    std::optional<Vec3f> unit_cube_point(Vec3f p) const;
    // Per majorant cell, the mean of sigma_a Le over 4^3 points of the cell.
    std::vector<SampledSpectrum> cell_emission(const SampledWavelengths &lambda) const;
    // The choice of a start cell (see above), built on first use.
    const DiscreteDistribution &emission_cells() const;

    Transform medium_from_render_;
    Transform render_from_unit_cube_;
    float render_volume_; // of the box, in render space
    Vec3f lo_, inverse_extent_;
    HenyeyGreenstein phase_;
    MajorantGrid majorants_;
    mutable std::once_flag emission_cells_built_;
    mutable DiscreteDistribution emission_cells_;
};

// A heterogeneous medium whose coefficients are one scalar density field d(u) times spectra:
// sigma_a(p) = d scale sigma_a, sigma_s(p) = d scale sigma_s (pbrt-v4's uniformgrid, cloud and
// nanovdb). Its majorant cells bound d, and sigma_maj is that bound times scale sigma_t.
class ScalarDensityMedium : public HeterogeneousMedium {
  protected:
    ScalarDensityMedium(const Transform &render_from_medium, const Bounds3f &bounds, float g, MajorantGrid majorants,
                        SpectrumPtr sigma_a, SpectrumPtr sigma_s, float scale);
    ~ScalarDensityMedium() = default;

    // The density at point u of the unit cube over the bounds.
    virtual float density_at(Vec3f u) const = 0;

  private:
    MediumProperties local(Vec3f u, const SampledWavelengths &lambda) const final;
    SampledSpectrum majorant_scale(const SampledWavelengths &lambda) const final;
    bool may_scatter(const SampledWavelengths &lambda, int carried) const final;

    SpectrumPtr sigma_a_, sigma_s_;
    float scale_;
};

} // namespace caustica
