// Fluorescent re-radiation in the hero-wavelength scheme (materials/fluorophore.h).
//
// A path that re-radiates changes wavelength. Rather than ending the secondary wavelengths, as a
// dispersive refraction must, the walk draws ONE new wavelength for all carried lanes at once,
// and lane j's throughput takes the factor that links lane j's wavelength to it:
//  - a camera subpath arrives carrying the film's wavelengths lambda_j and draws the absorbed
//    wavelength lambda from the dye's absorption: lane j is multiplied by
//    pi f(lambda -> lambda_j) / p(lambda), and everything after the vertex is evaluated at lambda
//    on every lane, while the film still credits lane j to lambda_j;
//  - a light subpath arrives carrying lambda_j and draws the emitted lambda from the dye's
//    emission: lane j takes pi f(lambda_j -> lambda) / p(lambda), and its splats now land at
//    lambda, each lane still weighed by the density its own wavelength was drawn with.
// Every lane thus keeps an unbiased estimate, the new wavelength's density is exact, and no lane
// is wasted (sample_reradiation_shift, fluorophore.h). The choice to re-radiate rather than
// reflect depends on the carried set alone (fluorescent_bxdf.h), as the hero-wavelength
// estimator requires.
#pragma once

#include "materials/bsdf.h"
#include "materials/fluorescent_bxdf.h"
#include "spectral/sampled_wavelengths.h"

#include <cstdint>
#include <optional>

namespace caustica {

class Medium;
class Sampler;
class Scene;
struct LightSampleContext;
struct SurfaceInteraction;

// A re-radiation drawn at a vertex reached carrying `lambda` in `mode`: the lobe for its shift,
// and the wavelengths the path carries after it (every lane at the new one, each keeping its
// density). Empty when nothing re-radiates to or from the carried wavelengths.
struct ReradiationSample {
    ReradiationBxDF lobe;
    SampledWavelengths lambda;
};
std::optional<ReradiationSample> sample_reradiation(const Reradiation &reradiation, TransportMode mode,
                                                    const SampledWavelengths &lambda, float u);

// Next-event estimation of the re-radiated light at a fluorescent surface point of a camera
// path: a shift is drawn, and a light sample taken at its wavelength through the re-radiation
// lobe (weighted against the walk's own re-radiation samples that reach the light, which draw
// with the same lobe density). Draws one sampler dimension before sample_direct_lighting's.
SampledSpectrum sample_reradiated_lighting(const Scene &scene, const SurfaceInteraction &si, const BSDF &bsdf,
                                           const LightSampleContext &ctx, const SampledWavelengths &lambda,
                                           Sampler &sampler, uint64_t &rays, const Medium *medium);

} // namespace caustica
