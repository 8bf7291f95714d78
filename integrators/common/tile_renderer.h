// Renders camera samples over the image in parallel tiles (oneTBB). Every sample's random numbers
// depend only on (pixel, sample index, seed), and every pixel belongs to exactly one tile, so the
// image is bit-identical whatever the number of threads.
#pragma once

#include "core/scratch_buffer.h"
#include "integrators/integrator.h"
#include "sampler/sampler.h"
#include "spectral/sampled_wavelengths.h"

#include <functional>

namespace caustica {

struct CameraRay;

// Radiance along a camera ray for the path's wavelengths (which the estimator may terminate).
using RadianceFunction = std::function<SampledSpectrum(const CameraRay &ray, SampledWavelengths &lambda,
                                                       Sampler &sampler, ScratchBuffer &scratch,
                                                       uint64_t &rays)>;

// Samples the path's wavelengths as the scene's overrides ask (hero, single, or fixed).
SampledWavelengths sample_wavelengths(const Scene &scene, float u);

void render_tiles(const Scene &scene, const RenderBudget &budget, RenderStats &stats,
                  const ProgressCallback &progress, const RadianceFunction &radiance);

} // namespace caustica
