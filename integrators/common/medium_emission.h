// Emissive media as the starts of light subpaths in the integrators that weigh them by MIS
// against their camera subpaths' collision estimate of the same emission (bdpt, vcm, bpm).
//
// A light subpath draws its start per unit volume (lights/medium_emitter.h); a camera subpath
// reaches the same point by a free flight, so the camera side's density there includes the free
// flight's, per unit length. That density is exact in closed form only in a homogeneous medium;
// every strategy takes that of a homogeneous medium with the point's mean extinction sigma over
// the carried wavelengths, sigma e^(-sigma d) at distance d from the previous vertex. Being one
// function of the path, it keeps the weights a partition of unity; where the medium varies it
// only makes them less than balanced.
#pragma once

#include "core/vecmath.h"

#include <cmath>

namespace caustica {

class Light;
class Medium;
class Scene;
class SampledWavelengths;

// The free-flight density, per unit length, that MIS takes for reaching a point of mean
// extinction sigma at distance d.
inline float collision_density(float sigma, float d) { return sigma * std::exp(-sigma * d); }

// The mean extinction over the wavelengths at point p of the medium.
float mean_extinction(const Medium &medium, Vec3f p, const SampledWavelengths &lambda);

// The emitter that stands for the medium's light (null for a medium that emits none).
const Light *medium_emitter_of(const Scene &scene, const Medium *medium);

// The density with which a light subpath starts at p in the emitter's medium, per unit volume:
// the emitter's choice among the lights and media, times its position density.
float medium_start_density(const Scene &scene, const Light &emitter, Vec3f p);

} // namespace caustica
