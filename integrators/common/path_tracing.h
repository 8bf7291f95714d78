// The path tracer's estimator on a camera walk: next-event estimation at every non-specular
// vertex (surface or medium), weighted against the walk's own hits on emitters by the power
// heuristic (Veach 1997, ch. 9), Russian roulette, and the emission of emissive media that the
// walk collects. pt is this estimator from the lens on. The bidirectional and photon integrators
// run it for the rest of a camera subpath that a fluorescent surface re-radiated
// (reradiation.h): no light subpath reaches light of the new wavelength, so next-event
// estimation and emitter hits are the only strategies left for it, and their weights, the path
// tracer's, sum to one on their own.
//
// Emitters and lights are evaluated at the wavelengths the walk carries (walk.lambda(): the
// film's until a re-radiation moves them), while the result stays on the film's wavelengths.
#pragma once

#include "lights/light.h"
#include "spectral/sampled_spectrum.h"

#include <cstdint>

namespace caustica {

class Sampler;
class Scene;
class SubpathWalk;

// Where the walk's last direction was sampled, for weighting the emitter it reaches.
struct EmissionMIS {
    bool specular_bounce = false;
    float bsdf_pdf = 0;          // density of the direction that left prev_ctx
    LightSampleContext prev_ctx; // where that direction was sampled
};

// Radiance gathered by continuing `walk`, which is about to advance along a ray that left its
// depth-th scattering vertex (0: the camera ray) as `mis` says, up to max_depth scattering
// vertices. The throughput walk.beta is included. With reradiated_only, only light re-radiated
// on the way counts: what comes after a re-radiation, and next-event estimation of re-radiated
// light at fluorescent vertices before one.
SampledSpectrum trace_radiance(const Scene &scene, SubpathWalk &walk, EmissionMIS mis, int depth, int max_depth,
                               Sampler &sampler, uint64_t &rays, bool reradiated_only = false);

// For the integrators that join camera and light subpaths, whose light subpaths do not
// re-radiate (their wavelengths must match the camera's at the joint):
//  - reradiated_light_at: next-event estimation of the light re-radiated at the walk's surface
//    vertex (sample_reradiated_lighting), before the walk scatters there;
//  - reradiated_beyond: the re-radiated light on the rest of the walk, after it scattered at
//    its depth-th vertex `at` with density `scattered`: the whole rest when that scatter
//    re-radiated (walk.reradiated()), which bdpt and vcm call to end their camera subpath, and
//    otherwise the re-radiations further on, which sppm calls at its visible points, where its
//    camera paths stop.
// Russian roulette is applied at `at` first, as the path tracer applies it after each scatter.
SampledSpectrum reradiated_light_at(const Scene &scene, const SubpathWalk &walk, Sampler &sampler, uint64_t &rays);
SampledSpectrum reradiated_beyond(const Scene &scene, SubpathWalk &walk, const LightSampleContext &at, float scattered,
                                  int depth, int max_depth, Sampler &sampler, uint64_t &rays);

} // namespace caustica
