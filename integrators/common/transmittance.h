// Visibility through participating media: the fraction of light that travels along a segment,
// passing through medium boundaries (shapes without a material) and attenuated by Beer-Lambert
// in each medium it crosses. Connections, shadow rays and camera connections all use it.
#pragma once

#include "geometry/ray.h"
#include "spectral/sampled_spectrum.h"
#include "spectral/sampled_wavelengths.h"

#include <cstdint>

namespace caustica {

class Medium;
class Scene;

// Transmittance from ray.o to ray.at(ray.t_max) (to infinity when t_max is infinite), starting
// in `medium`: zero if a surface with a material is in the way. In a scene without media or
// medium boundaries this is one occlusion query. Every query is counted in rays.
SampledSpectrum transmittance(const Scene &scene, Ray ray, const Medium *medium,
                              const SampledWavelengths &lambda, uint64_t &rays);

} // namespace caustica
