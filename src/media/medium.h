// Participating media: what a ray travelling through a medium meets before it reaches the next
// surface. Homogeneous media (pbrt-v4's "homogeneous") have closed-form transmittance and
// free-flight distances; heterogeneous ones ("uniformgrid", "rgbgrid", "cloud", "nanovdb";
// heterogeneous_medium.h) sample them by delta tracking and estimate transmittance by ratio
// tracking against a majorant. The interface is what the integrators need from any medium.
//
// Chromatic media: a path carries NumWavelengths wavelengths, and the medium has a different
// extinction for each. A medium samples a distance with the coefficients of one of them (the
// subpath's "lane") and reports the event's density under every wavelength's coefficients; the
// path combines the densities of all its events by multiple importance sampling over the
// wavelengths (integrators/common/spectral_mis.h, SpectralMIS). A medium that does not scatter
// at the carried wavelengths samples nothing: the event is the transmittance itself, with density
// 1 for every wavelength.
#pragma once

#include "geometry/ray.h"
#include "media/phase_function.h"
#include "spectral/sampled_spectrum.h"
#include "spectral/sampled_wavelengths.h"

#include <memory>
#include <optional>

namespace caustica {

class Material;

// The outcome of sampling a free-flight distance along a ray segment of length t_max.
struct MediumEvent {
    // True: the path scatters at distance t inside the medium. False: it reaches t_max (the next
    // surface, or infinity) and t == t_max.
    bool scattered = false;
    float t = 0;
    // Per wavelength: the event's contribution f, T(t) sigma_s(t) when scattered and T(t_max)
    // when passing (zero at terminated wavelengths), and its density had that wavelength's
    // coefficients sampled it, sigma_t(t) T(t) and T(t_max) (all 1 when nothing was sampled).
    // With delta tracking the event is the whole chain of null collisions before it, and f and
    // density are products over that chain (Miller et al. 2019). Only ratios are used: f and
    // density may share one positive factor.
    SampledSpectrum f{0.f}, density{1.f};
    // Emissive media: the emission collected at the collision, T(t) sigma_a(t) Le(t), on the
    // scale of f (zero when the path passes). Over the density above, it is the collision
    // estimator of the emission along the segment, the integral of T sigma_a Le (pbrt-v4's
    // convention: emitted radiance per unit length is sigma_a Le). An emissive medium samples
    // collisions even where it does not scatter, and a collision that only absorbs ends the
    // path (f zero) after its emission is counted.
    SampledSpectrum emitted{0.f};
};

// A point where a light path starts in an emissive medium, with its density per unit of
// render-space volume.
struct EmissionPoint {
    Vec3f p;
    float pdf = 0;
};

// The coefficients at one point of a medium.
struct MediumProperties {
    SampledSpectrum sigma_a{0.f}, sigma_s{0.f};
};

class Medium {
  public:
    // The coefficients at render-space point p (zero outside a grid's bounds).
    virtual MediumProperties properties(Vec3f p, const SampledWavelengths &lambda) const = 0;
    // An upper bound of sigma_t anywhere in the medium, at the given wavelengths.
    virtual SampledSpectrum max_sigma_t(const SampledWavelengths &lambda) const = 0;
    virtual const HenyeyGreenstein &phase() const = 0;
    // Emission: whether the medium emits anywhere, and the radiance Le it emits at render-space
    // point p (isotropically; the light leaving per unit length is sigma_a Le).
    virtual bool is_emissive() const { return false; }
    virtual SampledSpectrum Le(Vec3f p, const SampledWavelengths &lambda) const {
        (void)p;
        (void)lambda;
        return SampledSpectrum(0.f);
    }
    // Emissive media with bounds (the heterogeneous ones): where light paths start. A point is
    // drawn with u_cell and u_within (uniform numbers), emission_point_pdf is its density, and
    // emitted_power the integral of sigma_a Le over the medium. Media without bounds
    // (homogeneous) have none of these: lights/medium_emitter.h samples the scene's box instead.
    virtual bool has_emission_sampling() const { return false; }
    virtual std::optional<EmissionPoint> sample_emission_point(float u_cell, Vec3f u_within) const {
        (void)u_cell;
        (void)u_within;
        return std::nullopt;
    }
    virtual float emission_point_pdf(Vec3f p) const {
        (void)p;
        return 0;
    }
    virtual SampledSpectrum emitted_power(const SampledWavelengths &lambda) const {
        (void)lambda;
        return SampledSpectrum(0.f);
    }
    // Transmittance exp(-integral of sigma_t) from ray.o along the unit direction ray.d over the
    // given distance (may be Infinity); heterogeneous media return an unbiased estimate.
    virtual SampledSpectrum transmittance(const Ray &ray, float distance, const SampledWavelengths &lambda) const = 0;
    // Samples where a ray leaving ray.o along the unit direction ray.d first scatters, within
    // distance t_max (may be Infinity), with the extinction of wavelength lambda[lane];
    // u_distance drives the sampling.
    virtual MediumEvent sample_distance(const Ray &ray, float t_max, const SampledWavelengths &lambda, int lane,
                                        float u_distance) const = 0;
    // The material whose interior this medium is when the material made it for one entry point
    // (SampledHomogeneousMedium), else null.
    virtual const Material *interior_of() const { return nullptr; }
    // Scene analysis: true when its coefficients do not depend on wavelength (see
    // SceneFeatures::achromatic); false unless a medium shows it.
    virtual bool is_wavelength_independent() const { return false; }

  protected:
    // Media are owned through MediumPtr (made by make_shared, which destroys the concrete type)
    // or made in a path's scratch memory, which destroys nothing: no virtual destructor, so that
    // the latter is allowed.
    ~Medium() = default;
};

using MediumPtr = std::shared_ptr<const Medium>;

} // namespace caustica
