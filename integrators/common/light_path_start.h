// How every light subpath begins (lt, bdpt, sppm, bpm, vcm): a light or an emissive medium chosen
// by power, a ray emitted from it (Light::sample_le), and the flux that the ray carries.
#pragma once

#include "lights/light.h"
#include "spectral/sampled_spectrum.h"

#include <cstdint>
#include <optional>

namespace caustica {

class Sampler;
class Scene;
class SampledWavelengths;

// A point where a light subpath starts, on a light or in an emissive medium, and the density of
// choosing it (the light's choice times the position's density, per area or per volume).
struct LightPoint {
    const Light *light = nullptr;
    Vec3f p;
    Vec3f n;                // zero in a medium
    Vec2f uv;               // on a surface light, on which its radiance may depend
    float error_scale = 0;  // p's, as SurfaceInteraction::error_scale
    float time = 0;
    float pdf = 0;
};

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
    LightPoint origin() const;
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

// The start on an area light or in an emissive medium, joined to a lens point sampled with
// u_lens (the s = 1, t = 1 strategy of lt, bdpt and vcm): the emission that the camera sees
// directly, which light tracing renders with low variance where a light covers part of a pixel
// (its edges, and lights seen at grazing angles) and a camera ray hits or misses it.
struct StartSeenByLens {
    Vec2f p_raster;    // where it lands on the film
    Vec3f p_lens;
    Vec3f wi;          // the unit direction from the light point to the lens
    float cos_light;   // |cos| between the light's normal and the direction to the lens; 1 in a medium
    // Le |cos_light| We T / (pdf pdf_lens), with pdf the start's (LightPoint::pdf), pdf_lens as
    // a solid angle at the light point and T the transmittance to the lens; unweighted.
    SampledSpectrum L;
};

// Empty when the lens cannot be sampled from the start or nothing arrives there, and for delta
// lights: a light that no ray can meet (a point, an invisible lamp) is not seen by the lens
// either. rays counts the transmittance rays.
std::optional<StartSeenByLens> join_start_to_lens(const Scene &scene, const LightPoint &start, Vec2f u_lens,
                                                  const SampledWavelengths &lambda, uint64_t &rays);

// Whether bdpt and vcm join light subpaths' starts to the lens, as a strategy beside the camera
// hitting the light. Not when the film clamps samples ("maxcomponentvalue"): the clamp acts on
// each camera sample's value and each splat apart, and this strategy renders a bright light
// seen directly with many faint splats, which the clamp leaves alone, where pt, sppm, bpm and
// pbrt-v4's bdpt (which has no such strategy: pbrt-v4 section 16.3.3) see it with camera rays
// whose values it cuts down. Without the strategy a light seen directly is the camera's hit
// alone, with weight 1, as there. lt has no other way to render it and always joins.
bool lens_joins_light_starts(const Scene &scene);

} // namespace caustica
