// How every light subpath begins (lt, bdpt, sppm, bpm, vcm): a light or an emissive medium chosen
// by power, a ray emitted from it (Light::sample_le), and the flux that the ray carries.
#pragma once

#include "lights/light.h"
#include "spectral/sampled_spectrum.h"

#include <optional>

namespace caustica {

class Sampler;
class Scene;
class SampledWavelengths;

struct LightPathStart {
    const Light *light = nullptr;
    float pmf = 0;        // the probability of choosing the light
    LightLeSample les;    // the emitted ray, its radiance and its position and direction densities
    // |cos| between the ray and the light's surface normal; 1 for lights without a surface
    // (point, spot, distant, infinite, emissive media).
    float cos_origin = 1;
    // Le |cos| / (pmf pdf_pos pdf_dir): the flux the ray carries, per light path.
    SampledSpectrum flux{0.f};

    bool at_infinity() const {
        return light->type() == LightType::Infinite || light->type() == LightType::DeltaDirection;
    }
};

// Draws the light or emissive medium (lights/medium_emitter.h), chosen by power (one sampler
// dimension), and its ray (two 2D dimensions, drawn even when nothing can be chosen, so that the
// dimensions after it do not depend on the outcome). Empty when
// nothing is emitted, which includes a point drawn in an emissive medium's box that lies outside
// the medium (beyond the interfaces that bound it). The ray leaves at `time` (geometry/ray.h):
// that of the camera path the light path will be joined with.
std::optional<LightPathStart> start_light_path(const Scene &scene, Sampler &sampler, const SampledWavelengths &lambda,
                                               float time);

// The probability that start_light_path chooses `light` (a light or an emissive medium). A light
// subpath's throughput has it; MIS weights also take next-event estimation's choice of a light
// for the strategies that sample it (bdpt and vcm).
float light_path_start_pmf(const Scene &scene, const Light &light);

} // namespace caustica
